#include "geometry/cone.h"

#include <cmath>
#include <stdexcept>

namespace raycast {

Cone make_cone(double radius, double height, double phi_max_degrees, bool capped) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("radius must be > 0 and finite");
  if (!(height > 0) || !std::isfinite(height))
    throw std::invalid_argument("height must be > 0 and finite");
  return Cone{make_frustum(0, height, radius, 0, phi_max_degrees, capped)};
}

Cone make_cone(const Vec3& from, const Vec3& to, double radius_from, double radius_to,
               bool capped) {
  return Cone{make_frustum(from, to, radius_from, radius_to, capped)};
}

}  // namespace raycast
