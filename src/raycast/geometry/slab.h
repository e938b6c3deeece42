#pragma once
// The solid between two parallel planes.
#include "geometry/shape.h"

namespace raycast {

/// The solid d0 <= n . p <= d1 with n as given (not normalised). Part 0 is the plane n.p = d0
/// (outward normal -n/|n|), part 1 the plane n.p = d1 (normal n/|n|). (u, v) are 0.
struct Slab {
  static constexpr const char* kName = "slab";
  Vec3 n{0, 0, 1};
  double d0 = 0, d1 = 1;
  double width = 1;  // d1 - d0
  Vec3 unit_n{0, 0, 1};
};

/// A validated slab (finite non-zero n, finite d0 < d1); throws std::invalid_argument.
Slab make_slab(const Vec3& n, double d0, double d1);

Aabb bounds(const Slab& s);
bool intersect(const Slab& s, const Ray& ray, LocalHit& hit);
void spans(const Slab& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Slab& s, const Ray& ray, const LocalHit& hit);
inline bool contains(const Slab& s, const Vec3& p) {
  const double x = dot(s.n, p);
  return s.d0 <= x && x <= s.d1;
}
inline bool is_closed(const Slab&) { return true; }

}  // namespace raycast
