// Parsers for the quadric family and the planar solids: ellipsoid, quadric, cylinder, cone,
// polygon, slab, polyhedron.
#include <array>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "load/shape_parsers.h"

namespace raycast {

namespace {

// Runs make(), turning its std::invalid_argument into a SceneError at field `key`, or at the
// element key[i] when the message starts with "key[i]".
template <class Make>
auto positioned(Fields& f, const std::string& key, Make make) -> decltype(make()) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    const YamlNode node = f.node()[key];
    if (node.IsDefined() && node.IsSequence() && msg.rfind(key + "[", 0) == 0) {
      const std::size_t i = std::strtoul(msg.c_str() + key.size() + 1, nullptr, 10);
      if (i < node.size()) fail_at(f.ctx(), node[i], f.name(msg));
    }
    f.fail(key, f.name(key) + ": " + msg);
  }
}

// A list of exactly n numbers.
std::vector<double> numbers_n(Fields& f, const YamlNode& node, const std::string& what,
                              std::size_t n) {
  if (!node.IsSequence() || node.size() != n)
    fail_at(f.ctx(), node,
            what + " must be a list of " + std::to_string(n) + " numbers, got " + describe(node));
  return read_numbers(f.ctx(), node, what);
}

// `bounds: {min, max}` with min < max on every axis.
std::optional<Aabb> read_optional_bounds(Fields& f) {
  const YamlNode node = f.optional("bounds");
  if (!node.IsDefined()) return std::nullopt;
  Fields b(f.ctx(), node, f.name("bounds"));
  const Aabb box{b.vec3("min"), b.vec3("max")};
  b.finish();
  for (int a = 0; a < 3; ++a)
    if (!(box.lo[a] < box.hi[a]))
      fail_at(f.ctx(), node["max"], f.name("bounds") + ".max must be > min on every axis");
  return box;
}

QuadricCoefficients read_quadric_coefficients(Fields& f, std::string& key) {
  const int forms = f.has("coefficients") + f.has("matrix") + f.has("kind");
  if (forms != 1)
    f.fail("coefficients", f.name("") + " needs exactly one of coefficients, matrix or kind");
  if (f.has("coefficients")) {
    key = "coefficients";
    const auto v = numbers_n(f, f.required(key), f.name(key), 10);
    QuadricCoefficients c;
    for (int i = 0; i < 10; ++i) c[i] = v[i];
    return c;
  }
  if (f.has("matrix")) {
    key = "matrix";
    const YamlNode node = f.required(key);
    if (!node.IsSequence() || node.size() != 4)
      fail_at(f.ctx(), node, f.name(key) + " must be 4 rows of 4 numbers, got " + describe(node));
    Mat4 m;
    for (int r = 0; r < 4; ++r) {
      const auto row = numbers_n(f, node[r], f.name(key) + "[" + std::to_string(r) + "]", 4);
      for (int c = 0; c < 4; ++c) m.m[r][c] = row[c];
    }
    return positioned(f, key, [&] { return quadric_from_matrix(m); });
  }
  key = "kind";
  const std::string kind = f.string(key);
  static const std::pair<const char*, QuadricKind> kKinds[] = {
      {"ellipsoid", QuadricKind::kEllipsoid},
      {"paraboloid", QuadricKind::kParaboloid},
      {"hyperboloid1", QuadricKind::kHyperboloid1},
      {"hyperboloid2", QuadricKind::kHyperboloid2},
      {"cone", QuadricKind::kCone},
      {"cylinder", QuadricKind::kCylinder}};
  for (const auto& [name, k] : kKinds) {
    if (kind != name) continue;
    const double a = f.positive("a", 1);
    const double b = f.positive("b", a);
    const double c = f.positive("c", 1);
    return quadric_of_kind(k, a, b, c);
  }
  f.fail(key, f.name(key) +
                  " must be one of ellipsoid, paraboloid, hyperboloid1, hyperboloid2, cone, "
                  "cylinder; got '" +
                  kind + "'");
}

