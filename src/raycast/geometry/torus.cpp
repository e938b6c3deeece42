#include "geometry/torus.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/angles.h"
#include "math/polynomial_solver.h"

namespace raycast {

namespace {

// Slack on the bounding sphere so that rounding in the chord never drops a root at its end.
constexpr double kChordSlack = 1e-9;

double angle_0_2pi(double y, double x) {
  const double a = std::atan2(y, x);
  return a < 0 ? a + kTwoPi : a;
}

// The crossings of the line as u values of the quartic within [u_lo, u_hi], increasing.
int roots_u(const TorusQuartic& q, double u_lo, double u_hi, double* u) {
  return find_real_roots(q.p, std::max(u_lo, -q.h), std::min(u_hi, q.h), u);
}

// Margin of chord_misses, relative to the torus's size: far above the rounding of its few
// operations and above how far the rounded quartic's roots (even a tangent's double root, off by
// about the square root of the coefficients' rounding) can lie outside the torus.
constexpr double kMissMargin = 1e-6;

// Whether the line's part c + u e, u in [a, b], certainly misses the solid, by two shapes that
// contain it: the slab |z| <= r, and the outside of the hole's cylinder rho >= R - r (every
// point has (rho - R)^2 + z^2 <= r^2). The part clipped to the slab must lie inside the cylinder
// at both ends: rho^2 is convex in u, so then it does throughout. Exact up to kMissMargin: it
// only ever skips the solver for lines that it would find no root on.
bool chord_misses(const Torus& s, const TorusQuartic& q, double a, double b) {
  const double size = s.major_radius + s.minor_radius;
  const double zmax = s.minor_radius + kMissMargin * size;
  const double za = q.c.z + a * q.e.z, zb = q.c.z + b * q.e.z;
  if ((za > zmax && zb > zmax) || (za < -zmax && zb < -zmax)) return true;
  const double hole = s.major_radius - s.minor_radius - kMissMargin * size;
  if (!(hole > 0)) return false;  // no hole (a horn or spindle torus)
  if (q.e.z != 0) {
    double u1 = (-zmax - q.c.z) / q.e.z, u2 = (zmax - q.c.z) / q.e.z;
    if (u1 > u2) std::swap(u1, u2);
    a = std::max(a, u1);
    b = std::min(b, u2);
    if (!(a <= b)) return true;  // (rounding aside, the ends' test above has caught this)
  }
  auto rho2 = [&](double u) {
    const double x = q.c.x + u * q.e.x, y = q.c.y + u * q.e.y;
    return x * x + y * y;
  };
  return rho2(a) < hole * hole && rho2(b) < hole * hole;
}

}  // namespace

Torus make_torus(double major_radius, double minor_radius) {
  if (!(major_radius > 0) || !std::isfinite(major_radius))
    throw std::invalid_argument("major_radius must be > 0 and finite");
  if (!(minor_radius > 0) || !std::isfinite(minor_radius))
    throw std::invalid_argument("minor_radius must be > 0 and finite");
  return Torus{major_radius, minor_radius};
}

Aabb bounds(const Torus& s) {
  const double e = s.major_radius + s.minor_radius;
  return {{-e, -e, -s.minor_radius}, {e, e, s.minor_radius}};
}

double torus_function(const Torus& s, const Vec3& p) {
  const double R2 = s.major_radius * s.major_radius;
  const double a = dot(p, p) + R2 - s.minor_radius * s.minor_radius;
  return a * a - 4 * R2 * (p.x * p.x + p.y * p.y);
}

bool torus_quartic(const Torus& s, const Ray& ray, TorusQuartic& q) {
  const double len2 = dot(ray.d, ray.d);
  const double len = std::sqrt(len2);
  q.inv_len = 1 / len;
  q.t_c = -dot(ray.o, ray.d) / len2;
  const Vec3 c = ray.o + q.t_c * ray.d;  // nearest point to the centre
  const Vec3 e = ray.d * q.inv_len;
  q.c = c;
  q.e = e;
  const double outer = s.major_radius + s.minor_radius;
  const double cc = dot(c, c);
  const double h2 = outer * outer - cc;
  if (!(h2 >= -kChordSlack * outer * outer)) return false;
  q.h = std::sqrt(std::max(h2, 0.0)) * (1 + kChordSlack) + kChordSlack * outer;
  // |c + u e|^2 = ee u^2 + 2 b u + cc, and f = A^2 - 4 R^2 rho^2 with A = |p|^2 + R^2 - r^2.
  const double R2 = s.major_radius * s.major_radius;
  const double ee = dot(e, e);
  const double b = dot(c, e);
  const double G = cc + R2 - s.minor_radius * s.minor_radius;
  const double exy = e.x * e.x + e.y * e.y;
  const double cexy = c.x * e.x + c.y * e.y;
  const double cxy = c.x * c.x + c.y * c.y;
  q.p.degree = 4;
  q.p.c[4] = ee * ee;
  q.p.c[3] = 4 * ee * b;
  q.p.c[2] = 4 * b * b + 2 * ee * G - 4 * R2 * exy;
  q.p.c[1] = 4 * b * G - 8 * R2 * cexy;
  q.p.c[0] = G * G - 4 * R2 * cxy;
  return true;
}

bool intersect(const Torus& s, const Ray& ray, LocalHit& hit) {
  TorusQuartic q;
  if (!torus_quartic(s, ray, q)) return false;
  const double len = 1 / q.inv_len;
  // The u range of [tmin, tmax], widened by a rounding margin; t is re-checked exactly below.
  const double margin = gamma(4) * (std::abs(q.t_c) * len + q.h);
  const double u_lo = (ray.tmin - q.t_c) * len - margin, u_hi = (ray.tmax - q.t_c) * len + margin;
  // Only the nearest crossing in [tmin, tmax] is wanted: the isolation stops there.
  const auto in_range = [&](double u) {
    const double t = q.t_c + u * q.inv_len;
    return t >= ray.tmin && t <= ray.tmax;
  };
  const double lo = std::max(u_lo, -q.h), hi = std::min(u_hi, q.h);
  if (lo <= hi && chord_misses(s, q, lo, hi)) return false;
  double u;
  if (!find_first_real_root(q.p, lo, hi, in_range, u)) return false;
  hit = LocalHit{.t = q.t_c + u * q.inv_len};
  return true;
}

void spans(const Torus& s, const Ray& ray, SpanList& out) {
  TorusQuartic q;
  if (!torus_quartic(s, ray, q)) return;
  double u[4];
  const int n = roots_u(q, -q.h, q.h, u);
  // Inside between consecutive crossings where the quartic is negative; a tangent touch (a
  // double root reported once) has the same sign on both sides and opens no span.
  for (int i = 0; i + 1 < n; ++i) {
    if (!(evaluate(q.p, 0.5 * (u[i] + u[i + 1])) < 0)) continue;
    const LocalHit in{q.t_c + u[i] * q.inv_len, -1, 0, 0, 0};
    const LocalHit out_hit{q.t_c + u[i + 1] * q.inv_len, -1, 0, 0, 0};
    out.add(in, out_hit);
  }
}

SurfaceInfo surface_geometry(const Torus& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  const double R2 = s.major_radius * s.major_radius;
  // The gradient points out of the solid (towards increasing f).
  const double a = dot(p, p) + R2 - s.minor_radius * s.minor_radius;
  Vec3 g = 4 * a * p - 8 * R2 * Vec3{p.x, p.y, 0};
  const double gl = length(g);
  if (gl > 0 && std::isfinite(gl)) {
    // One Newton step along the gradient puts p back on the surface.
    p -= (torus_function(s, p) / (gl * gl)) * g;
    g = 4 * (dot(p, p) + R2 - s.minor_radius * s.minor_radius) * p - 8 * R2 * Vec3{p.x, p.y, 0};
    si.n = normalize(g);
  } else {
    si.n = -normalize(ray.d);
  }
  si.shading_n = si.n;
  si.p = p;
  // The remaining error of p is a few ulps of the torus's size.
  const double size = s.major_radius + s.minor_radius;
  si.p_error = gamma(16) * (abs(p) + Vec3{size, size, size});
  return si;
}

SurfaceInfo surface(const Torus& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si = surface_geometry(s, ray, hit);
  const Vec3& p = si.p;
  const double rho = std::sqrt(p.x * p.x + p.y * p.y);
  si.u = angle_0_2pi(p.y, p.x) / kTwoPi;
  si.v = angle_0_2pi(p.z, rho - s.major_radius) / kTwoPi;
  return si;
}

bool contains(const Torus& s, const Vec3& p) { return torus_function(s, p) <= 0; }

}  // namespace raycast
