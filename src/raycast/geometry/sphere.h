#pragma once
// Spheres, whole or partial (pbrt-style z range and phi_max), in object space.
#include "geometry/shape.h"

namespace raycast {

/// The sphere |p - center| = radius. Partial when z_min > -radius, z_max < radius or
/// phi_max < 2 pi: then only the surface with z_min <= z - center.z <= z_max and
/// atan2(y, x) <= phi_max remains, an open surface. Angles in radians here; the loader converts.
struct Sphere {
  static constexpr const char* kName = "sphere";
  Vec3 center;
  double radius = 1;
  double z_min = -kInfinity;  // relative to center, clamped to [-radius, radius] by make_sphere
  double z_max = kInfinity;
  double phi_max = 0;  // radians in (0, 2 pi]; set by make_sphere

  bool is_partial() const;
};

/// A validated sphere (radius > 0 and finite; z_min < z_max; 0 < phi_max_degrees <= 360).
/// Throws std::invalid_argument naming the bad parameter otherwise.
Sphere make_sphere(const Vec3& center, double radius, double z_min = -kInfinity,
                   double z_max = kInfinity, double phi_max_degrees = 360);

Aabb bounds(const Sphere& s);
bool intersect(const Sphere& s, const Ray& ray, LocalHit& hit);
void spans(const Sphere& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Sphere& s, const Ray& ray, const LocalHit& hit);
/// surface() without (u, v) (left 0): no atan2 or acos, for hits whose shading needs no
/// parameters (scene/object.h surface with SurfaceNeeds::kGeometry).
SurfaceInfo surface_geometry(const Sphere& s, const Ray& ray, const LocalHit& hit);
bool contains(const Sphere& s, const Vec3& p);
bool is_closed(const Sphere& s);

/// Both crossings of the full sphere's line (t0 <= t1), in units of ray.d; false when the line
/// misses. Shared by the sphere and the ellipsoid.
bool sphere_line_roots(const Vec3& o, const Vec3& d, double radius, double& t0, double& t1);

}  // namespace raycast
