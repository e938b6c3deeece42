#pragma once
// The shadow rays' own walk over a scene's objects (docs/performance-render.md, session 8): each
// bounded object is culled by a ball around it, a dozen double operations per object and no
// per-ray set-up (the top-level walk's reciprocal, float boxes and visitor cost about as much as
// the shape tests of a shadow ray). The culling is conservative: every object whose exact
// geometry the exact segment meets passes, with a margin far beyond the rounding of the test; the
// objects' own tests decide, so the answers are the top-level walk's.
#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "scene/scene.h"

namespace raycast {

/// A ball holding one bounded object (world space), and the object's index in scene.objects.
struct ShadowBall {
  Vec3 centre;
  double radius2 = 0;  // the radius squared, widened for rounding
  std::uint32_t index = 0;
};

/// The objects of a scene in the order ObjectSet's flat walk visits them (unbounded ones, then
/// bounded ones in index order), the bounded ones with their balls.
struct ShadowBounds {
  /// False when the scene's own walk must be used: more bounded objects than ObjectSet walks flat
  /// (its BVH's order differs), the one-mesh direct path, or coordinates beyond kShadowBallLimit.
  bool usable = false;
  std::vector<std::uint32_t> unbounded;
  std::vector<ShadowBall> balls;
};

/// Balls whose |centre| + radius exceeds this, and rays whose |origin| does, use the scene's walk
/// (the test squares distances; this keeps them far from overflow).
inline constexpr double kShadowBallLimit = 1e100;

ShadowBounds make_shadow_bounds(const Scene& scene);

/// Relative widening of the ball test: covers the rounding of v, e and the dot products (a few
/// ulps of |v|^2) many times over.
inline constexpr double kShadowBallSlack = 1e-12;

/// The unit direction of a segment's d (|d|^2 a finite normal double: is_valid).
inline Vec3 shadow_direction(const Vec3& d) { return d * (1 / std::sqrt(length_squared(d))); }

/// Whether the half-line from `o` along the unit `e` may come within the ball: false only when
/// its exact distance from the centre exceeds the radius (the segment's far end is not used:
/// conservative). Requires |o| and |centre| below kShadowBallLimit.
inline bool may_meet(const ShadowBall& b, const Vec3& o, const Vec3& e) {
  const Vec3 v = b.centre - o;
  const double vv = length_squared(v) * (1 - kShadowBallSlack);
  const double k = dot(v, e);
  // Behind the origin the nearest point of the half-line is the origin itself.
  if (!(k > 0)) return vv <= b.radius2;
  return vv - k * k <= b.radius2;
}

}  // namespace raycast
