#pragma once
// Two boxes against one ray in one pass, in double (SSE2, the x86-64 baseline; a scalar loop of
// the same arithmetic elsewhere): intersect_slabs (geometry/aabb.h) on two boxes at once, with
// its result and its entry distance bit for bit. A flat set of a few boxes tests them this way
// without the float test's per-ray set-up (rounding the ray and the slack, about 150
// instructions). The planes of each pair are stored for
// one ray octant (near planes in rows 0-2, far in 3-5), so the test loads them in a fixed order.
#include <cmath>
#include <cstdint>

#include "geometry/aabb.h"
#include "geometry/ray.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace raycast {

/// Two boxes for rays of one octant: row a (a < 3) holds each box's near plane on axis a (lo
/// where d's component is positive, hi where it is negative), row 3 + a the far one; lane l is
/// box l.
struct alignas(16) BoxPair {
  double plane[6][2];
};

/// The octant of a direction by the signs of its reciprocal (bit a set: axis a negative), as
/// intersect_slabs picks its planes.
inline unsigned ray_octant(const Vec3& inv_d) {
  return (std::signbit(inv_d.x) ? 1u : 0u) | (std::signbit(inv_d.y) ? 2u : 0u) |
         (std::signbit(inv_d.z) ? 4u : 0u);
}

/// Lane `lane` of `p` set to `box`'s planes for rays of `octant` (an empty box, lo = +inf and
/// hi = -inf, gives a lane no ray with a finite origin meets: its entry is +inf, its exit -inf).
inline void set_box_pair_lane(BoxPair& p, int lane, const Aabb& box, unsigned octant) {
  for (int a = 0; a < 3; ++a) {
    const bool negative = (octant >> a) & 1;
    p.plane[a][lane] = negative ? box.hi[a] : box.lo[a];
    p.plane[3 + a][lane] = negative ? box.lo[a] : box.hi[a];
  }
}

/// box_pair_hits lane by lane: intersect_slabs's arithmetic in its order (the path of other
/// architectures; the tests compare the two on x86-64).
inline unsigned box_pair_hits_scalar(const BoxPair& p, const Vec3& o, const Vec3& inv_d,
                                     double tmin, double tmax, double t_enter[2]) {
  unsigned mask = 0;
  for (int l = 0; l < 2; ++l) {
    double t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
      const double near = (p.plane[a][l] - o[a]) * inv_d[a];
      double far = (p.plane[3 + a][l] - o[a]) * inv_d[a];
      far *= 1 + 2 * gamma(3);
      t0 = near > t0 ? near : t0;
      t1 = far < t1 ? far : t1;
    }
    t_enter[l] = t0;
    if (t0 <= t1) mask |= 1u << l;
  }
  return mask;
}

/// Bit l set when box l of `p` (stored for the octant of inv_d = reciprocal(d)) meets the segment
/// [tmin, tmax] of o + t d by intersect_slabs's test; t_enter[l] is its entry then (the same
/// value). NaN distances (0 * inf) leave their axis unconstrained, as there.
inline unsigned box_pair_hits(const BoxPair& p, const Vec3& o, const Vec3& inv_d, double tmin,
                              double tmax, double t_enter[2]) {
#if defined(__SSE2__)
  // The far distances' minimum is scaled once: x -> x (1 + 2 gamma(3)) is monotone, so scaling
  // the minimum gives the minimum of the scaled values, bit for bit.
  __m128d t0 = _mm_set1_pd(tmin), far = _mm_set1_pd(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const __m128d oa = _mm_set1_pd(o[a]), inv = _mm_set1_pd(inv_d[a]);
    const __m128d n = _mm_mul_pd(_mm_sub_pd(_mm_load_pd(p.plane[a]), oa), inv);
    const __m128d f = _mm_mul_pd(_mm_sub_pd(_mm_load_pd(p.plane[3 + a]), oa), inv);
    t0 = _mm_max_pd(n, t0);  // n NaN: t0 kept
    far = _mm_min_pd(f, far);
  }
  const __m128d t1 = _mm_min_pd(_mm_mul_pd(far, _mm_set1_pd(1 + 2 * gamma(3))), _mm_set1_pd(tmax));
  _mm_storeu_pd(t_enter, t0);
  return static_cast<unsigned>(_mm_movemask_pd(_mm_cmple_pd(t0, t1)));
#else
  return box_pair_hits_scalar(p, o, inv_d, tmin, tmax, t_enter);
#endif
}

}  // namespace raycast
