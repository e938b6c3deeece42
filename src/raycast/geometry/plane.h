#pragma once
// The plane as a half-space solid: inside is behind the normal, as in POV-Ray.
#include <cmath>

#include "geometry/shape.h"

namespace raycast {

/// The solid dot(n, p) <= offset; n is unit. (u, v) are the coordinates of the hit along two
/// fixed tangent axes (s, t) of the plane, measured from `point`.
struct Plane {
  static constexpr const char* kName = "plane";
  Vec3 n{0, 0, 1};
  Vec3 point;
  double offset = 0;  // dot(n, point)
  Vec3 s{1, 0, 0}, t{0, 1, 0};
};

/// A validated plane (finite point, finite non-zero normal); throws std::invalid_argument.
Plane make_plane(const Vec3& normal, const Vec3& point);

Aabb bounds(const Plane& p);
/// The ray parameter where the line meets the plane; NaN or +-inf when parallel.
inline double plane_crossing(const Plane& p, const Ray& ray) {
  return (p.offset - dot(p.n, ray.o)) / dot(p.n, ray.d);
}
/// Whether a plane_crossing t is a crossing within [tmin, tmax]. A parallel ray gives NaN (on
/// the plane) or +-inf (off it): neither is a crossing, even when tmax is infinite.
inline bool plane_crossing_within(double t, const Ray& ray) {
  return std::isfinite(t) && t >= ray.tmin && t <= ray.tmax;
}
/// intersect's answer without the record, inline for the shadow rays' walk
/// (render/integrator.cpp).
inline bool crosses(const Plane& p, const Ray& ray) {
  return plane_crossing_within(plane_crossing(p, ray), ray);
}
bool intersect(const Plane& p, const Ray& ray, LocalHit& hit);
void spans(const Plane& p, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Plane& p, const Ray& ray, const LocalHit& hit);
/// surface() without (u, v) (left 0), for hits whose shading needs no parameters.
SurfaceInfo surface_geometry(const Plane& p, const Ray& ray, const LocalHit& hit);
bool contains(const Plane& p, const Vec3& q);
inline bool is_closed(const Plane&) { return true; }

}  // namespace raycast
