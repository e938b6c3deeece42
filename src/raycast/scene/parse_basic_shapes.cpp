// Parsers for the first shapes: plane, sphere.
#include <cmath>
#include <stdexcept>

#include "scene/shape_parsers.h"

namespace raycast {

ShapeVariant parse_plane(Fields& f) {
  const Vec3 n = f.direction("normal");
  const Vec3 p = f.vec3("point", {0, 0, 0});
  return make_plane(n, p);
}

ShapeVariant parse_sphere(Fields& f) {
  const Vec3 c = f.vec3("center", {0, 0, 0});
  const double r = f.positive("radius");
  const double z_min = f.number("z_min", -r);
  const double z_max = f.number("z_max", r);
  if (!(z_min < z_max)) f.fail("z_max", f.name("z_max") + " must be > z_min");
  if (z_max <= -r || z_min >= r) f.fail("z_min", f.name("z_min") + ", z_max must overlap [-radius, radius]");
  const double phi = f.number("phi_max", 360);
  if (!(phi > 0 && phi <= 360)) f.fail("phi_max", f.name("phi_max") + " must be in (0, 360]");
  return make_sphere(c, r, z_min, z_max, phi);
}

}  // namespace raycast
