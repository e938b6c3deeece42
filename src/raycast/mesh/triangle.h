#pragma once
// Ray/triangle tests in float: the watertight test of Woop, Benthin and Wald 2013 (the one the
// engine uses) and Moller-Trumbore 1997 (kept for comparison and tests).
#include <cmath>
#include <cstdint>

#include "math/vec3.h"

namespace raycast {

/// A ray prepared for the watertight test: the axis kz along which |d| is largest, kx and ky the
/// other two (swapped so the winding is kept), and the shear (sx, sy, sz) that maps d to (0, 0, 1)
/// in the permuted space. Built once per ray (Woop et al. 2013, section 3).
struct WatertightRay {
  Vec3f o;
  Vec3f d;
  int kx = 0, ky = 1, kz = 2;
  float sx = 0, sy = 0, sz = 1;
};

inline WatertightRay make_watertight_ray(const Vec3f& o, const Vec3f& d) {
  WatertightRay r;
  r.o = o;
  r.d = d;
  const Vec3f a = abs(d);
  r.kz = max_dimension(a);
  r.kx = r.kz == 2 ? 0 : r.kz + 1;
  r.ky = r.kx == 2 ? 0 : r.kx + 1;
  if (d[r.kz] < 0) {
    const int k = r.kx;
    r.kx = r.ky;
    r.ky = k;
  }
  r.sx = d[r.kx] / d[r.kz];
  r.sy = d[r.ky] / d[r.kz];
  r.sz = 1.0f / d[r.kz];
  return r;
}

/// The result of a triangle test: t along the ray in units of d (float), and the barycentrics of
/// v1 and v2 (b1, b2), with the hit point v0 + b1 (v1 - v0) + b2 (v2 - v0).
struct TriangleHit {
  float t;
  float b1;
  float b2;
};

/// Watertight ray/triangle test (Woop, Benthin and Wald 2013). Both faces count. A hit needs the
/// three edge functions of one sign (zero allowed on either side, so a ray through a shared edge
/// or vertex hits at least one of the triangles that meet there), a non-zero determinant and
/// tmin <= t <= tmax (the float t = T / det). An edge function that is exactly 0 in float is
/// recomputed in double, as the paper prescribes, so its sign is exact.
inline bool intersect_watertight(const WatertightRay& r, const Vec3f& v0, const Vec3f& v1,
                                 const Vec3f& v2, float tmin, float tmax, TriangleHit& hit) {
  const Vec3f a = v0 - r.o, b = v1 - r.o, c = v2 - r.o;
  // Shear and scale the vertices into ray space.
  const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
  const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
  const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
  float u = cx * by - cy * bx;
  float v = ax * cy - ay * cx;
  float w = bx * ay - by * ax;
  if (u == 0 || v == 0 || w == 0) {
    u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
    v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
    w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
  }
  const bool same_sign = (u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0);
  const float det = u + v + w;
  if (!same_sign || !(det != 0)) return false;
  const float az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
  const float t_scaled = u * az + v * bz + w * cz;
  const float t = t_scaled / det;
  if (!(t >= tmin && t <= tmax)) return false;
  hit = {t, v / det, w / det};
  return true;
}

/// Moller-Trumbore 1997: not watertight (rays through shared edges can slip through); for
/// comparison only. Same contract as intersect_watertight otherwise.
inline bool intersect_moller_trumbore(const Vec3f& o, const Vec3f& d, const Vec3f& v0,
                                      const Vec3f& v1, const Vec3f& v2, float tmin, float tmax,
                                      TriangleHit& hit) {
  const Vec3f e1 = v1 - v0, e2 = v2 - v0;
  const Vec3f p = cross(d, e2);
  const float det = dot(e1, p);
  if (det == 0) return false;
  const float inv = 1.0f / det;
  const Vec3f s = o - v0;
  const float b1 = dot(s, p) * inv;
  if (!(b1 >= 0 && b1 <= 1)) return false;
  const Vec3f q = cross(s, e1);
  const float b2 = dot(d, q) * inv;
  if (!(b2 >= 0 && b1 + b2 <= 1)) return false;
  const float t = dot(e2, q) * inv;
  if (!(t >= tmin && t <= tmax)) return false;
  hit = {t, b1, b2};
  return true;
}

}  // namespace raycast
