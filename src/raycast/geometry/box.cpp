#include "geometry/box.h"

#include <cmath>
#include <stdexcept>

#include "geometry/shape_error.h"
#include "math/float_error.h"

namespace raycast {

Box make_box(const Vec3& lo, const Vec3& hi) {
  if (!is_finite(lo)) throw std::invalid_argument("min must be finite");
  if (!is_finite(hi)) throw std::invalid_argument("max must be finite");
  for (int a = 0; a < 3; ++a)
    if (!(lo[a] < hi[a]))
      throw ShapeParameterError("max", std::string("must be > min on every axis, got ") +
                                           format_parameter(hi[a]) +
                                           " <= " + format_parameter(lo[a]) + " on " + "xyz"[a]);
  return Box{lo, hi};
}

bool box_line_interval(const Box& b, const Ray& ray, double& t0, int& face0, double& t1,
                       int& face1) {
  // Slab method (Kay and Kajiya 1986) with exact divisions: each face's t is one correctly
  // rounded subtraction and one division, so hand-computed rays come out to the last ulp.
  t0 = -kInfinity;
  t1 = kInfinity;
  face0 = face1 = kNoSurface;
  for (int a = 0; a < 3; ++a) {
    const double o = ray.o[a], d = ray.d[a];
    if (d == 0) {
      if (o < b.lo[a] || o > b.hi[a]) return false;
      continue;
    }
    double near = (b.lo[a] - o) / d, far = (b.hi[a] - o) / d;
    int near_face = 2 * a, far_face = 2 * a + 1;
    if (d < 0) {
      std::swap(near, far);
      std::swap(near_face, far_face);
    }
    if (near > t0) {
      t0 = near;
      face0 = near_face;
    }
    if (far < t1) {
      t1 = far;
      face1 = far_face;
    }
  }
  // A valid ray (non-zero direction) constrains at least one axis and so sets both faces.
  return face0 != kNoSurface && t0 <= t1;
}

Aabb bounds(const Box& b) { return {b.lo, b.hi}; }

bool intersect(const Box& b, const Ray& ray, LocalHit& hit) {
  double t0, t1;
  int f0, f1;
  if (!box_line_interval(b, ray, t0, f0, t1, f1)) return false;
  if (t0 >= ray.tmin && t0 <= ray.tmax) {
    hit = LocalHit{.t = t0, .part = f0};
    return true;
  }
  if (t1 >= ray.tmin && t1 <= ray.tmax) {
    hit = LocalHit{.t = t1, .part = f1};
    return true;
  }
  return false;
}

void spans(const Box& b, const Ray& ray, SpanList& out) {
  double t0, t1;
  int f0, f1;
  if (!box_line_interval(b, ray, t0, f0, t1, f1)) return;
  out.add(LocalHit{.t = t0, .part = f0}, LocalHit{.t = t1, .part = f1});
}

SurfaceInfo surface_geometry(const Box& b, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  const int face = hit.part >= 0 && hit.part < 6 ? hit.part : 0;
  const int a = face / 2;
  const bool at_hi = face % 2 == 1;
  Vec3 p = ray.at(hit.t);
  // The computed t carries two roundings (subtraction, division); o + t d adds two more. The face
  // coordinate is snapped onto the face plane, so it is exact.
  si.p_error = gamma(5) * (abs(ray.o) + abs(hit.t * ray.d));
  p[a] = at_hi ? b.hi[a] : b.lo[a];
  si.p_error[a] = 0;
  // The true point lies on the face rectangle: clamping onto it only removes error. Inline:
  // std::fmax then std::fmin were two library calls per coordinate. The same values (a NaN
  // coordinate gives the lower bound, as fmax does); on a tie of zeros the point keeps its own
  // sign, where fmax / fmin leave the sign unspecified (GCC may swap their operands).
  for (int c : {(a + 1) % 3, (a + 2) % 3}) {
    const double above = p[c] >= b.lo[c] ? p[c] : b.lo[c];
    p[c] = above <= b.hi[c] ? above : b.hi[c];
  }
  si.p = p;
  si.n = Vec3{};
  si.n[a] = at_hi ? 1 : -1;
  si.shading_n = si.n;
  return si;
}

SurfaceInfo surface(const Box& b, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si = surface_geometry(b, ray, hit);
  const int a = (hit.part >= 0 && hit.part < 6 ? hit.part : 0) / 2;
  const int ub = (a + 1) % 3, vc = (a + 2) % 3;
  si.u = (si.p[ub] - b.lo[ub]) / (b.hi[ub] - b.lo[ub]);
  si.v = (si.p[vc] - b.lo[vc]) / (b.hi[vc] - b.lo[vc]);
  return si;
}

bool contains(const Box& b, const Vec3& p) {
  return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z &&
         p.z <= b.hi.z;
}

}  // namespace raycast
