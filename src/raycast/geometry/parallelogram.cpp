#include "geometry/parallelogram.h"

#include <cmath>
#include <stdexcept>

#include "geometry/shape_error.h"
#include "geometry/triangle.h"
#include "math/float_error.h"

namespace raycast {

Parallelogram make_parallelogram(const Vec3& origin, const Vec3& u, const Vec3& v) {
  if (!is_finite(origin)) throw std::invalid_argument("origin must be finite");
  if (!is_finite(u) || !is_finite(v)) throw std::invalid_argument("u and v must be finite");
  const Vec3 w = cross(u, v);
  const double lw = length(w), scale = length(u) * length(v);
  if (!std::isfinite(lw) || !std::isfinite(scale))
    throw ShapeParameterError("v", "and u are too large");
  if (!(lw > kDegenerateSine * scale))
    throw ShapeParameterError("v", "and u must be non-zero and not parallel");
  Parallelogram q;
  q.origin = origin;
  q.u = u;
  q.v = v;
  q.n = w / lw;
  return q;
}

Aabb bounds(const Parallelogram& q) {
  Aabb b;
  for (const Vec3& c : {q.origin, q.origin + q.u, q.origin + q.v, q.origin + q.u + q.v}) b.grow(c);
  return b;
}

namespace {

// The same Cramer's-rule solve as Moller-Trumbore 1997, with the barycentric test replaced by
// the parallelogram's 0 <= a, b <= 1 (edges inclusive). False for a ray parallel to the plane.
bool line_crossing(const Parallelogram& q, const Ray& ray, double& t, double& a, double& b) {
  const Vec3 pv = cross(ray.d, q.v);
  const double det = dot(q.u, pv);
  if (det == 0 || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  const Vec3 tv = ray.o - q.origin;
  a = dot(tv, pv) * inv;
  if (!(a >= 0 && a <= 1)) return false;
  const Vec3 qv = cross(tv, q.u);
  b = dot(ray.d, qv) * inv;
  if (!(b >= 0 && b <= 1)) return false;
  t = dot(q.v, qv) * inv;
  return std::isfinite(t);
}

}  // namespace

bool intersect(const Parallelogram& q, const Ray& ray, LocalHit& hit) {
  double t, a, b;
  if (!line_crossing(q, ray, t, a, b)) return false;
  if (!(t >= ray.tmin && t <= ray.tmax)) return false;
  hit = LocalHit{.t = t, .a = a, .b = b};
  return true;
}

void spans(const Parallelogram& q, const Ray& ray, SpanList& out) {
  double t, a, b;
  if (!line_crossing(q, ray, t, a, b)) return;
  const LocalHit h{t, -1, 0, a, b};
  out.add(h, h);
}

SurfaceInfo surface(const Parallelogram& q, const Ray& ray, const LocalHit& hit) {
  (void)ray;
  SurfaceInfo si;
  // Reprojection onto the surface: origin + a u + b v lies exactly on the plane for any real a, b,
  // so the error is that of this evaluation (two products, two sums: gamma(3)).
  const Vec3 ta = hit.a * q.u, tb = hit.b * q.v;
  si.p = q.origin + ta + tb;
  si.p_error = gamma(3) * (abs(q.origin) + abs(ta) + abs(tb));
  si.n = q.n;
  si.shading_n = q.n;
  si.u = hit.a;
  si.v = hit.b;
  return si;
}

}  // namespace raycast
