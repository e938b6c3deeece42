#pragma once
// Spheres, whole or partial (pbrt-style z range and phi_max), in object space.
#include <cmath>
#include <limits>
#include <utility>

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
/// parameters (objects/object.h surface with SurfaceNeeds::kGeometry).
SurfaceInfo surface_geometry(const Sphere& s, const Ray& ray, const LocalHit& hit);
bool contains(const Sphere& s, const Vec3& p);
bool is_closed(const Sphere& s);

/// Both crossings of the full sphere's line (t0 <= t1), in units of ray.d; false when the line
/// misses. Shared by the sphere and the ellipsoid.
bool sphere_line_roots(const Vec3& o, const Vec3& d, double radius, double& t0, double& t1);

/// sphere_line_roots with dot(o, o) already computed (`oo`), inline for CSG's interval walk; the
/// same arithmetic, so the same roots bit for bit.
inline bool sphere_line_roots(const Vec3& o, const Vec3& d, double oo, double radius, double& t0,
                              double& t1) {
  // Hearn and Baker's refinement (used by pbrt-v4): b^2 - 4ac = 4a (r^2 - |f|^2) with f the
  // line's closest point to the centre, computed as (r - |f|)(r + |f|) without cancellation.
  const double a = dot(d, d);
  const double b = 2 * dot(o, d);
  const double c = oo - radius * radius;
  const Vec3 f = o - (b / (2 * a)) * d;
  const double f2 = dot(f, f);
  // Early out before both square roots: |f|^2 above r^2 (1 + 8 eps) makes the rounded |f|
  // exceed r (sqrt and the two products round by at most 3 eps), which the test below rejects.
  if (f2 > radius * radius * (1 + 8 * std::numeric_limits<double>::epsilon())) return false;
  const double lf = std::sqrt(f2);
  const double disc = 4 * a * (radius + lf) * (radius - lf);
  if (!(disc >= 0)) return false;
  const double root = std::sqrt(disc);
  const double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
  if (q == 0) {
    t0 = t1 = 0;
  } else {
    t0 = q / a;
    t1 = c / q;
  }
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace raycast
