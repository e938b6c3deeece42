// height_field { IMAGE_TYPE "file" | "file" | function W, H { ... } [smooth] [water_level L]
// [hierarchy [on|off]] }: the heights read into the node.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "io/image.h"
#include "pov/interpreter.h"
#include "texture/pigment.h"

namespace raycast::pov {

namespace {

// The keywords of POV-Ray's image types.
bool is_image_type(const std::string& w) {
  static constexpr const char* kTypes[] = {"png",  "pgm", "ppm", "tga", "gif", "iff", "jpeg",
                                           "tiff", "bmp", "exr", "hdr", "sys", "pot"};
  for (const char* t : kTypes)
    if (w == t) return true;
  return false;
}

}  // namespace

// function W, H { F }: F at (j / (W - 1), i / (H - 1), 0) for the pixel in column j and row i (top
// row first), kept as POV-Ray keeps it: clamped to [0, 1] in 16 bits. A pigment's colour counts
// by its grey, 0.297 r + 0.589 g + 0.114 b (POV-Ray's rule for a colour image of 16 bits).
void Interpreter::height_field_function(Node& n, const Pos& at) {
  const Pos wpos = tok().pos;
  const double w = std::floor(number("the height field's width") + 0.5);
  skip_comma();
  const double h = std::floor(number("the height field's depth") + 0.5);
  if (!(w >= 2 && h >= 2 && w <= kMaxHeightImageSide && h <= kMaxHeightImageSide &&
        w * h <= double(kMaxHeightImagePixels)))
    fail_at(wpos, "a function height field's size must be 2 to " +
                      std::to_string(kMaxHeightImageSide) + " each way and at most " +
                      std::to_string(kMaxHeightImagePixels) + " points");
  expect_symbol("{", "after the height field's size");
  std::function<double(double, double)> value;
  Pigment pigment;
  if (is_word("pigment")) {
    next();
    pigment = pigment_block(Pigment{});
    value = [&pigment](double x, double y) {
      const Vec3 c = pigment.model ? texture::evaluate(*pigment.model, Vec3{x, y, 0}).rgb
                                   : Vec3{pigment.c0.r, pigment.c0.g, pigment.c0.b};
      const auto clamp = [](double v) { return v > 0 ? std::min(v, 1.0) : 0.0; };
      return 0.297 * clamp(c.x) + 0.589 * clamp(c.y) + 0.114 * clamp(c.z);
    };
  } else if (is_word("pattern") || is_word("transform") || is_word("spline") ||
             is_word("internal")) {
    unsupported_warning(at, "height fields of a " + tok().text + " function");
    skip_block_rest("function");
    return;
  } else {
    auto f = std::make_shared<FunctionValue>();
    f->params = {"x", "y", "z"};
    f->body = function_expression(0, f->params);
    value = [f](double x, double y) { return evaluate(*f, {x, y, 0}); };
  }
  expect_symbol("}", "to close the height field's function");
  auto img = std::make_shared<HeightImage>();
  img->width = static_cast<int>(w);
  img->height = static_cast<int>(h);
  img->values.resize(std::size_t(img->width) * std::size_t(img->height));
  for (int i = 0; i < img->height; ++i)
    for (int j = 0; j < img->width; ++j) {
      const double v = value(j / (w - 1), i / (h - 1));
      const double c = v > 0 ? std::min(v, 1.0) : 0.0;  // NaN too: 0
      img->values[std::size_t(i) * std::size_t(img->width) + std::size_t(j)] =
          static_cast<std::uint16_t>(std::lround(c * 65535));
    }
  n.heights = std::move(img);
}

void Interpreter::height_field_body(Node& n, int) {
  const Pos at = tok().pos;
  n.values = {0};  // the water level
  if (is_word("function")) {
    next();
    height_field_function(n, at);
  } else {
    std::string type;
    if (tok().kind == Token::Word && is_image_type(tok().text)) {
      type = tok().text;
      next();
    }
    const Pos fpos = tok().pos;
    const std::string name = string_value("the height field's image file");
    std::optional<HeightImageFormat> format;
    try {
      format = height_image_format(type, name);
    } catch (const ImageError& e) {  // a type raycast does not read: the field is left out
      unsupported_warning(fpos, "height fields from this image type", e.what());
    }
    if (format) {
      const std::optional<std::string> found = find_on_library_path(name);
      if (!found) fail_at(fpos, "height field image '" + name + "' not found on the library path");
      try {
        n.heights = std::make_shared<HeightImage>(read_height_image(*found, *format));
      } catch (const ImageError& e) {
        fail_at(fpos, e.what());
      }
      n.image = *found;
      n.image_type = type;
    }
  }
  for (;;) {
    if (is_word("smooth")) {
      next();
      n.smooth = true;
    } else if (is_word("water_level")) {
      next();
      n.values[0] = number("water_level");
    } else if (is_word("hierarchy")) {
      next();  // POV-Ray's bounding blocks: the mesh has its own BVH
      boolean_option();
    } else {
      break;
    }
  }
}

}  // namespace raycast::pov
