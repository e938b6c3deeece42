#pragma once
// Balls around objects, two per record by component, and the half-line test over them: the
// shadow rays' culling in ObjectSet::any_along. A
// dozen double operations per ball and no per-ray set-up (the flat walk's reciprocal and float
// boxes cost about as much as a shadow ray's shape tests). The test is conservative: every ball
// the exact half-line comes within passes, with a margin far beyond the rounding of the test.
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "math/vec3.h"

namespace raycast {

/// Balls whose |centre| + radius exceeds this, and half-lines whose |origin| does, are not
/// tested (the test squares distances; this keeps them far from overflow).
inline constexpr double kBallLimit = 1e100;

/// Relative widening of the ball test: covers the rounding of v, e and the dot products (a few
/// ulps of |v|^2) many times over.
inline constexpr double kBallSlack = 1e-12;

/// A ball's radius squared widened by a relative 1e-12 (the margin the ball tests take beside
/// kBallSlack).
inline double widened_radius2(double radius) { return radius * radius * (1 + 1e-12); }

/// Two balls (lanes 0 and 1): centre and radius squared (widened) by component, and the index
/// of the object each bounds. An unused lane holds an empty ball (radius2 -1).
struct alignas(16) BallPair {
  double x[2], y[2], z[2], radius2[2];
  std::uint32_t index[2];
};

/// Appends a ball (radius >= 0, |centre| + radius within kBallLimit) around object `index`,
/// its radius squared widened by a relative 1e-12.
inline void add_ball(std::vector<BallPair>& balls, std::size_t& count, std::uint32_t index,
                     const Vec3& centre, double radius) {
  const std::size_t lane = count % 2;
  if (lane == 0) balls.push_back({{0, 0}, {0, 0}, {0, 0}, {-1, -1}, {0, 0}});
  BallPair& p = balls.back();
  p.x[lane] = centre.x;
  p.y[lane] = centre.y;
  p.z[lane] = centre.z;
  p.radius2[lane] = widened_radius2(radius);
  p.index[lane] = index;
  ++count;
}

/// f(index) for each ball, in order, that the half-line from `o` along the unit `e` may come
/// within (false only when its exact distance from the centre exceeds the radius; the segment's
/// far end is not used: conservative); stops when f returns true (returned). With v = centre - o
/// and k = v . e, the distance squared is |v|^2 - k^2 for k > 0, else |v|^2 (the nearest point is
/// the origin). Requires |o| below kBallLimit. Two balls per step in SSE2 (the same operations in
/// the same order as the scalar loop of other architectures).
template <class F>
bool each_ball_near(const BallPair* p, const BallPair* end, const Vec3& o, const Vec3& e, F&& f) {
#if defined(__SSE2__)
  const __m128d ox = _mm_set1_pd(o.x), oy = _mm_set1_pd(o.y), oz = _mm_set1_pd(o.z);
  const __m128d ex = _mm_set1_pd(e.x), ey = _mm_set1_pd(e.y), ez = _mm_set1_pd(e.z);
  const __m128d shrink = _mm_set1_pd(1 - kBallSlack), zero = _mm_setzero_pd();
  for (; p != end; ++p) {
    const __m128d vx = _mm_sub_pd(_mm_load_pd(p->x), ox);
    const __m128d vy = _mm_sub_pd(_mm_load_pd(p->y), oy);
    const __m128d vz = _mm_sub_pd(_mm_load_pd(p->z), oz);
    const __m128d vv = _mm_mul_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, vx), _mm_mul_pd(vy, vy)), _mm_mul_pd(vz, vz)), shrink);
    const __m128d k =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, ex), _mm_mul_pd(vy, ey)), _mm_mul_pd(vz, ez));
    const __m128d kk = _mm_and_pd(_mm_cmpgt_pd(k, zero), _mm_mul_pd(k, k));
    unsigned mask = static_cast<unsigned>(
        _mm_movemask_pd(_mm_cmple_pd(_mm_sub_pd(vv, kk), _mm_load_pd(p->radius2))));
    for (; mask != 0; mask &= mask - 1)
      if (f(p->index[std::countr_zero(mask)])) return true;
  }
#else
  for (; p != end; ++p) {
    for (int l = 0; l < 2; ++l) {
      const double vx = p->x[l] - o.x, vy = p->y[l] - o.y, vz = p->z[l] - o.z;
      const double vv = (vx * vx + vy * vy + vz * vz) * (1 - kBallSlack);
      const double k = vx * e.x + vy * e.y + vz * e.z;
      const double kk = k > 0 ? k * k : 0.0;
      if (vv - kk <= p->radius2[l] && f(p->index[l])) return true;
    }
  }
#endif
  return false;
}

}  // namespace raycast
