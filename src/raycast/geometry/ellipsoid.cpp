#include "geometry/ellipsoid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/sphere.h"

namespace raycast {

namespace {

// Both crossings of the line with the ellipsoid, from the unit sphere in scaled coordinates:
// the scaling is linear, so t is the same in both spaces.
bool roots(const Ellipsoid& e, const Ray& ray, double& t0, double& t1) {
  const Vec3 o = mul(ray.o - e.center, e.inv_radii);
  const Vec3 d = mul(ray.d, e.inv_radii);
  return sphere_line_roots(o, d, 1.0, t0, t1);
}

}  // namespace

Ellipsoid make_ellipsoid(const Vec3& center, const Vec3& radii) {
  if (!is_finite(center)) throw std::invalid_argument("center must be finite");
  for (int i = 0; i < 3; ++i)
    if (!(radii[i] > 0) || !std::isfinite(radii[i]) || !std::isfinite(1 / radii[i]))
      throw std::invalid_argument("radii must be > 0 and finite");
  Ellipsoid e;
  e.center = center;
  e.radii = radii;
  e.inv_radii = {1 / radii.x, 1 / radii.y, 1 / radii.z};
  return e;
}

Aabb bounds(const Ellipsoid& e) { return {e.center - e.radii, e.center + e.radii}; }

bool intersect(const Ellipsoid& e, const Ray& ray, LocalHit& hit) {
  double t[2];
  if (!roots(e, ray, t[0], t[1])) return false;
  for (int i = 0; i < 2; ++i) {
    if (t[i] < ray.tmin || t[i] > ray.tmax) continue;
    hit = LocalHit{.t = t[i], .part = i};
    return true;
  }
  return false;
}

bool occluded(const Ellipsoid& e, const Ray& ray) {
  double t0, t1;
  if (!roots(e, ray, t0, t1)) return false;
  return (t0 >= ray.tmin && t0 <= ray.tmax) || (t1 >= ray.tmin && t1 <= ray.tmax);
}

void spans(const Ellipsoid& e, const Ray& ray, SpanList& out) {
  double t0, t1;
  if (!roots(e, ray, t0, t1)) return;
  out.add(LocalHit{.t = t0}, LocalHit{.t = t1, .part = 1});
}

namespace {

// The record without (u, v); q is the hit point on the unit sphere (reprojected).
SurfaceInfo geometry_at(const Ellipsoid& e, const Ray& ray, const LocalHit& hit, Vec3& q) {
  SurfaceInfo si;
  // The point on the unit sphere, reprojected (pbrt-v4 6.8.5), then scaled back.
  q = mul(ray.o - e.center, e.inv_radii) + hit.t * mul(ray.d, e.inv_radii);
  q /= length(q);
  const Vec3 p = mul(q, e.radii);
  si.p = p + e.center;
  si.p_error = gamma(7) * abs(p) + gamma(1) * abs(e.center);
  // The gradient of the implicit function: (x/a^2, y/b^2, z/c^2) = q / radii.
  si.n = normalize(mul(q, e.inv_radii));
  si.shading_n = si.n;
  return si;
}

}  // namespace

SurfaceInfo surface_geometry(const Ellipsoid& e, const Ray& ray, const LocalHit& hit) {
  Vec3 q;
  return geometry_at(e, ray, hit, q);
}

SurfaceInfo surface(const Ellipsoid& e, const Ray& ray, const LocalHit& hit) {
  Vec3 q;
  SurfaceInfo si = geometry_at(e, ray, hit, q);
  double phi = std::atan2(q.y, q.x);
  if (phi < 0) phi += 2 * std::numbers::pi;
  si.u = phi / (2 * std::numbers::pi);
  si.v = 1 - std::acos(std::clamp(q.z, -1.0, 1.0)) / std::numbers::pi;
  return si;
}

bool contains(const Ellipsoid& e, const Vec3& p) {
  return length_squared(mul(p - e.center, e.inv_radii)) <= 1;
}

}  // namespace raycast
