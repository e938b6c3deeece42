// Parsers for the higher-degree shapes: torus, superellipsoid, algebraic, implicit, revolution.
#include <cmath>
#include <stdexcept>

#include "load/shape_parsers.h"
#include "math/expression.h"

namespace raycast {

namespace {

// The YAML position of character `offset` of a single-line scalar: plain scalars start at their
// mark, quoted ones one character later.
// Escape sequences before the offset in a double-quoted scalar are not accounted for.
YamlMark mark_in_scalar(const YamlNode& node, std::size_t offset) {
  YamlMark m = node.Mark();
  if (m.column < 0) return m;
  m.column += static_cast<int>(offset) + (node.IsQuoted() ? 1 : 0);
  return m;
}

// The formula text of `key`, and a call of `make` that turns ExpressionErrors into SceneErrors
// at the exact column.
template <class Make>
auto with_formula(Fields& f, const std::string& key, Make&& make) {
  const std::string text = f.string(key);
  const YamlNode node = f.optional(key);
  try {
    return make(text);
  } catch (const ExpressionError& e) {
    fail_at(f.ctx(), mark_in_scalar(node, e.offset()), f.name(key) + ": " + e.what());
  }
}

Aabb read_required_bounds(Fields& f) {
  Fields b(f.ctx(), f.required("bounds"), f.name("bounds"));
  Aabb box{b.vec3("min"), b.vec3("max")};
  b.finish();
  if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
    f.fail("bounds", f.name("bounds") + ".min must be < max on every axis");
  return box;
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<Torus>, Fields& f) {
  const double R = f.positive("major_radius");
  const double r = f.positive("minor_radius");
  return make_torus(R, r);
}

ShapeVariant parse_shape(std::type_identity<Superellipsoid>, Fields& f) {
  const double e = f.positive("e", 1);
  const double n = f.positive("n", 1);
  return make_superellipsoid(e, n);
}

ShapeVariant parse_shape(std::type_identity<Algebraic>, Fields& f) {
  const Aabb box = read_required_bounds(f);
  const bool open = f.boolean("open", false);
  return with_formula(f, "equation", [&](const std::string& text) -> ShapeVariant {
    return make_algebraic(text, box, open);
  });
}

ShapeVariant parse_shape(std::type_identity<Implicit>, Fields& f) {
  const Aabb box = read_required_bounds(f);
  const bool open = f.boolean("open", false);
  return with_formula(f, "function", [&](const std::string& text) -> ShapeVariant {
    return make_implicit(text, box, open);
  });
}

ShapeVariant parse_shape(std::type_identity<Revolution>, Fields& f) {
  const YamlNode list = f.required("profile");
  if (!list.IsSequence())
    fail_at(f.ctx(), list,
            f.name("profile") + " must be a list of [r, z] points, got " + describe(list));
  std::vector<std::array<double, 2>> profile;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string what = f.name("profile") + "[" + std::to_string(i) + "]";
    const auto v = read_numbers(f.ctx(), list[i], what);
    if (v.size() != 2)
      fail_at(f.ctx(), list[i], what + " must be [r, z], got " + describe(list[i]));
    if (v[0] < 0) fail_at(f.ctx(), list[i], what + ": r must be >= 0, got " + std::to_string(v[0]));
    profile.push_back({v[0], v[1]});
  }
  const std::string curve = f.string("curve", "linear");
  if (curve != "linear" && curve != "bspline")
    f.fail("curve", f.name("curve") + " must be linear or bspline, got " + curve);
  const bool capped = f.boolean("capped", true);
  const ProfileCurve kind = curve == "linear" ? ProfileCurve::kLinear : ProfileCurve::kBSpline;
  const std::size_t need = kind == ProfileCurve::kLinear ? 2 : 4;
  if (profile.size() < need)
    fail_at(f.ctx(), list,
            f.name("profile") + " needs at least " + std::to_string(need) + " points for a " +
                curve + " curve, got " + std::to_string(profile.size()));
  return make_revolution(profile, kind, capped);
}

}  // namespace raycast
