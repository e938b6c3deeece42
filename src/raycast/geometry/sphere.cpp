#include "geometry/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometry/angles.h"
#include "geometry/shape_error.h"
#include "math/float_error.h"

namespace raycast {

namespace {

double phi_of(const Vec3& p) {
  double phi = std::atan2(p.y, p.x);
  if (phi < 0) phi += kTwoPi;
  return phi;
}

// Whether the object-space point (relative to the centre) lies on the kept part.
bool on_kept_part(const Sphere& s, const Vec3& p) {
  if (p.z < s.z_min || p.z > s.z_max) return false;
  return s.phi_max >= kTwoPi || phi_of(p) <= s.phi_max;
}

}  // namespace

bool Sphere::is_partial() const { return z_min > -radius || z_max < radius || phi_max < kTwoPi; }

Sphere make_sphere(const Vec3& center, double radius, double z_min, double z_max,
                   double phi_max_degrees) {
  if (!is_finite(center)) throw std::invalid_argument("center must be finite");
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("radius must be > 0 and finite");
  if (std::isnan(z_min) || std::isnan(z_max) || !(z_min < z_max))
    throw ShapeParameterError("z_max", "must be > z_min, got " + format_parameter(z_max) +
                                           " <= " + format_parameter(z_min));
  if (!(phi_max_degrees > 0 && phi_max_degrees <= 360))
    throw ShapeParameterError("phi_max",
                              "must be in (0, 360], got " + format_parameter(phi_max_degrees));
  Sphere s;
  s.center = center;
  s.radius = radius;
  s.z_min = std::clamp(z_min, -radius, radius);
  s.z_max = std::clamp(z_max, -radius, radius);
  if (!(s.z_min < s.z_max))
    throw ShapeParameterError("z_min", "and z_max must overlap [-radius, radius]");
  s.phi_max = phi_max_degrees >= 360 ? kTwoPi : phi_max_degrees * std::numbers::pi / 180;
  return s;
}

bool sphere_line_roots(const Vec3& o, const Vec3& d, double radius, double& t0, double& t1) {
  return sphere_line_roots(o, d, dot(o, o), radius, t0, t1);
}

Aabb bounds(const Sphere& s) {
  const double r = s.radius;
  return {s.center + Vec3{-r, -r, s.z_min}, s.center + Vec3{r, r, s.z_max}};
}

bool intersect(const Sphere& s, const Ray& ray, LocalHit& hit) {
  const Vec3 o = ray.o - s.center;
  // Outside and moving away: sphere_line_roots would give c > 0 and b > 0, so q < 0 and both
  // roots c / q and q / a negative (the signs are exact), none in [tmin, tmax] for tmin >= 0.
  // Rejected here without the division and the two square roots.
  if (ray.tmin >= 0 && dot(o, o) > s.radius * s.radius && dot(o, ray.d) > 0) return false;
  double t[2];
  if (!sphere_line_roots(o, ray.d, s.radius, t[0], t[1])) return false;
  const bool partial = s.is_partial();
  for (int i = 0; i < 2; ++i) {
    if (t[i] < ray.tmin || t[i] > ray.tmax) continue;
    if (partial && !on_kept_part(s, o + t[i] * ray.d)) continue;
    hit = LocalHit{.t = t[i], .part = i};
    return true;
  }
  return false;
}

void spans(const Sphere& s, const Ray& ray, SpanList& out) {
  const Vec3 o = ray.o - s.center;
  double t0, t1;
  if (!sphere_line_roots(o, ray.d, s.radius, t0, t1)) return;
  const LocalHit h0{t0, -1, 0, 0, 0}, h1{t1, -1, 1, 0, 0};
  if (!s.is_partial()) {
    out.add(h0, h1);
    return;
  }
  if (on_kept_part(s, o + t0 * ray.d)) out.add(h0, h0);
  if (t1 != t0 && on_kept_part(s, o + t1 * ray.d)) out.add(h1, h1);
}

namespace {

// The hit point relative to the centre, reprojected onto the surface, and its record without
// (u, v); the remaining error is gamma(5) |p| (pbrt-v4 6.8.5).
SurfaceInfo geometry_at(const Sphere& s, const Ray& ray, const LocalHit& hit, Vec3& p) {
  SurfaceInfo si;
  p = ray.o - s.center + hit.t * ray.d;
  p *= s.radius / length(p);
  si.p_error = gamma(5) * abs(p) + gamma(1) * abs(s.center);
  si.n = p / s.radius;
  si.shading_n = si.n;
  si.p = p + s.center;
  return si;
}

}  // namespace

SurfaceInfo surface_geometry(const Sphere& s, const Ray& ray, const LocalHit& hit) {
  Vec3 p;
  return geometry_at(s, ray, hit, p);
}

SurfaceInfo surface(const Sphere& s, const Ray& ray, const LocalHit& hit) {
  Vec3 p;
  SurfaceInfo si = geometry_at(s, ray, hit, p);
  si.u = phi_of(p) / s.phi_max;
  const double theta = std::acos(std::clamp(p.z / s.radius, -1.0, 1.0));
  // acos(-1) is pi and acos(1) is 0 exactly: whole spheres skip those two calls.
  const double z_lo = std::clamp(s.z_min / s.radius, -1.0, 1.0);
  const double z_hi = std::clamp(s.z_max / s.radius, -1.0, 1.0);
  const double theta_lo = z_lo == -1 ? std::numbers::pi : std::acos(z_lo);
  const double theta_hi = z_hi == 1 ? 0.0 : std::acos(z_hi);
  si.v = (theta_lo - theta) / (theta_lo - theta_hi);
  return si;
}

bool contains(const Sphere& s, const Vec3& p) {
  return !s.is_partial() && length_squared(p - s.center) <= s.radius * s.radius;
}

bool is_closed(const Sphere& s) { return !s.is_partial(); }

}  // namespace raycast
