#pragma once
// General implicit surfaces f(x, y, z) = 0 from formula text, clipped by a box, found with
// interval arithmetic so that no root is skipped and no bound on the gradient is needed.
#include <string_view>

#include "geometry/shape.h"
#include "math/formula.h"

namespace raycast {

/// Subdivision stops at this depth (the chord split into 2^depth pieces): past it a piece whose
/// inclusion still holds 0 without a sign change is taken to hold no crossing (a tangent touch).
inline constexpr int kImplicitMaxDepth = 48;
/// At most this many interval evaluations per ray: bounds the work on any input (a formula that
/// vanishes on a whole region, say); past it the search gives up and reports no further crossing.
inline constexpr int kImplicitMaxSteps = 20000;

/// The solid {f < 0} intersected with `box` (closed by the box's faces, as algebraic), or with
/// `open` only the surface f = 0 inside the box. Roots along a ray: the box chord's t-interval
/// is subdivided in order; a piece is dropped when the interval inclusion of f over it excludes
/// 0, and a piece whose derivative inclusion (dual numbers over intervals) excludes 0 is monotone
/// and holds a root exactly when f changes sign over it, refined by Newton's method with
/// bisection. The normal is the gradient by automatic differentiation. (u, v) = (0, 0).
struct Implicit {
  static constexpr const char* kName = "implicit";
  Formula f;
  Aabb box;
  bool open = false;
};

/// Throws ExpressionError (offset into `function`) or std::invalid_argument (box).
Implicit make_implicit(std::string_view function, const Aabb& box, bool open = false);

Aabb bounds(const Implicit& s);
bool intersect(const Implicit& s, const Ray& ray, LocalHit& hit);
bool occluded(const Implicit& s, const Ray& ray);
void spans(const Implicit& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Implicit& s, const Ray& ray, const LocalHit& hit);
bool contains(const Implicit& s, const Vec3& p);
inline bool is_closed(const Implicit& s) { return !s.open; }

/// f at p.
double evaluate(const Implicit& s, const Vec3& p);

}  // namespace raycast
