#include "geometry/frustum.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/angles.h"
#include "geometry/quadric_line.h"

namespace raycast {

namespace {

Vec3 to_local(const Frustum& f, const Vec3& v) {
  return {dot(v, f.ex), dot(v, f.ey), dot(v, f.ez)};
}
Vec3 to_world(const Frustum& f, const Vec3& v) { return v.x * f.ex + v.y * f.ey + v.z * f.ez; }

// The ray in the frustum's local frame (the frame is orthonormal, so t is unchanged).
Ray local_ray(const Frustum& f, const Ray& ray) {
  if (!f.has_frame) return ray;
  return {to_local(f, ray.o - f.origin), to_local(f, ray.d), ray.tmin, ray.tmax};
}

// The side's g = x^2 + y^2 - r(z)^2 along the line: a2 t^2 + a1 t + a0.
void side_coefficients(const Frustum& f, const Vec3& o, const Vec3& d, double& a2, double& a1,
                       double& a0) {
  const double rho = f.r0 + f.k * (o.z - f.z0);  // r at the origin's height
  const double kd = f.k * d.z;
  a2 = d.x * d.x + d.y * d.y - kd * kd;
  a1 = 2 * (o.x * d.x + o.y * d.y - kd * rho);
  a0 = o.x * o.x + o.y * o.y - rho * rho;
}

// The line's interval between the planes z0 and z1 (ends carry the caps' parts).
bool z_interval(const Frustum& f, const Vec3& o, const Vec3& d, LineInterval& out) {
  if (d.z == 0) {
    if (o.z < f.z0 || o.z > f.z1) return false;
    out = {{-kInfinity, kNoSurface}, {kInfinity, kNoSurface}};
    return true;
  }
  const double inv = 1 / d.z;
  LineEnd a{(f.z0 - o.z) * inv, kFrustumCap0}, b{(f.z1 - o.z) * inv, kFrustumCap1};
  if (inv < 0) std::swap(a, b);
  out = {a, b};
  return true;
}

// Closed solid: the side's inside intervals clipped to the z range (at most 2, sorted).
int solid_intervals(const Frustum& f, const Ray& r, LineInterval iv[2]) {
  double a2, a1, a0;
  side_coefficients(f, r.o, r.d, a2, a1, a0);
  const int n = quadratic_inside(a2, a1, a0, kFrustumSide, iv);
  LineInterval zi;
  if (n == 0 || !z_interval(f, r.o, r.d, zi)) return 0;
  int k = 0;
  for (int i = 0; i < n; ++i)
    if (clip_interval(iv[i], zi, iv[k])) ++k;
  return k;
}

// Whether atan2(y, x) in [0, 2 pi) is <= phi_max, by half-plane tests instead of atan2: with
// c = (cos phi_max, sin phi_max), cross(c, p) = |p| sin(phi - phi_max).
bool in_phi(const Frustum& f, double x, double y) {
  if (f.phi_max >= kTwoPi) return true;
  const double cr = f.cos_phi_max * y - f.sin_phi_max * x;
  if (f.phi_max <= std::numbers::pi) return (y > 0 || (y == 0 && x >= 0)) && cr <= 0;
  return !(y < 0 && cr > 0);
}

// Open surface: every crossing of the kept side and caps, sorted by t (at most 4).
int open_crossings(const Frustum& f, const Ray& r, LineEnd out[4]) {
  int n = 0;
  double a2, a1, a0, t[2];
  side_coefficients(f, r.o, r.d, a2, a1, a0);
  int roots = 0;
  if (a2 == 0) {
    if (a1 != 0) {
      t[0] = -a0 / a1;
      roots = 1;
    }
  } else {
    roots = solve_quadratic(a2, a1, a0, t[0], t[1]);
    if (roots == 2 && t[0] == t[1]) roots = 1;
  }
  for (int i = 0; i < roots; ++i) {
    const Vec3 p = r.o + t[i] * r.d;
    if (std::isfinite(t[i]) && p.z >= f.z0 && p.z <= f.z1 && in_phi(f, p.x, p.y))
      out[n++] = {t[i], kFrustumSide};
  }
  if (f.capped && r.d.z != 0) {
    const double zs[2] = {f.z0, f.z1}, rs[2] = {f.r0, f.r1};
    for (int c = 0; c < 2; ++c) {
      if (rs[c] == 0) continue;
      const double tc = (zs[c] - r.o.z) / r.d.z;
      const double x = r.o.x + tc * r.d.x, y = r.o.y + tc * r.d.y;
      if (x * x + y * y <= rs[c] * rs[c] && in_phi(f, x, y))
        out[n++] = {tc, c == 0 ? kFrustumCap0 : kFrustumCap1};
    }
  }
  std::sort(out, out + n, [](const LineEnd& a, const LineEnd& b) { return a.t < b.t; });
  return n;
}

void validate(double z0, double z1, double r0, double r1, double phi_max_degrees) {
  if (!std::isfinite(z0) || !std::isfinite(z1) || !(z0 < z1) || !std::isfinite(z1 - z0))
    throw std::invalid_argument("the z range must be finite and non-empty");
  if (!(r0 >= 0) || !(r1 >= 0) || !std::isfinite(r0) || !std::isfinite(r1) || (r0 == 0 && r1 == 0))
    throw std::invalid_argument("radii must be >= 0, finite and not both 0");
  if (!(phi_max_degrees > 0 && phi_max_degrees <= 360))
    throw std::invalid_argument("phi_max must be in (0, 360]");
}

}  // namespace

bool Frustum::is_closed() const { return capped && phi_max >= kTwoPi; }

Frustum make_frustum(double z0, double z1, double r0, double r1, double phi_max_degrees,
                     bool capped) {
  validate(z0, z1, r0, r1, phi_max_degrees);
  Frustum f;
  f.z0 = z0;
  f.z1 = z1;
  f.r0 = r0;
  f.r1 = r1;
  f.k = (r1 - r0) / (z1 - z0);
  f.phi_max = phi_max_degrees >= 360 ? kTwoPi : phi_max_degrees * std::numbers::pi / 180;
  f.cos_phi_max = std::cos(f.phi_max);
  f.sin_phi_max = std::sin(f.phi_max);
  f.capped = capped;
  return f;
}

Frustum make_frustum(const Vec3& from, const Vec3& to, double r0, double r1, bool capped) {
  if (!is_finite(from) || !is_finite(to)) throw std::invalid_argument("from and to must be finite");
  const double len = length(to - from);
  if (!(len > 0) || !std::isfinite(len)) throw std::invalid_argument("from and to must differ");
  Frustum f = make_frustum(0, len, r0, r1, 360, capped);
  f.has_frame = true;
  f.origin = from;
  f.ez = (to - from) / len;
  make_frame(f.ez, f.ex, f.ey);
  return f;
}

Aabb frustum_bounds(const Frustum& f) {
  const double r = std::max(f.r0, f.r1);
  const Aabb local{{-r, -r, f.z0}, {r, r, f.z1}};
  if (!f.has_frame) return local;
  Aabb b;
  for (int i = 0; i < 8; ++i) {
    const Vec3 c{i & 1 ? local.hi.x : local.lo.x, i & 2 ? local.hi.y : local.lo.y,
                 i & 4 ? local.hi.z : local.lo.z};
    b.grow(f.origin + to_world(f, c));
  }
  // Widen by the rounding of the frame's products (a few ulps of the coordinates).
  const Vec3 pad = gamma(6) * (abs(b.lo) + abs(b.hi));
  return {b.lo - pad, b.hi + pad};
}

bool frustum_intersect(const Frustum& f, const Ray& ray, LocalHit& hit) {
  const Ray r = local_ray(f, ray);
  if (f.is_closed()) {
    LineInterval iv[2];
    const int n = solid_intervals(f, r, iv);
    LineEnd e;
    if (!first_end(iv, n, r.tmin, r.tmax, e)) return false;
    hit = LocalHit{.t = e.t, .part = e.part};
    return true;
  }
  LineEnd c[4];
  const int n = open_crossings(f, r, c);
  for (int i = 0; i < n; ++i) {
    if (c[i].t < r.tmin || c[i].t > r.tmax) continue;
    hit = LocalHit{.t = c[i].t, .part = c[i].part};
    return true;
  }
  return false;
}

int frustum_solid_intervals(const Frustum& f, const Ray& ray, LineInterval out[2]) {
  return solid_intervals(f, local_ray(f, ray), out);
}

void frustum_spans(const Frustum& f, const Ray& ray, SpanList& out) {
  if (f.is_closed()) {
    LineInterval iv[2];
    const int n = frustum_solid_intervals(f, ray, iv);
    for (int i = 0; i < n; ++i)
      out.add(LocalHit{.t = iv[i].in.t, .part = iv[i].in.part},
              LocalHit{.t = iv[i].out.t, .part = iv[i].out.part});
    return;
  }
  LineEnd c[4];
  const int n = open_crossings(f, local_ray(f, ray), c);
  for (int i = 0; i < n; ++i) {
    const LocalHit h{c[i].t, -1, c[i].part, 0, 0};
    out.add(h, h);
  }
}

namespace {

// frustum_surface, with (u, v) only when kUv (the geometry is the same either way).
template <bool kUv>
SurfaceInfo frustum_record(const Frustum& f, const Ray& ray, const LocalHit& hit) {
  const Ray r = local_ray(f, ray);
  Vec3 p = r.at(hit.t);
  Vec3 err = gamma(5) * (abs(r.o) + abs(hit.t * r.d));
  Vec3 n;
  if (hit.part == kFrustumCap0 || hit.part == kFrustumCap1) {
    // Snapped onto the cap; err.z stays the computed point's so spawned rays move off it.
    p.z = hit.part == kFrustumCap0 ? f.z0 : f.z1;
    n = {0, 0, hit.part == kFrustumCap0 ? -1.0 : 1.0};
  } else {
    const double rz = f.r0 + f.k * (p.z - f.z0);
    const double rxy = std::sqrt(p.x * p.x + p.y * p.y);
    if (f.k == 0 && rxy > 0) {
      // Cylinder: reproject onto the radius (pbrt-v4 6.8.5).
      p.x *= f.r0 / rxy;
      p.y *= f.r0 / rxy;
      err.x = gamma(3) * std::abs(p.x);
      err.y = gamma(3) * std::abs(p.y);
    }
    n = {p.x, p.y, -f.k * rz};
    const double ln = length(n);
    // At a cone's apex the gradient vanishes: the tip's own direction along the axis.
    n = ln > 0 ? n / ln : Vec3{0, 0, f.k < 0 ? 1.0 : -1.0};
    if (f.k != 0 && ln > 0) {
      // The root's own error: the distance to the surface to first order, |g| / |grad g| with
      // g = x^2 + y^2 - r(z)^2, plus g's rounding.
      const double g = p.x * p.x + p.y * p.y - rz * rz;
      const double dist = (std::abs(g) + gamma(6) * (p.x * p.x + p.y * p.y + rz * rz)) / (2 * ln);
      err += dist * abs(n);
    }
  }
  SurfaceInfo si;
  if constexpr (kUv) {
    si.u = phi_of(p.x, p.y) / f.phi_max;
    si.v = (p.z - f.z0) / (f.z1 - f.z0);
  }
  if (f.has_frame) {
    const Vec3 w = to_world(f, p);
    si.p = f.origin + w;
    si.p_error = abs(err.x * f.ex) + abs(err.y * f.ey) + abs(err.z * f.ez) +
                 gamma(4) * (abs(f.origin) + abs(p.x * f.ex) + abs(p.y * f.ey) + abs(p.z * f.ez));
    si.n = normalize(to_world(f, n));
  } else {
    si.p = p;
    si.p_error = err;
    si.n = n;
  }
  si.shading_n = si.n;
  return si;
}

}  // namespace

SurfaceInfo frustum_surface(const Frustum& f, const Ray& ray, const LocalHit& hit) {
  return frustum_record<true>(f, ray, hit);
}

SurfaceInfo frustum_surface_geometry(const Frustum& f, const Ray& ray, const LocalHit& hit) {
  return frustum_record<false>(f, ray, hit);
}

bool frustum_contains(const Frustum& f, const Vec3& p) {
  if (!f.is_closed()) return false;
  const Vec3 q = f.has_frame ? to_local(f, p - f.origin) : p;
  if (q.z < f.z0 || q.z > f.z1) return false;
  const double rz = f.r0 + f.k * (q.z - f.z0);
  return q.x * q.x + q.y * q.y <= rz * rz;
}

}  // namespace raycast
