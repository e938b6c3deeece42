#include "geometry/cylinder.h"

#include <cmath>
#include <stdexcept>

namespace raycast {

Cylinder make_cylinder(double radius, double z_min, double z_max, double phi_max_degrees,
                       bool capped) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("radius must be > 0 and finite");
  return Cylinder{make_frustum(z_min, z_max, radius, radius, phi_max_degrees, capped)};
}

Cylinder make_cylinder(const Vec3& from, const Vec3& to, double radius, bool capped) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("radius must be > 0 and finite");
  return Cylinder{make_frustum(from, to, radius, radius, capped)};
}

}  // namespace raycast
