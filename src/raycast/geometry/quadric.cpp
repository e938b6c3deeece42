#include "geometry/quadric.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/quadric_line.h"

namespace raycast {

namespace {

// Parts of a quadric's hits: the curved surface, then the box faces 1 + 2 axis + (max side).
constexpr int kCurved = 0;
int face_part(int axis, bool hi) { return 1 + 2 * axis + (hi ? 1 : 0); }

// f along the line: f(o + t d) = a2 t^2 + a1 t + a0, with a1 = grad f(o) . d.
void line_coefficients(const QuadricCoefficients& c, const Vec3& o, const Vec3& d, double& a2,
                       double& a1, double& a0) {
  a2 = c[0] * d.x * d.x + c[1] * d.y * d.y + c[2] * d.z * d.z + c[3] * d.x * d.y +
       c[4] * d.x * d.z + c[5] * d.y * d.z;
  a1 = dot(quadric_gradient(c, o), d);
  a0 = quadric_value(c, o);
}

// The whole line's interval inside the box, with the faces it enters and leaves through.
bool box_interval(const Aabb& b, const Vec3& o, const Vec3& d, LineInterval& out) {
  out = {{-kInfinity, kNoSurface}, {kInfinity, kNoSurface}};
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (o[a] < b.lo[a] || o[a] > b.hi[a]) return false;
      continue;
    }
    const double inv = 1 / d[a];
    LineEnd near{(b.lo[a] - o[a]) * inv, face_part(a, false)};
    LineEnd far{(b.hi[a] - o[a]) * inv, face_part(a, true)};
    if (inv < 0) std::swap(near, far);
    if (near.t > out.in.t) out.in = near;
    if (far.t < out.out.t) out.out = far;
  }
  return out.in.t <= out.out.t;
}

// The intervals of the whole line inside the closed solid (at most 2, sorted).
int solid_intervals(const Quadric& q, const Ray& ray, LineInterval iv[2]) {
  double a2, a1, a0;
  line_coefficients(q.c, ray.o, ray.d, a2, a1, a0);
  int n = quadratic_inside(a2, a1, a0, kCurved, iv);
  if (!q.box || n == 0) return n;
  LineInterval b;
  if (!box_interval(*q.box, ray.o, ray.d, b)) return 0;
  int k = 0;
  for (int i = 0; i < n; ++i)
    if (clip_interval(iv[i], b, iv[k])) ++k;
  return k;
}

// The curved surface's crossings kept by an open quadric (inside the box, if any), sorted.
int open_crossings(const Quadric& q, const Ray& ray, double t[2]) {
  double a2, a1, a0;
  line_coefficients(q.c, ray.o, ray.d, a2, a1, a0);
  int n = 0;
  if (a2 == 0) {
    if (a1 == 0) return 0;
    t[0] = t[1] = -a0 / a1;
    n = std::isfinite(t[0]) ? 1 : 0;
  } else {
    if (solve_quadratic(a2, a1, a0, t[0], t[1]) == 0) return 0;
    n = t[1] == t[0] ? 1 : 2;
  }
  LineInterval b{{-kInfinity, kNoSurface}, {kInfinity, kNoSurface}};
  if (q.box && !box_interval(*q.box, ray.o, ray.d, b)) return 0;
  int k = 0;
  for (int i = 0; i < n; ++i)
    if (std::isfinite(t[i]) && t[i] >= b.in.t && t[i] <= b.out.t) t[k++] = t[i];
  return k;
}

