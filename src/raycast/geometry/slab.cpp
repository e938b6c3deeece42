#include "geometry/slab.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace raycast {

namespace {

struct SlabCrossings {
  double t_in, t_out;
  int part_in, part_out;
};

// The line's interval inside the slab and the planes it enters and leaves through: one division
// for the first plane, one multiply-add for the second. False when the line is parallel to the
// planes (it is then wholly inside or outside and crosses nothing).
bool slab_crossings(const Slab& s, const Ray& ray, SlabCrossings& c) {
  const double nd = dot(s.n, ray.d);
  if (nd == 0) return false;
  const double inv = 1 / nd;
  const double t0 = (s.d0 - dot(s.n, ray.o)) * inv;
  const double t1 = std::fma(s.width, inv, t0);
  if (!std::isfinite(t0) || !std::isfinite(t1)) return false;
  c = inv > 0 ? SlabCrossings{t0, t1, 0, 1} : SlabCrossings{t1, t0, 1, 0};
  return true;
}

}  // namespace

Slab make_slab(const Vec3& n, double d0, double d1) {
  if (!is_finite(n) || length_squared(n) == 0 || !std::isfinite(length_squared(n)))
    throw std::invalid_argument("normal must be finite and non-zero");
  if (!std::isfinite(d0) || !std::isfinite(d1) || !(d0 < d1) || !std::isfinite(d1 - d0))
    throw std::invalid_argument("offsets must be finite with d0 < d1");
  Slab s;
  s.n = n;
  s.d0 = d0;
  s.d1 = d1;
  s.width = d1 - d0;
  s.unit_n = normalize(n);
  return s;
}

Aabb bounds(const Slab& s) {
  Aabb b = Aabb::everything();
  // Bounded only along an axis the normal is parallel to.
  for (int a = 0; a < 3; ++a) {
    if (s.n[(a + 1) % 3] == 0 && s.n[(a + 2) % 3] == 0) {
      double lo = s.d0 / s.n[a], hi = s.d1 / s.n[a];
      if (lo > hi) std::swap(lo, hi);
      b.lo[a] = lo - gamma(2) * std::abs(lo);
      b.hi[a] = hi + gamma(2) * std::abs(hi);
    }
  }
  return b;
}

bool intersect(const Slab& s, const Ray& ray, LocalHit& hit) {
  SlabCrossings c;
  if (!slab_crossings(s, ray, c)) return false;
  if (c.t_in >= ray.tmin && c.t_in <= ray.tmax) {
    hit = LocalHit{.t = c.t_in, .part = c.part_in};
    return true;
  }
  if (c.t_out >= ray.tmin && c.t_out <= ray.tmax) {
    hit = LocalHit{.t = c.t_out, .part = c.part_out};
    return true;
  }
  return false;
}

void spans(const Slab& s, const Ray& ray, SpanList& out) {
  SlabCrossings c;
  if (slab_crossings(s, ray, c)) {
    out.add(LocalHit{.t = c.t_in, .part = c.part_in}, LocalHit{.t = c.t_out, .part = c.part_out});
    return;
  }
  const double x = dot(s.n, ray.o);
  if (s.d0 <= x && x <= s.d1)  // parallel (or overflowing): wholly inside or outside
    out.add(LocalHit{.t = -kInfinity, .part = kNoSurface},
            LocalHit{.t = kInfinity, .part = kNoSurface});
}

SurfaceInfo surface(const Slab& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 q = ray.at(hit.t);
  const double d = hit.part == 0 ? s.d0 : s.d1;
  // Project onto the plane; the rest is a few ulps of the coordinates.
  q -= ((dot(s.n, q) - d) / length_squared(s.n)) * s.n;
  si.p = q;
  si.p_error = gamma(8) * abs(q) + (gamma(4) * std::abs(d) / length(s.n)) * abs(s.unit_n);
  si.n = hit.part == 0 ? -s.unit_n : s.unit_n;
  si.shading_n = si.n;
  return si;
}

}  // namespace raycast
