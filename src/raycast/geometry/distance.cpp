#include "geometry/distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace raycast {

Vec3 closest_point(const Plane& s, const Vec3& p) { return p - dot(p - s.point, s.n) * s.n; }

bool closest_point(const Sphere& s, const Vec3& p, Vec3& q) {
  if (s.z_min > -s.radius || s.z_max < s.radius || s.phi_max < 2 * std::numbers::pi) return false;
  const Vec3 d = p - s.center;
  const double len = length(d);
  q = len > 0 ? s.center + (s.radius / len) * d : s.center + Vec3(s.radius, 0, 0);
  return true;
}

Vec3 closest_point(const Box& s, const Vec3& p) {
  const bool inside = p.x >= s.lo.x && p.x <= s.hi.x && p.y >= s.lo.y && p.y <= s.hi.y &&
                      p.z >= s.lo.z && p.z <= s.hi.z;
  if (!inside) return min(max(p, s.lo), s.hi);
  // Inside (or on the surface): the nearest face.
  Vec3 q = p;
  int axis = 0;
  bool high = false;
  double best = kInfinity;
  for (int a = 0; a < 3; ++a) {
    const double to_lo = p[a] - s.lo[a], to_hi = s.hi[a] - p[a];
    if (to_lo < best) best = to_lo, axis = a, high = false;
    if (to_hi < best) best = to_hi, axis = a, high = true;
  }
  q[axis] = high ? s.hi[axis] : s.lo[axis];
  return q;
}

namespace {

// Eberly 2013: the root s of sum (r_i z_i / (s + r_i))^2 - 1 = 0 by bisection on a bracket that
// the monotone function crosses once; stops when the midpoint no longer moves.
template <std::size_t N>
double ellipsoid_root(const std::array<double, N>& r, const std::array<double, N>& z, double g) {
  std::array<double, N> n;
  double len2 = 0;
  for (std::size_t i = 0; i < N; ++i) {
    n[i] = r[i] * z[i];
    len2 += n[i] * n[i];
  }
  double s0 = z[N - 1] - 1;
  double s1 = g < 0 ? 0 : std::sqrt(len2) - 1;
  double s = 0;
  for (int iter = 0; iter < 2200; ++iter) {
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1) break;
    double f = -1;
    for (std::size_t i = 0; i < N; ++i) {
      const double ratio = n[i] / (s + r[i]);
      f += ratio * ratio;
    }
    if (f > 0)
      s0 = s;
    else if (f < 0)
      s1 = s;
    else
      break;
  }
  return s;
}

// The nearest point of the ellipse x0^2/e0^2 + x1^2/e1^2 = 1 (e0 >= e1 > 0) to (y0, y1) with
// y0, y1 >= 0.
std::array<double, 2> ellipse_point(double e0, double e1, double y0, double y1) {
  if (y1 > 0) {
    if (y0 > 0) {
      const double z0 = y0 / e0, z1 = y1 / e1;
      const double g = z0 * z0 + z1 * z1 - 1;
      if (g == 0) return {y0, y1};
      const double r0 = (e0 / e1) * (e0 / e1);
      const double s = ellipsoid_root<2>({r0, 1}, {z0, z1}, g);
      return {r0 * y0 / (s + r0), y1 / (s + 1)};
    }
    return {0, e1};
  }
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double x = numer0 / denom0;
    return {e0 * x, e1 * std::sqrt(std::max(0.0, 1 - x * x))};
  }
  return {e0, 0};
}

// The same for the ellipsoid with e0 >= e1 >= e2 > 0 and y >= 0 componentwise.
std::array<double, 3> ellipsoid_point(const std::array<double, 3>& e,
                                      const std::array<double, 3>& y) {
  if (y[2] > 0) {
    if (y[1] > 0) {
      if (y[0] > 0) {
        const double z0 = y[0] / e[0], z1 = y[1] / e[1], z2 = y[2] / e[2];
        const double g = z0 * z0 + z1 * z1 + z2 * z2 - 1;
        if (g == 0) return y;
        const double r0 = (e[0] / e[2]) * (e[0] / e[2]), r1 = (e[1] / e[2]) * (e[1] / e[2]);
        const double s = ellipsoid_root<3>({r0, r1, 1}, {z0, z1, z2}, g);
        return {r0 * y[0] / (s + r0), r1 * y[1] / (s + r1), y[2] / (s + 1)};
      }
      const auto q = ellipse_point(e[1], e[2], y[1], y[2]);
      return {0, q[0], q[1]};
    }
    if (y[0] > 0) {
      const auto q = ellipse_point(e[0], e[2], y[0], y[2]);
      return {q[0], 0, q[1]};
    }
    return {0, 0, e[2]};
  }
  // y2 = 0: the nearest point may still leave the plane z = 0 (inside, near the long axes).
  const double d0 = e[0] * e[0] - e[2] * e[2], d1 = e[1] * e[1] - e[2] * e[2];
  const double n0 = e[0] * y[0], n1 = e[1] * y[1];
  if (n0 < d0 && n1 < d1) {
    const double x0 = n0 / d0, x1 = n1 / d1;
    const double discr = 1 - x0 * x0 - x1 * x1;
    if (discr > 0) return {e[0] * x0, e[1] * x1, e[2] * std::sqrt(discr)};
  }
  const auto q = ellipse_point(e[0], e[1], y[0], y[1]);
  return {q[0], q[1], 0};
}

