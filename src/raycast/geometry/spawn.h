#pragma once
// Origins for secondary rays that cannot re-hit the surface they leave (pbrt-v4 6.8.6): move the
// hit point along the normal by the projection of its error box, then one ulp further out.
#include <cmath>
#include <limits>

#include "geometry/hit.h"
#include "math/interval.h"

namespace raycast {

/// The point to start a ray from s.p in direction w: offset to the side of the surface w points to.
/// The ulp step follows the sign of the normal itself, so a point with a zero error bound (a box
/// face or a disk snapped exactly onto its plane) still leaves the surface rather than staying on
/// it, where a ray with tmin = 0 would hit it again at t = 0. A coordinate that would end up
/// subnormal (a surface through 0) moves to the smallest normal double instead: one subnormal
/// ulp divided by a direction component above 1 underflows to t = -0, which counts as t >= 0.
/// This holds for direction components below 2^52 in magnitude.
inline Vec3 offset_ray_origin(const SurfaceInfo& s, const Vec3& w) {
  const double dist = dot(abs(s.n), s.p_error);
  Vec3 dir = s.n;
  if (dot(w, s.n) < 0) dir = -dir;
  Vec3 po = s.p + dist * dir;
  constexpr double kMinNormal = std::numeric_limits<double>::min();
  for (int i = 0; i < 3; ++i) {
    if (dir[i] == 0) continue;
    const double away = dir[i] > 0 ? kInfinity : -kInfinity;
    // One ulp towards `away`, as std::nextafter(po[i], away) but without the libm call.
    po[i] = dir[i] > 0 ? interval_detail::up(po[i]) : interval_detail::down(po[i]);
    if (std::abs(po[i]) < kMinNormal && (po[i] == 0 || std::signbit(po[i]) == std::signbit(away)))
      po[i] = std::copysign(kMinNormal, away);
  }
  return po;
}

}  // namespace raycast