// Sylvester's criterion on the quadratic part: f is an ellipsoid's function (up to scale) when
// its 3x3 matrix M is positive definite; then its solid is bounded.
bool ellipsoid_hull(const QuadricCoefficients& c, Aabb& hull) {
  const double m00 = c[0], m11 = c[1], m22 = c[2], m01 = c[3] / 2, m02 = c[4] / 2, m12 = c[5] / 2;
  // Cofactors of M (M is symmetric, so its inverse is cofactor / det).
  const double c00 = m11 * m22 - m12 * m12, c11 = m00 * m22 - m02 * m02,
               c22 = m00 * m11 - m01 * m01;
  const double c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11,
               c12 = m01 * m02 - m00 * m12;
  const double det = m00 * c00 + m01 * c01 + m02 * c02;
  if (!(m00 > 0 && c22 > 0 && det > 0)) return false;
  const Vec3 b{c[6] / 2, c[7] / 2, c[8] / 2};
  // Centre -M^-1 b; the solid is (x - ctr)^T M (x - ctr) < k with k = b^T M^-1 b - J.
  const Vec3 mb{(c00 * b.x + c01 * b.y + c02 * b.z) / det,
                (c01 * b.x + c11 * b.y + c12 * b.z) / det,
                (c02 * b.x + c12 * b.y + c22 * b.z) / det};
  const double k = dot(b, mb) - c[9];
  if (!(k > 0)) throw std::invalid_argument("the quadric's inside (f < 0) is empty");
  // Half-extent along axis i: sqrt(k (M^-1)_ii), widened by a relative margin for rounding.
  constexpr double kMargin = 1e-9;
  const Vec3 half{std::sqrt(k * c00 / det), std::sqrt(k * c11 / det), std::sqrt(k * c22 / det)};
  const Vec3 ctr = -mb;
  const Vec3 pad = (1 + kMargin) * half + kMargin * abs(ctr);
  hull = {ctr - pad, ctr + pad};
  return is_finite(hull.lo) && is_finite(hull.hi);
}

}  // namespace

double quadric_value(const QuadricCoefficients& c, const Vec3& p) {
  return p.x * (c[0] * p.x + c[3] * p.y + c[4] * p.z + c[6]) +
         p.y * (c[1] * p.y + c[5] * p.z + c[7]) + p.z * (c[2] * p.z + c[8]) + c[9];
}

Vec3 quadric_gradient(const QuadricCoefficients& c, const Vec3& p) {
  return {2 * c[0] * p.x + c[3] * p.y + c[4] * p.z + c[6],
          c[3] * p.x + 2 * c[1] * p.y + c[5] * p.z + c[7],
          c[4] * p.x + c[5] * p.y + 2 * c[2] * p.z + c[8]};
}

Quadric make_quadric(const QuadricCoefficients& c, const std::optional<Aabb>& box, bool open) {
  bool any = false;
  for (int i = 0; i < 10; ++i) {
    if (!std::isfinite(c[i])) throw std::invalid_argument("coefficients must be finite");
    if (i < 9 && c[i] != 0) any = true;
  }
  if (!any) throw std::invalid_argument("coefficients A..I must not all be 0");
  Quadric q;
  q.c = c;
  q.open = open;
  if (box) {
    if (!is_finite(box->lo) || !is_finite(box->hi))
      throw std::invalid_argument("bounds must be finite");
    if (!(box->lo.x < box->hi.x && box->lo.y < box->hi.y && box->lo.z < box->hi.z))
      throw std::invalid_argument("bounds.min must be < bounds.max on every axis");
    q.box = box;
    q.hull = *box;
  }
  Aabb hull;
  if (ellipsoid_hull(c, hull)) q.hull = overlap(q.hull, hull);
  if (q.hull.is_empty()) throw std::invalid_argument("bounds do not meet the quadric's inside");
  return q;
}

QuadricCoefficients quadric_from_matrix(const Mat4& m) {
  double scale = 0;
  for (const auto& row : m.m)
    for (double v : row) {
      if (!std::isfinite(v)) throw std::invalid_argument("matrix must be finite");
      scale = std::max(scale, std::abs(v));
    }
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (std::abs(m.m[i][j] - m.m[j][i]) > kQuadricSymmetryTolerance * scale)
        throw std::invalid_argument("matrix must be symmetric");
  const auto& q = m.m;
  // Off-diagonal pairs enter twice in x^T Q x; average them so tiny asymmetries cancel.
  return {
      q[0][0],           q[1][1],           q[2][2],           q[0][1] + q[1][0], q[0][2] + q[2][0],
      q[1][2] + q[2][1], q[0][3] + q[3][0], q[1][3] + q[3][1], q[2][3] + q[3][2], q[3][3]};
}

