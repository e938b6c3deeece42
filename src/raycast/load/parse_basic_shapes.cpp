// Parsers for the basic shapes: plane, sphere, box, triangle, parallelogram, disk.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "load/shape_parsers.h"

namespace raycast {

namespace {

// A list of exactly `count` points, each [x, y, z] of finite numbers.
std::vector<Vec3> points(Fields& f, const std::string& key, std::size_t count) {
  const YamlNode n = f.required(key);
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
  const double phi = f.number("phi_max", 360);
  return make_sphere(c, r, z_min, z_max, phi);
}

ShapeVariant parse_shape(std::type_identity<Box>, Fields& f) {
  const Vec3 lo = f.vec3("min");
  const Vec3 hi = f.vec3("max");
  return make_box(lo, hi);
}

ShapeVariant parse_shape(std::type_identity<Triangle>, Fields& f) {
  const std::vector<Vec3> p = points(f, "vertices", 3);
  if (!f.has("normals")) return make_triangle(p[0], p[1], p[2]);
  const std::vector<Vec3> n = points(f, "normals", 3);
  const YamlNode nn = f.optional("normals");
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
  return make_parallelogram(origin, u, v);
}

ShapeVariant parse_shape(std::type_identity<Disk>, Fields& f) {
  const bool centred = f.has("center") || f.has("normal");
  const double radius = f.positive("radius");
  const double inner = f.non_negative("inner_radius", 0);
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
  return make_disk(radius, inner, height, phi);
}

}  // namespace raycast
