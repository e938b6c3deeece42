#pragma once
// Origins for secondary rays that cannot re-hit the surface they leave (pbrt-v4 6.8.6): move the
// hit point along the normal by the projection of its error box, then one ulp further out.
#include <cmath>

#include "geometry/hit.h"

namespace raycast {

/// The point to start a ray from s.p in direction w: offset to the side of the surface w points to.
inline Vec3 offset_ray_origin(const SurfaceInfo& s, const Vec3& w) {
  const double dist = dot(abs(s.n), s.p_error);
  const Vec3 side = dot(w, s.n) < 0 ? -s.n : s.n;
  Vec3 po = s.p + dist * side;
  // The ulp step follows the normal, not the offset: a point computed exactly (zero error bound,
  // e.g. on the plane y = 0) must still leave the surface, or t = 0 would re-hit it.
  for (int i = 0; i < 3; ++i) {
    if (side[i] > 0)
      po[i] = std::nextafter(po[i], kInfinity);
    else if (side[i] < 0)
      po[i] = std::nextafter(po[i], -kInfinity);
  }
  return po;
}

}  // namespace raycast
