#include "geometry/triangle.h"

#include <cmath>
#include <stdexcept>

#include "geometry/shape_error.h"
#include "math/float_error.h"

namespace raycast {

Triangle make_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  if (!is_finite(p0) || !is_finite(p1) || !is_finite(p2))
    throw std::invalid_argument("vertices must be finite");
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;
  const Vec3 c = cross(e1, e2);
  const double lc = length(c), scale = length(e1) * length(e2);
  if (!std::isfinite(lc) || !std::isfinite(scale))
    throw ShapeParameterError("vertices", "are too large");
  if (!(lc > kDegenerateSine * scale))
    throw ShapeParameterError("vertices", "are collinear or coincide (a degenerate triangle)");
  Triangle t;
  t.p0 = p0;
  t.p1 = p1;
  t.p2 = p2;
  t.n = c / lc;
  return t;
}

Triangle make_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& n0,
                       const Vec3& n1, const Vec3& n2) {
  Triangle t = make_triangle(p0, p1, p2);
  for (const Vec3* n : {&n0, &n1, &n2})
    if (!is_finite(*n) || length_squared(*n) == 0 || !std::isfinite(length_squared(*n)))
      throw std::invalid_argument("normals must be finite and non-zero");
  t.has_normals = true;
  t.n0 = normalize(n0);
  t.n1 = normalize(n1);
  t.n2 = normalize(n2);
  return t;
}

Aabb bounds(const Triangle& tri) {
  Aabb b;
  b.grow(tri.p0);
  b.grow(tri.p1);
  b.grow(tri.p2);
  return b;
}

namespace {

// Moller-Trumbore 1997: solves o + t d = p0 + b1 e1 + b2 e2 by Cramer's rule. Returns false for a
// ray parallel to the plane; the crossing of the whole line otherwise (edges inclusive).
bool line_crossing(const Triangle& tri, const Ray& ray, double& t, double& b1, double& b2) {
  const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
  const Vec3 pv = cross(ray.d, e2);
  const double det = dot(e1, pv);
  if (det == 0 || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  const Vec3 tv = ray.o - tri.p0;
  b1 = dot(tv, pv) * inv;
  if (!(b1 >= 0 && b1 <= 1)) return false;
  const Vec3 qv = cross(tv, e1);
  b2 = dot(ray.d, qv) * inv;
  if (!(b2 >= 0 && b1 + b2 <= 1)) return false;
  t = dot(e2, qv) * inv;
  return std::isfinite(t);
}

}  // namespace

bool intersect(const Triangle& tri, const Ray& ray, LocalHit& hit) {
  double t, b1, b2;
  if (!line_crossing(tri, ray, t, b1, b2)) return false;
  if (!(t >= ray.tmin && t <= ray.tmax)) return false;
  hit = LocalHit{.t = t, .a = b1, .b = b2};
  return true;
}

void spans(const Triangle& tri, const Ray& ray, SpanList& out) {
  double t, b1, b2;
  if (!line_crossing(tri, ray, t, b1, b2)) return;
  const LocalHit h{t, -1, 0, b1, b2};
  out.add(h, h);
}

SurfaceInfo surface(const Triangle& tri, const Ray& ray, const LocalHit& hit) {
  (void)ray;
  SurfaceInfo si;
  const double b1 = hit.a, b2 = hit.b;
  // The point from its barycentrics, p0 + b1 e1 + b2 e2: for any real b1, b2 the exact value lies
  // on the triangle's plane, so the error is only that of this evaluation (two subtractions for
  // the edges, two products, two sums: gamma(4) of the terms' magnitudes bounds it).
  const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
  const Vec3 t1 = b1 * e1, t2 = b2 * e2;
  si.p = tri.p0 + t1 + t2;
  si.p_error = gamma(4) * (abs(tri.p0) + abs(t1) + abs(t2) + b1 * abs(tri.p1) + b2 * abs(tri.p2));
  si.n = tri.n;
  si.shading_n = tri.n;
  if (tri.has_normals) {
    const Vec3 ns = (1 - b1 - b2) * tri.n0 + b1 * tri.n1 + b2 * tri.n2;
    const double l = length(ns);
    if (l > 0 && std::isfinite(l)) si.shading_n = dot(ns, tri.n) < 0 ? -ns / l : ns / l;
  }
  si.u = b1;
  si.v = b2;
  return si;
}

}  // namespace raycast
