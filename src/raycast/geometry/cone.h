#pragma once
// Partial cones, pbrt-style, on the shared frustum core (geometry/frustum.h).
#include "geometry/frustum.h"

namespace raycast {

/// The cone of pbrt: base radius `radius` at z = 0 narrowing to its apex at z = height, cut to
/// 0 <= phi <= phi_max, with the base disk when capped; or the frustum from `from` (radius_from)
/// to `to` (radius_to), with a disk at each end of non-zero radius when capped. A closed solid
/// when phi_max = 360 and capped, else an open surface. u = phi / phi_max, v = the height
/// fraction (0 at the base or `from`, 1 at the apex or `to`).
/// The side is a quadratic in t solved in the cancellation-free form (math/quadratic.h); the
/// make_ functions throw std::invalid_argument for bad parameters.
struct Cone {
  static constexpr const char* kName = "cone";
  Frustum f;
};

/// A validated canonical cone (radius > 0, height > 0, 0 < phi_max <= 360 degrees).
Cone make_cone(double radius, double height, double phi_max_degrees = 360, bool capped = true);
/// A validated frustum from `from` to `to` (radii >= 0, not both 0), full around its axis.
Cone make_cone(const Vec3& from, const Vec3& to, double radius_from, double radius_to,
               bool capped = true);

inline Aabb bounds(const Cone& s) { return frustum_bounds(s.f); }
inline bool intersect(const Cone& s, const Ray& ray, LocalHit& hit) {
  return frustum_intersect(s.f, ray, hit);
}
inline void spans(const Cone& s, const Ray& ray, SpanList& out) { frustum_spans(s.f, ray, out); }
inline SurfaceInfo surface(const Cone& s, const Ray& ray, const LocalHit& hit) {
  return frustum_surface(s.f, ray, hit);
}
inline SurfaceInfo surface_geometry(const Cone& s, const Ray& ray, const LocalHit& hit) {
  return frustum_surface_geometry(s.f, ray, hit);
}
inline bool contains(const Cone& s, const Vec3& p) { return frustum_contains(s.f, p); }
inline bool is_closed(const Cone& s) { return s.f.is_closed(); }

}  // namespace raycast
