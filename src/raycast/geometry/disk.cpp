#include "geometry/disk.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/angles.h"
#include "geometry/shape_error.h"
#include "math/float_error.h"

namespace raycast {

namespace {

void check_radii(double radius, double inner_radius) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw std::invalid_argument("radius must be > 0 and finite");
  if (!(inner_radius >= 0) || !(inner_radius < radius))
    throw ShapeParameterError("inner_radius",
                              "must be in [0, radius), got " + format_parameter(inner_radius));
}

// The crossing of the line with the disk's plane and its in-plane coordinates; false when the
// line is parallel to the plane or the crossing lies off the kept annulus sector (edges kept).
bool line_crossing(const Disk& d, const Ray& ray, double& t, double& x, double& y) {
  if (d.canonical) {
    // z = height exactly; the other coordinates carry the rounding of o + t d.
    if (ray.d.z == 0) return false;
    t = (d.center.z - ray.o.z) / ray.d.z;
    x = ray.o.x + t * ray.d.x;
    y = ray.o.y + t * ray.d.y;
  } else {
    const double dn = dot(d.n, ray.d);
    if (dn == 0) return false;
    const Vec3 oc = ray.o - d.center;
    t = -dot(d.n, oc) / dn;
    const Vec3 rel = oc + t * ray.d;
    x = dot(rel, d.s);
    y = dot(rel, d.t);
  }
  if (!std::isfinite(t)) return false;
  const double r2 = x * x + y * y;
  if (r2 > d.radius * d.radius || r2 < d.inner_radius * d.inner_radius) return false;
  return d.phi_max >= kTwoPi || phi_of(x, y) <= d.phi_max;
}

}  // namespace

Disk make_disk(double radius, double inner_radius, double height, double phi_max_degrees) {
  check_radii(radius, inner_radius);
  if (!std::isfinite(height)) throw std::invalid_argument("height must be finite");
  if (!(phi_max_degrees > 0 && phi_max_degrees <= 360))
    throw ShapeParameterError("phi_max",
                              "must be in (0, 360], got " + format_parameter(phi_max_degrees));
  Disk d;
  d.center = {0, 0, height};
  d.radius = radius;
  d.inner_radius = inner_radius;
  d.phi_max = phi_max_degrees >= 360 ? kTwoPi : phi_max_degrees * std::numbers::pi / 180;
  return d;
}

Disk make_disk(const Vec3& center, const Vec3& normal, double radius, double inner_radius) {
  if (!is_finite(center)) throw std::invalid_argument("center must be finite");
  if (!is_finite(normal) || length_squared(normal) == 0 || !std::isfinite(length_squared(normal)))
    throw std::invalid_argument("normal must be finite and non-zero");
  check_radii(radius, inner_radius);
  Disk d;
  d.center = center;
  d.n = normalize(normal);
  make_frame(d.n, d.s, d.t);
  d.canonical = d.n == Vec3{0, 0, 1} && d.s == Vec3{1, 0, 0} && d.t == Vec3{0, 1, 0} &&
                center.x == 0 && center.y == 0;
  d.radius = radius;
  d.inner_radius = inner_radius;
  d.phi_max = kTwoPi;
  return d;
}

Aabb bounds(const Disk& d) {
  // Per axis, the extent of a circle of radius R with unit normal n is R sqrt(1 - n_a^2).
  Aabb b;
  for (int a = 0; a < 3; ++a) {
    const double e = d.radius * std::sqrt(std::max(0.0, 1 - d.n[a] * d.n[a]));
    const double pad = gamma(4) * (std::abs(d.center[a]) + d.radius);
    b.lo[a] = d.center[a] - e - pad;
    b.hi[a] = d.center[a] + e + pad;
  }
  if (d.canonical) b.lo.z = b.hi.z = d.center.z;
  return b;
}

bool intersect(const Disk& d, const Ray& ray, LocalHit& hit) {
  double t, x, y;
  if (!line_crossing(d, ray, t, x, y)) return false;
  if (!(t >= ray.tmin && t <= ray.tmax)) return false;
  hit = LocalHit{.t = t, .a = x, .b = y};
  return true;
}

void spans(const Disk& d, const Ray& ray, SpanList& out) {
  double t, x, y;
  if (!line_crossing(d, ray, t, x, y)) return;
  const LocalHit h{t, -1, 0, x, y};
  out.add(h, h);
}

SurfaceInfo surface(const Disk& d, const Ray& ray, const LocalHit& hit) {
  (void)ray;
  SurfaceInfo si;
  const double x = hit.a, y = hit.b;
  // Reprojection: center + x s + y t lies exactly on the plane for any real x, y. For the
  // canonical disk s and t are the axes, so z is exact and x, y carry no further rounding.
  if (d.canonical) {
    si.p = {x, y, d.center.z};
    si.p_error = {gamma(3) * std::abs(x), gamma(3) * std::abs(y), 0};
  } else {
    const Vec3 ts = x * d.s, tt = y * d.t;
    si.p = d.center + ts + tt;
    si.p_error = gamma(3) * (abs(d.center) + abs(ts) + abs(tt));
  }
  si.n = d.n;
  si.shading_n = d.n;
  const double r = std::sqrt(x * x + y * y);
  si.u = d.phi_max >= kTwoPi ? phi_of(x, y) / kTwoPi : phi_of(x, y) / d.phi_max;
  si.v = std::clamp((d.radius - r) / (d.radius - d.inner_radius), 0.0, 1.0);
  si.u = std::clamp(si.u, 0.0, 1.0);
  return si;
}

}  // namespace raycast
