#pragma once
// The shadow rays' own walk over a scene's objects (docs/performance-render.md, session 8): each
// bounded object is culled by a ball around it, a dozen double operations per object and no
// per-ray set-up (the top-level walk's reciprocal, float boxes and visitor cost about as much as
// the shape tests of a shadow ray). The culling is conservative: every object whose exact
// geometry the exact segment meets passes, with a margin far beyond the rounding of the test; the
// objects' own tests decide, so the answers are the top-level walk's.
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/ray.h"
#include "scene/scene.h"

namespace raycast {

/// The objects of a scene in the order ObjectSet's flat walk visits them (unbounded ones, then
/// bounded ones in index order), the bounded ones with a ball around each (world space; the
/// balls' coordinates by component, padded to an even count with empty balls).
struct ShadowBounds {
  /// False when the scene's own walk must be used: more bounded objects than ObjectSet walks flat
  /// (its BVH's order differs), the one-mesh direct path, or coordinates beyond kShadowBallLimit.
  bool usable = false;
  std::vector<std::uint32_t> unbounded;
  std::vector<std::uint32_t> bounded;    // index in scene.objects, by ball
  std::vector<double> x, y, z, radius2;  // centre and radius squared (widened), by ball
};

/// Balls whose |centre| + radius exceeds this, and rays whose |origin| does, use the scene's walk
/// (the test squares distances; this keeps them far from overflow).
inline constexpr double kShadowBallLimit = 1e100;

ShadowBounds make_shadow_bounds(const Scene& scene);

/// Relative widening of the ball test: covers the rounding of v, e and the dot products (a few
/// ulps of |v|^2) many times over.
inline constexpr double kShadowBallSlack = 1e-12;

/// f(bounded[k]) for each ball k, in order, that the half-line from `o` along the unit `e` may come
/// within (false only when its exact distance from the centre exceeds the radius; the segment's
/// far end is not used: conservative); stops when f returns true (returned). With v = centre - o
/// and k = v . e, the distance squared is |v|^2 - k^2 for k > 0, else |v|^2 (the nearest point is
/// the origin). Requires |o| below kShadowBallLimit. Two balls per step in SSE2 (the same
/// operations in the same order as the scalar loop of other architectures).
template <class F>
bool each_shadow_ball(const ShadowBounds& b, const Vec3& o, const Vec3& e, F&& f) {
  const std::size_t n = b.x.size();
#if defined(__SSE2__)
  const __m128d ox = _mm_set1_pd(o.x), oy = _mm_set1_pd(o.y), oz = _mm_set1_pd(o.z);
  const __m128d ex = _mm_set1_pd(e.x), ey = _mm_set1_pd(e.y), ez = _mm_set1_pd(e.z);
  const __m128d shrink = _mm_set1_pd(1 - kShadowBallSlack), zero = _mm_setzero_pd();
  for (std::size_t i = 0; i < n; i += 2) {
    const __m128d vx = _mm_sub_pd(_mm_loadu_pd(&b.x[i]), ox);
    const __m128d vy = _mm_sub_pd(_mm_loadu_pd(&b.y[i]), oy);
    const __m128d vz = _mm_sub_pd(_mm_loadu_pd(&b.z[i]), oz);
    const __m128d vv = _mm_mul_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, vx), _mm_mul_pd(vy, vy)), _mm_mul_pd(vz, vz)), shrink);
    const __m128d k =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, ex), _mm_mul_pd(vy, ey)), _mm_mul_pd(vz, ez));
    const __m128d kk = _mm_and_pd(_mm_cmpgt_pd(k, zero), _mm_mul_pd(k, k));
    unsigned mask = static_cast<unsigned>(
        _mm_movemask_pd(_mm_cmple_pd(_mm_sub_pd(vv, kk), _mm_loadu_pd(&b.radius2[i]))));
    for (; mask != 0; mask &= mask - 1)
      if (f(b.bounded[i + static_cast<std::size_t>(std::countr_zero(mask))])) return true;
  }
#else
  for (std::size_t i = 0; i < n; ++i) {
    const double vx = b.x[i] - o.x, vy = b.y[i] - o.y, vz = b.z[i] - o.z;
    const double vv = (vx * vx + vy * vy + vz * vz) * (1 - kShadowBallSlack);
    const double k = vx * e.x + vy * e.y + vz * e.z;
    const double kk = k > 0 ? k * k : 0.0;
    if (vv - kk <= b.radius2[i] && f(b.bounded[i])) return true;
  }
#endif
  return false;
}

}  // namespace raycast
