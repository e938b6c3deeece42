// Parsers for the swept shapes: prism, and text (whose letters are prisms).
#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/prism_spline.h"
#include "load/shape_parsers.h"
#include "load/text_shape.h"

namespace raycast {

namespace {

PrismSpline read_spline(Fields& f) {
  const std::string s = f.string("spline", "linear");
  if (s == "linear") return PrismSpline::kLinear;
  if (s == "quadratic") return PrismSpline::kQuadratic;
  if (s == "cubic") return PrismSpline::kCubic;
  if (s == "bezier") return PrismSpline::kBezier;
  f.fail("spline", f.name("spline") + " must be linear, quadratic, cubic or bezier, got " + s);
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<Prism>, Fields& f) {
  const YamlNode list = f.required("points");
  if (!list.IsSequence())
    fail_at(f.ctx(), list,
            f.name("points") + " must be a list of [x, y] points, got " + describe(list));
  std::vector<std::array<double, 2>> points;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string what = f.name("points") + "[" + std::to_string(i) + "]";
    const auto v = read_numbers(f.ctx(), list[i], what);
    if (v.size() != 2)
      fail_at(f.ctx(), list[i], what + " must be [x, y], got " + describe(list[i]));
    points.push_back({v[0], v[1]});
  }
  const PrismSpline spline = read_spline(f);
  const YamlNode heights = f.optional("heights");
  double z0 = 0, z1 = 1;
  if (heights) {
    const auto h = read_numbers(f.ctx(), heights, f.name("heights"));
    if (h.size() != 2 || h[0] == h[1])
      fail_at(f.ctx(), heights, f.name("heights") + " must be two different numbers [z0, z1]");
    z0 = h[0], z1 = h[1];
  }
  const std::string sweep = f.string("sweep", "linear");
  if (sweep != "linear" && sweep != "conic")
    f.fail("sweep", f.name("sweep") + " must be linear or conic, got " + sweep);
  const bool open = f.boolean("open", false);
  try {
    return make_prism(spline_contours(points, spline), z0, z1, sweep == "conic", open);
  } catch (const std::invalid_argument& e) {
    fail_at(f.ctx(), list, f.name("points") + ": " + e.what());
  }
}

}  // namespace raycast

namespace raycast {

ShapeVariant parse_shape(std::type_identity<Text>, Fields& f) {
  const std::string font = f.string("font");
  const std::string text = f.string("string");
  const double thickness = f.positive("thickness", 1);
  Vec3 offset;
  if (const YamlNode o = f.optional("offset")) {
    const auto v = read_numbers(f.ctx(), o, f.name("offset"));
    if (v.size() != 2 && v.size() != 3)
      fail_at(f.ctx(), o, f.name("offset") + " must be [x, y] or [x, y, z], got " + describe(o));
    offset = {v[0], v[1], v.size() == 3 ? v[2] : 0};
  }
  const std::filesystem::path p(font);
  const std::string path =
      p.is_absolute() ? font : (std::filesystem::path(f.ctx().dir) / p).string();
  if (f.ctx().files) f.ctx().files->push_back(path);  // a data file of the scene
  try {
    return make_text_shape(path, text, thickness, offset);
  } catch (const std::runtime_error& e) {
    f.fail("font", f.name("font") + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    f.fail("string", f.name("string") + ": " + e.what());
  }
}

}  // namespace raycast
