#pragma once
// Axis-aligned bounding boxes and the slab test.
#include <cmath>

#include "geometry/ray.h"
#include "math/float_error.h"
#include "math/transform.h"
#include "math/vec3.h"

namespace raycast {

/// A closed box [lo, hi]. The default box is empty (lo = +inf, hi = -inf) so that growing it by
/// anything gives that thing's box.
struct Aabb {
  Vec3 lo{kInfinity, kInfinity, kInfinity};
  Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

  static Aabb everything() {
    return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
  }
  bool is_empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  bool is_bounded() const { return is_finite(lo) && is_finite(hi); }
  Vec3 centre() const { return 0.5 * (lo + hi); }
  Vec3 extent() const { return hi - lo; }
  void grow(const Vec3& p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void grow(const Aabb& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  bool contains(const Vec3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  /// Half the surface area (the SAH only needs ratios); 0 for an empty box.
  double half_area() const {
    if (is_empty()) return 0;
    const Vec3 e = extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

inline Aabb merge(Aabb a, const Aabb& b) {
  a.grow(b);
  return a;
}
inline Aabb overlap(const Aabb& a, const Aabb& b) { return {max(a.lo, b.lo), min(a.hi, b.hi)}; }

/// The box of the transformed corners of b (exact for affine maps); unbounded boxes stay
/// unbounded on every axis that an infinite extent can reach.
Aabb transform_bounds(const Transform& xf, const Aabb& b);

/// 1 / d per component; a zero component gives +-inf, which the slab test expects. x and y in one
/// packed division: the same correctly rounded quotients as scalar ones, one division fewer on the
/// per-ray path (three divsd were 11% of a one-object scene's ray).
inline Vec3 reciprocal(const Vec3& d) {
  using V2 = double __attribute__((vector_size(16)));
  const V2 q = V2{1.0, 1.0} / V2{d.x, d.y};
  return {q[0], q[1], 1.0 / d.z};
}

/// Slab test (Kay and Kajiya 1986): the entry is the largest of the per-axis entries, the exit the
/// smallest of the exits; a hit when entry <= exit and [entry, exit] meets [tmin, tmax]. The near
/// and far planes are chosen by the sign of inv_d (not by comparing the two t values, which would
/// turn an empty box inside out), and comparisons are ordered so that the NaN of 0 * inf (origin
/// on a slab plane, direction parallel to it, either sign of zero) leaves that axis
/// unconstrained. The exit is widened by 2 gamma(3) so the test is conservative under rounding
/// (pbrt-v4 6.8.2). On a hit, t_enter is the entry clipped to tmin.
inline bool intersect_slabs(const Aabb& b, const Vec3& o, const Vec3& inv_d, double tmin,
                            double tmax, double& t_enter) {
  double t0 = tmin, t1 = tmax;
  for (int a = 0; a < 3; ++a) {
    const bool negative = std::signbit(inv_d[a]);
    const double near = ((negative ? b.hi[a] : b.lo[a]) - o[a]) * inv_d[a];
    double far = ((negative ? b.lo[a] : b.hi[a]) - o[a]) * inv_d[a];
    far *= 1 + 2 * gamma(3);
    t0 = near > t0 ? near : t0;
    t1 = far < t1 ? far : t1;
    if (t0 > t1) return false;
  }
  t_enter = t0;
  return true;
}

/// The whole-line variant: [t_enter, t_exit] of the line o + t d inside b, unclipped.
inline bool slab_interval(const Aabb& b, const Vec3& o, const Vec3& inv_d, double& t_enter,
                          double& t_exit) {
  double t0 = -kInfinity, t1 = kInfinity;
  for (int a = 0; a < 3; ++a) {
    const bool negative = std::signbit(inv_d[a]);
    const double near = ((negative ? b.hi[a] : b.lo[a]) - o[a]) * inv_d[a];
    const double far = ((negative ? b.lo[a] : b.hi[a]) - o[a]) * inv_d[a];
    t0 = near > t0 ? near : t0;
    t1 = far < t1 ? far : t1;
  }
  if (!(t0 <= t1)) return false;
  t_enter = t0;
  t_exit = t1;
  return true;
}

}  // namespace raycast
