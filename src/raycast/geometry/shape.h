#pragma once
// The shape concept: every shape type is a plain value struct in object space with this small set
// of free functions (found by argument-dependent lookup). See docs/architecture.md.
#include <concepts>

#include "geometry/aabb.h"
#include "geometry/hit.h"
#include "geometry/ray.h"
#include "geometry/span_list.h"

namespace raycast {

// Contracts, for every shape S (the ray is in S's object space; t in units of ray.d):
// - bounds(s): a box containing the surface (infinite extents for unbounded shapes).
// - intersect(s, ray, hit): the nearest crossing with ray.tmin <= t <= ray.tmax; fills hit and
//   returns true, or returns false and leaves hit untouched.
// - occluded(s, ray): whether any crossing lies in [tmin, tmax]; may stop at the first found.
//   Optional: a shape with no cheaper any-hit test than its nearest hit gets the default below.
// - spans(s, ray, out): appends, sorted by t, every interval of the whole line (t from -inf to
//   inf, ignoring tmin/tmax) inside the solid; for open surfaces each crossing as a zero-length
//   span.
// - surface(s, ray, hit): the full record for a hit produced by intersect or spans with this ray.
// - contains(s, p): p inside the closed solid (false everywhere for open surfaces).
// - is_closed(s): whether s bounds a solid (only those may be CSG operands).
// - S::kName: the shape's key in the scene format ("sphere"), for messages and `raycast info`.
/// The default any-hit query: the nearest hit. A shape's own non-template `occluded` (a faster
/// test, or one that stops at the first crossing found) is preferred by overload resolution.
template <class S>
requires requires(const S& s, const Ray& ray, LocalHit& hit) {
  { intersect(s, ray, hit) } -> std::same_as<bool>;
}
bool occluded(const S& s, const Ray& ray) {
  LocalHit hit;
  return intersect(s, ray, hit);
}

template <class S>
concept Shape = requires(const S& s, const Ray& ray, LocalHit& hit, const LocalHit& chit,
                         SpanList& out, const Vec3& p) {
  { S::kName } -> std::convertible_to<const char*>;
  { bounds(s) } -> std::same_as<Aabb>;
  { intersect(s, ray, hit) } -> std::same_as<bool>;
  { occluded(s, ray) } -> std::same_as<bool>;
  { spans(s, ray, out) } -> std::same_as<void>;
  { surface(s, ray, chit) } -> std::same_as<SurfaceInfo>;
  { contains(s, p) } -> std::same_as<bool>;
  { is_closed(s) } -> std::same_as<bool>;
};

}  // namespace raycast