double phi_max_degrees(Fields& f) {
  const double phi = f.number("phi_max", 360);
  if (!(phi > 0 && phi <= 360)) f.fail("phi_max", f.name("phi_max") + " must be in (0, 360]");
  return phi;
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<Ellipsoid>, Fields& f) {
  const Vec3 c = f.vec3("center", {0, 0, 0});
  const Vec3 r = f.vec3("radii");
  if (!(r.x > 0 && r.y > 0 && r.z > 0)) f.fail("radii", f.name("radii") + " must all be > 0");
  return positioned(f, "radii", [&] { return make_ellipsoid(c, r); });
}

ShapeVariant parse_shape(std::type_identity<Quadric>, Fields& f) {
  std::string key;
  const QuadricCoefficients c = read_quadric_coefficients(f, key);
  const std::optional<Aabb> box = read_optional_bounds(f);
  const bool open = f.boolean("open", false);
  return positioned(f, key, [&] { return make_quadric(c, box, open); });
}

ShapeVariant parse_shape(std::type_identity<Cylinder>, Fields& f) {
  const bool capped = f.boolean("capped", true);
  const double r = f.positive("radius");
  if (f.has("from") || f.has("to")) {
    const Vec3 from = f.vec3("from"), to = f.vec3("to");
    return positioned(f, "to", [&] { return make_cylinder(from, to, r, capped); });
  }
  const double z_min = f.number("z_min", -1), z_max = f.number("z_max", 1);
  if (!(z_min < z_max)) f.fail("z_max", f.name("z_max") + " must be > z_min");
  const double phi = phi_max_degrees(f);
  return positioned(f, "radius", [&] { return make_cylinder(r, z_min, z_max, phi, capped); });
}

ShapeVariant parse_shape(std::type_identity<Cone>, Fields& f) {
  const bool capped = f.boolean("capped", true);
  if (f.has("from") || f.has("to")) {
    const Vec3 from = f.vec3("from"), to = f.vec3("to");
    const double r0 = f.non_negative("radius_from", -1), r1 = f.non_negative("radius_to", 0);
    if (r0 < 0) f.required("radius_from");
    if (r0 == 0 && r1 == 0)
      f.fail("radius_from", f.name("radius_from") + " and radius_to must not both be 0");
    return positioned(f, "to", [&] { return make_cone(from, to, r0, r1, capped); });
  }
  const double r = f.positive("radius");
  const double h = f.positive("height", 1);
  const double phi = phi_max_degrees(f);
  return positioned(f, "radius", [&] { return make_cone(r, h, phi, capped); });
}

ShapeVariant parse_shape(std::type_identity<Polygon>, Fields& f) {
  const std::vector<Vec3> v = read_points(f.ctx(), f.required("vertices"), f.name("vertices"));
  return positioned(f, "vertices", [&] { return make_polygon(v); });
}

ShapeVariant parse_shape(std::type_identity<Slab>, Fields& f) {
  const Vec3 n = f.direction("normal");
  const auto d = numbers_n(f, f.required("offsets"), f.name("offsets"), 2);
  if (!(d[0] < d[1])) f.fail("offsets", f.name("offsets") + " must be [d0, d1] with d0 < d1");
  return positioned(f, "offsets", [&] { return make_slab(n, d[0], d[1]); });
}

ShapeVariant parse_shape(std::type_identity<Polyhedron>, Fields& f) {
  const YamlNode node = f.required("planes");
  if (!node.IsSequence())
    fail_at(f.ctx(), node, f.name("planes") + " must be a list of [nx, ny, nz, d]");
  std::vector<std::array<double, 4>> planes;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const auto v = numbers_n(f, node[i], f.name("planes") + "[" + std::to_string(i) + "]", 4);
    planes.push_back({v[0], v[1], v[2], v[3]});
  }
  return positioned(f, "planes", [&] { return make_polyhedron(planes); });
}

}  // namespace raycast
