#pragma once
// Algebraic surfaces of any degree (up to kMaxPolynomialDegree) from equation text, clipped by a
// box.
#include <string>
#include <string_view>

#include "geometry/shape.h"
#include "math/trivariate.h"

namespace raycast {

/// The solid {f < 0} intersected with `box` (the box's faces close it where the solid reaches
/// them, as POV-Ray's contained_by), or with `open` only the surface f = 0 inside the box, an open
/// surface. Per ray, f(o + t d) is expanded into a polynomial in t about the middle of the box's
/// chord and its real roots on the chord are isolated (find_real_roots). The normal is the
/// gradient of f (a box face's normal on the faces). (u, v) = (0, 0).
struct Algebraic {
  static constexpr const char* kName = "algebraic";
  Trivariate f;
  Aabb box;
  bool open = false;
  /// The part of `box` where the solid (or the open surface) may lie, from interval bounds of f
  /// (reach_of_algebraic): what bounds() reports, so that rays through the box's empty corners
  /// never reach the root finder. Empty: not computed (bounds() is then the box).
  Aabb reach;
};

/// The smallest box found within s.box outside which f certainly keeps the sign of the empty
/// side, with a margin: f > delta there (closed), or |f| > delta (open), for delta = 1e-9 times a
/// bound on the magnitude of f's terms over the box, a million times the rounding of any
/// evaluation, so that no crossing the root finder reports, nor any point inside the solid, lies
/// outside it. Per side, a best-first search over halved cells (each bounded by interval
/// arithmetic on the formula as written) down to 1/256 of the box's extent. s.box when the search
/// finds nothing to keep (an empty solid: the box is a valid, if loose, answer).
Aabb reach_of_algebraic(const Algebraic& s);

/// Throws ExpressionError (a std::invalid_argument with the offset in `equation`) for bad text,
/// std::invalid_argument for a box that is not finite with min < max on every axis, or a
/// constant equation.
Algebraic make_algebraic(std::string_view equation, const Aabb& box, bool open = false);

Aabb bounds(const Algebraic& s);
bool intersect(const Algebraic& s, const Ray& ray, LocalHit& hit);
bool occluded(const Algebraic& s, const Ray& ray);
void spans(const Algebraic& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Algebraic& s, const Ray& ray, const LocalHit& hit);
bool contains(const Algebraic& s, const Vec3& p);
inline bool is_closed(const Algebraic& s) { return !s.open; }

/// Validates a `bounds` box for the clipped shapes; throws std::invalid_argument.
void check_bounds_box(const Aabb& box);

}  // namespace raycast