QuadricCoefficients quadric_of_kind(QuadricKind kind, double a, double b, double c) {
  for (double v : {a, b, c})
    if (!(v > 0) || !std::isfinite(v))
      throw std::invalid_argument("a, b and c must be > 0 and finite");
  const double ia = 1 / (a * a), ib = 1 / (b * b), ic = 1 / (c * c);
  switch (kind) {
    case QuadricKind::kEllipsoid:
      return {ia, ib, ic, 0, 0, 0, 0, 0, 0, -1};
    case QuadricKind::kParaboloid:
      return {ia, ib, 0, 0, 0, 0, 0, 0, -1 / c, 0};
    case QuadricKind::kHyperboloid1:
      return {ia, ib, -ic, 0, 0, 0, 0, 0, 0, -1};
    case QuadricKind::kHyperboloid2:
      return {ia, ib, -ic, 0, 0, 0, 0, 0, 0, 1};
    case QuadricKind::kCone:
      return {ia, ib, -ic, 0, 0, 0, 0, 0, 0, 0};
    case QuadricKind::kCylinder:
      return {ia, ib, 0, 0, 0, 0, 0, 0, 0, -1};
  }
  throw std::invalid_argument("unknown quadric kind");
}

Aabb bounds(const Quadric& q) { return q.hull; }

bool intersect(const Quadric& q, const Ray& ray, LocalHit& hit) {
  if (q.open) {
    double t[2];
    const int n = open_crossings(q, ray, t);
    for (int i = 0; i < n; ++i) {
      if (t[i] < ray.tmin || t[i] > ray.tmax) continue;
      hit = LocalHit{.t = t[i], .part = kCurved};
      return true;
    }
    return false;
  }
  LineInterval iv[2];
  const int n = solid_intervals(q, ray, iv);
  LineEnd e;
  if (!first_end(iv, n, ray.tmin, ray.tmax, e)) return false;
  hit = LocalHit{.t = e.t, .part = e.part};
  return true;
}

void spans(const Quadric& q, const Ray& ray, SpanList& out) {
  if (q.open) {
    double t[2];
    const int n = open_crossings(q, ray, t);
    for (int i = 0; i < n; ++i) {
      const LocalHit h{t[i], -1, kCurved, 0, 0};
      out.add(h, h);
    }
    return;
  }
  LineInterval iv[2];
  const int n = solid_intervals(q, ray, iv);
  for (int i = 0; i < n; ++i)
    out.add(LocalHit{.t = iv[i].in.t, .part = iv[i].in.part},
            LocalHit{.t = iv[i].out.t, .part = iv[i].out.part});
}

SurfaceInfo surface(const Quadric& q, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  si.p_error = gamma(3) * (abs(ray.o) + abs(hit.t * ray.d));
  if (hit.part > kCurved && q.box) {
    // A box face: snap the coordinate onto the face exactly, but keep the computed point's
    // error bound on that axis so that spawned rays move off the face (a zero offset re-hits).
    const int axis = (hit.part - 1) / 2;
    const bool hi = (hit.part - 1) % 2 == 1;
    p[axis] = hi ? q.box->hi[axis] : q.box->lo[axis];
    si.n = Vec3{};
    si.n[axis] = hi ? 1 : -1;
  } else {
    const Vec3 g = quadric_gradient(q.c, p);
    const double lg = length(g);
    si.n = lg > 0 && std::isfinite(lg) ? g / lg : -normalize(ray.d);
    // Distance to the surface to first order, |f| / |grad f|, with f's own rounding bound.
    if (lg > 0 && std::isfinite(lg)) {
      const Vec3 ap = abs(p);
      const QuadricCoefficients& c = q.c;
      const double f_abs = std::abs(c[0]) * ap.x * ap.x + std::abs(c[1]) * ap.y * ap.y +
                           std::abs(c[2]) * ap.z * ap.z + std::abs(c[3]) * ap.x * ap.y +
                           std::abs(c[4]) * ap.x * ap.z + std::abs(c[5]) * ap.y * ap.z +
                           std::abs(c[6]) * ap.x + std::abs(c[7]) * ap.y + std::abs(c[8]) * ap.z +
                           std::abs(c[9]);
      const double dist = (std::abs(quadric_value(c, p)) + gamma(10) * f_abs) / lg;
      si.p_error += dist * abs(si.n);
    }
  }
  si.p = p;
  si.shading_n = si.n;
  return si;
}

bool contains(const Quadric& q, const Vec3& p) {
  if (q.open) return false;
  if (q.box && !q.box->contains(p)) return false;
  return quadric_value(q.c, p) < 0;
}

}  // namespace raycast
