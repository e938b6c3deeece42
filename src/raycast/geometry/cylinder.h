#pragma once
// Partial cylinders, pbrt-style, on the shared frustum core (geometry/frustum.h).
#include "geometry/frustum.h"

namespace raycast {

/// The cylinder x^2 + y^2 = radius^2 for z_min <= z <= z_max (pbrt-style), cut to
/// 0 <= phi <= phi_max, with disks closing its ends when capped; or the same from `from` to `to`
/// (z_min = 0 at from). A closed solid when phi_max = 360 and capped, else an open surface.
/// u = phi / phi_max, v = (z - z_min) / (z_max - z_min) (also on the caps: 0 and 1).
/// The side is a quadratic in t solved in the cancellation-free form (math/quadratic.h); the
/// make_ functions throw std::invalid_argument for bad parameters.
struct Cylinder {
  static constexpr const char* kName = "cylinder";
  Frustum f;
};

/// A validated canonical cylinder (radius > 0; z_min < z_max; 0 < phi_max <= 360 degrees).
Cylinder make_cylinder(double radius, double z_min, double z_max, double phi_max_degrees = 360,
                       bool capped = true);
/// A validated cylinder from `from` to `to` (distinct points), full around its axis.
Cylinder make_cylinder(const Vec3& from, const Vec3& to, double radius, bool capped = true);

inline Aabb bounds(const Cylinder& s) { return frustum_bounds(s.f); }
inline bool intersect(const Cylinder& s, const Ray& ray, LocalHit& hit) {
  return frustum_intersect(s.f, ray, hit);
}
inline void spans(const Cylinder& s, const Ray& ray, SpanList& out) {
  frustum_spans(s.f, ray, out);
}
inline SurfaceInfo surface(const Cylinder& s, const Ray& ray, const LocalHit& hit) {
  return frustum_surface(s.f, ray, hit);
}
inline SurfaceInfo surface_geometry(const Cylinder& s, const Ray& ray, const LocalHit& hit) {
  return frustum_surface_geometry(s.f, ray, hit);
}
inline bool contains(const Cylinder& s, const Vec3& p) { return frustum_contains(s.f, p); }
inline bool is_closed(const Cylinder& s) { return s.f.is_closed(); }

}  // namespace raycast
