#include "geometry/plane.h"

#include <cmath>
#include <stdexcept>

namespace raycast {

Plane make_plane(const Vec3& normal, const Vec3& point) {
  if (!is_finite(point)) throw std::invalid_argument("point must be finite");
  if (!is_finite(normal) || length_squared(normal) == 0)
    throw std::invalid_argument("normal must be finite and non-zero");
  Plane p;
  p.n = normalize(normal);
  p.point = point;
  p.offset = dot(p.n, point);
  make_frame(p.n, p.s, p.t);
  return p;
}

Aabb bounds(const Plane& p) {
  Aabb b = Aabb::everything();
  // An axis-aligned plane is thin along its normal axis.
  for (int a = 0; a < 3; ++a) {
    if (std::abs(p.n[a]) == 1) {
      // The half-space extends to -inf behind the normal; the surface sits at point[a].
      if (p.n[a] > 0)
        b.hi[a] = p.point[a];
      else
        b.lo[a] = p.point[a];
    }
  }
  return b;
}

bool intersect(const Plane& p, const Ray& ray, LocalHit& hit) {
  const double t = plane_crossing(p, ray);
  if (!plane_crossing_within(t, ray)) return false;
  hit = LocalHit{.t = t};
  return true;
}

void spans(const Plane& p, const Ray& ray, SpanList& out) {
  const double dn = dot(p.n, ray.d);
  const LocalHit lo{-kInfinity, -1, kNoSurface, 0, 0}, hi{kInfinity, -1, kNoSurface, 0, 0};
  const double t = (p.offset - dot(p.n, ray.o)) / dn;
  // Parallel, or so nearly that the crossing lies beyond every double (a subnormal d . n):
  // the whole line is in or out, with no surface crossing at +-inf.
  if (dn == 0 || !std::isfinite(t)) {
    if (dot(p.n, ray.o) <= p.offset) out.add(lo, hi);
    return;
  }
  const LocalHit at{t, -1, 0, 0, 0};
  if (dn > 0)
    out.add(lo, at);  // leaving the half-space
  else
    out.add(at, hi);
}

SurfaceInfo surface_geometry(const Plane& p, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 q = ray.at(hit.t);
  // Project onto the plane: the remaining error is a few ulps of the coordinates.
  q -= (dot(p.n, q) - p.offset) * p.n;
  si.p = q;
  si.p_error = gamma(6) * (abs(q) + abs(p.point));
  si.n = p.n;
  si.shading_n = p.n;
  return si;
}

SurfaceInfo surface(const Plane& p, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si = surface_geometry(p, ray, hit);
  const Vec3 rel = si.p - p.point;
  si.u = dot(rel, p.s);
  si.v = dot(rel, p.t);
  return si;
}

bool contains(const Plane& p, const Vec3& q) { return dot(p.n, q) <= p.offset; }

}  // namespace raycast
