// Parsers for the basic shapes: plane, sphere, box, triangle, parallelogram, disk.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "load/shape_parsers.h"

namespace raycast {

namespace {

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The sine of the angle between a and b is at most kDegenerateSine (triangle.h).
bool nearly_parallel(const Vec3& a, const Vec3& b) {
  return !(length(cross(a, b)) > kDegenerateSine * length(a) * length(b));
}

// A list of exactly `count` points, each [x, y, z] of finite numbers.
std::vector<Vec3> points(Fields& f, const std::string& key, std::size_t count) {
  const YAML::Node n = f.required(key);
  if (!n.IsSequence() || n.size() != count)
    fail_at(f.ctx(), n,
            f.name(key) + " must be a list of " + std::to_string(count) +
                " [x, y, z] points, got " + describe(n));
  return read_points(f.ctx(), n, f.name(key));
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<Plane>, Fields& f) {
  const Vec3 n = f.direction("normal");
  const Vec3 p = f.vec3("point", {0, 0, 0});
  return make_plane(n, p);
}

ShapeVariant parse_shape(std::type_identity<Sphere>, Fields& f) {
  const Vec3 c = f.vec3("center", {0, 0, 0});
  const double r = f.positive("radius");
  const double z_min = f.number("z_min", -r);
  const double z_max = f.number("z_max", r);
  if (!(z_min < z_max)) f.fail("z_max", f.name("z_max") + " must be > z_min");
  if (z_max <= -r || z_min >= r)
    f.fail("z_min", f.name("z_min") + ", z_max must overlap [-radius, radius]");
  const double phi = f.number("phi_max", 360);
  if (!(phi > 0 && phi <= 360)) f.fail("phi_max", f.name("phi_max") + " must be in (0, 360]");
  return make_sphere(c, r, z_min, z_max, phi);
}

ShapeVariant parse_shape(std::type_identity<Box>, Fields& f) {
  const Vec3 lo = f.vec3("min");
  const Vec3 hi = f.vec3("max");
  for (int a = 0; a < 3; ++a)
    if (!(lo[a] < hi[a]))
      f.fail("max", f.name("max") + " must be > box.min on every axis, got " +
                        format_number(hi[a]) + " <= " + format_number(lo[a]) + " on " + "xyz"[a]);
  return make_box(lo, hi);
}

ShapeVariant parse_shape(std::type_identity<Triangle>, Fields& f) {
  const std::vector<Vec3> p = points(f, "vertices", 3);
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  if (!std::isfinite(length_squared(e1)) || !std::isfinite(length_squared(e2)))
    f.fail("vertices", f.name("vertices") + " are too large");
  if (nearly_parallel(e1, e2))
    f.fail("vertices", f.name("vertices") + " are collinear or coincide (a degenerate triangle)");
  if (!f.has("normals")) return make_triangle(p[0], p[1], p[2]);
  const std::vector<Vec3> n = points(f, "normals", 3);
  const YAML::Node nn = f.optional("normals");
  for (std::size_t i = 0; i < 3; ++i)
    if (length_squared(n[i]) == 0 || !std::isfinite(length_squared(n[i])))
      fail_at(f.ctx(), nn[i],
              f.name("normals") + "[" + std::to_string(i) + "] must be a non-zero vector");
  return make_triangle(p[0], p[1], p[2], n[0], n[1], n[2]);
}

ShapeVariant parse_shape(std::type_identity<Parallelogram>, Fields& f) {
  const Vec3 origin = f.vec3("origin");
  const Vec3 u = f.direction("u");
  const Vec3 v = f.direction("v");
  if (nearly_parallel(u, v))
    f.fail("v", f.name("u") + " and " + f.name("v") + " must not be parallel");
  return make_parallelogram(origin, u, v);
}

ShapeVariant parse_shape(std::type_identity<Disk>, Fields& f) {
  const bool centred = f.has("center") || f.has("normal");
  const double radius = f.positive("radius");
  const double inner = f.non_negative("inner_radius", 0);
  if (!(inner < radius))
    f.fail("inner_radius",
           f.name("inner_radius") + " must be < radius, got " + format_number(inner));
  if (centred) {
    for (const char* key : {"height", "phi_max"})
      if (f.has(key))
        f.fail(key, f.name(key) + " cannot be combined with center and normal (use a transform)");
    const Vec3 c = f.vec3("center");
    const Vec3 n = f.direction("normal");
    return make_disk(c, n, radius, inner);
  }
  const double height = f.number("height", 0);
  const double phi = f.number("phi_max", 360);
  if (!(phi > 0 && phi <= 360))
    f.fail("phi_max", f.name("phi_max") + " must be in (0, 360], got " + format_number(phi));
  return make_disk(radius, inner, height, phi);
}

}  // namespace raycast
