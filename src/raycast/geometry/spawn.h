#pragma once
// Origins for secondary rays that cannot re-hit the surface they leave (pbrt-v4 6.8.6): move the
// hit point along the normal by the projection of its error box, then one ulp further out.
#include <cmath>

#include "geometry/hit.h"

namespace raycast {

/// The point to start a ray from s.p in direction w: offset to the side of the surface w points to.
inline Vec3 offset_ray_origin(const SurfaceInfo& s, const Vec3& w) {
  const double dist = dot(abs(s.n), s.p_error);
  Vec3 offset = dist * s.n;
  if (dot(w, s.n) < 0) offset = -offset;
  Vec3 po = s.p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0)
      po[i] = std::nextafter(po[i], kInfinity);
    else if (offset[i] < 0)
      po[i] = std::nextafter(po[i], -kInfinity);
  }
  return po;
}

}  // namespace raycast