// The nearest point to (x, y) on the segment from a to b in the plane.
std::array<double, 2> segment_point(double x, double y, double ax, double ay, double bx,
                                    double by) {
  const double dx = bx - ax, dy = by - ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return {ax + t * dx, ay + t * dy};
}

bool frustum_point(const Frustum& f, const Vec3& p_world, Vec3& q) {
  if (f.phi_max < 2 * std::numbers::pi) return false;
  const Vec3 d = p_world - f.origin;
  const Vec3 p = f.has_frame ? Vec3(dot(f.ex, d), dot(f.ey, d), dot(f.ez, d)) : p_world;
  const double rho = std::hypot(p.x, p.y);
  // The profile in the (rho, z) half-plane: the side, and the caps when capped.
  std::array<double, 2> best = segment_point(rho, p.z, f.r0, f.z0, f.r1, f.z1);
  auto dist2 = [&](const std::array<double, 2>& c) {
    return (c[0] - rho) * (c[0] - rho) + (c[1] - p.z) * (c[1] - p.z);
  };
  if (f.capped) {
    for (const auto& c : {segment_point(rho, p.z, 0, f.z0, f.r0, f.z0),
                          segment_point(rho, p.z, 0, f.z1, f.r1, f.z1)})
      if (dist2(c) < dist2(best)) best = c;
  }
  const double cx = rho > 0 ? p.x / rho : 1, cy = rho > 0 ? p.y / rho : 0;
  const Vec3 local(best[0] * cx, best[0] * cy, best[1]);
  q = f.has_frame ? f.origin + local.x * f.ex + local.y * f.ey + local.z * f.ez : local;
  return true;
}

}  // namespace

Vec3 closest_point(const Ellipsoid& s, const Vec3& p) {
  // Sort the axes by decreasing radius, fold p into the first octant, solve, unfold.
  const Vec3 d = p - s.center;
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return s.radii[a] > s.radii[b]; });
  std::array<double, 3> e, y;
  for (int i = 0; i < 3; ++i) {
    e[i] = s.radii[order[i]];
    y[i] = std::abs(d[order[i]]);
  }
  const std::array<double, 3> x = ellipsoid_point(e, y);
  Vec3 q;
  for (int i = 0; i < 3; ++i) q[order[i]] = std::copysign(x[i], d[order[i]]);
  return s.center + q;
}

bool closest_point(const Cylinder& s, const Vec3& p, Vec3& q) { return frustum_point(s.f, p, q); }
bool closest_point(const Cone& s, const Vec3& p, Vec3& q) { return frustum_point(s.f, p, q); }

Vec3 closest_point(const Torus& s, const Vec3& p) {
  const double R = s.major_radius, r = s.minor_radius;
  const double rho = std::hypot(p.x, p.y);
  const double cx = rho > 0 ? p.x / rho : 1, cy = rho > 0 ? p.y / rho : 0;
  // The profile circle about (R, 0) in the (rho, z) half-plane.
  const double dr = rho - R, dz = p.z;
  const double len = std::hypot(dr, dz);
  double qr = len > 0 ? R + r * dr / len : R + r, qz = len > 0 ? r * dz / len : 0;
  if (qr < 0) {
    // Spindle torus: the nearest point of the outer arc is one of its ends on the axis.
    const double h = std::sqrt(std::max(0.0, r * r - R * R));
    qr = 0;
    qz = p.z >= 0 ? h : -h;
  }
  return {qr * cx, qr * cy, qz};
}

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

}  // namespace raycast
