#pragma once
// Shared pieces of the solids bounded by a box (algebraic and implicit surfaces, POV-Ray's
// `contained_by`): the line's chord through the box with the faces it enters and leaves by, and
// the spans of {f < 0} inside the box from the sorted roots of f along the chord.
#include <cmath>

#include "geometry/aabb.h"
#include "geometry/hit.h"
#include "geometry/ray.h"
#include "geometry/span_list.h"

namespace raycast {

/// The parameter interval [t0, t1] of the whole line o + t d inside a closed box, with the faces
/// (0..5 = -x, +x, -y, +y, -z, +z) at each end; face -1 where an end is unconstrained.
struct BoxChord {
  double t0 = -kInfinity, t1 = kInfinity;
  int face0 = -1, face1 = -1;
};

/// false when the line misses the box (or only touches it where a d component is 0 outside).
inline bool box_chord(const Aabb& b, const Ray& ray, BoxChord& c) {
  c = BoxChord{};
  for (int a = 0; a < 3; ++a) {
    if (ray.d[a] == 0) {
      if (ray.o[a] < b.lo[a] || ray.o[a] > b.hi[a]) return false;
      continue;
    }
    const double inv = 1 / ray.d[a];
    double near = (b.lo[a] - ray.o[a]) * inv, far = (b.hi[a] - ray.o[a]) * inv;
    int fn = 2 * a, ff = 2 * a + 1;
    if (near > far) {
      std::swap(near, far);
      std::swap(fn, ff);
    }
    if (near > c.t0) c.t0 = near, c.face0 = fn;
    if (far < c.t1) c.t1 = far, c.face1 = ff;
  }
  return c.t0 <= c.t1;
}

/// The outward unit normal of box face `face` (0..5 = -x, +x, -y, +y, -z, +z).
inline Vec3 box_face_normal(int face) {
  Vec3 n;
  n[face / 2] = face % 2 ? 1.0 : -1.0;
  return n;
}

/// LocalHit parts used by the clipped solids: 0 the curved surface, 1 + face a box face.
inline constexpr int kCurvedPart = 0;
inline constexpr int kFacePart = 1;

/// Appends the spans of the solid {f < 0} within the chord (closed = true), or a zero-length span
/// at each crossing where f changes sign (closed = false: the curved surface alone, open).
/// roots[0..n) are the sorted roots of f in [c.t0, c.t1] with an error estimate each (stored in
/// LocalHit::a); negative_at(t) tells whether f < 0 at t.
template <class NegativeAt>
void chord_spans(const BoxChord& c, const double* roots, const double* errors, int n, bool closed,
                 NegativeAt&& negative_at, SpanList& out) {
  auto point = [&](int i) { return i < 0 ? c.t0 : (i >= n ? c.t1 : roots[i]); };
  auto end = [&](int i) {
    if (i < 0) return LocalHit{.t = c.t0, .part = kFacePart + c.face0};
    if (i >= n) return LocalHit{.t = c.t1, .part = kFacePart + c.face1};
    return LocalHit{.t = roots[i], .part = kCurvedPart, .a = errors[i]};
  };
  if (!closed) {
    for (int i = 0; i < n; ++i) {
      const bool left = negative_at(0.5 * (point(i - 1) + roots[i]));
      const bool right = negative_at(0.5 * (roots[i] + point(i + 1)));
      if (left != right) out.add(end(i), end(i));
    }
    return;
  }
  const std::size_t first = out.size();
  for (int i = -1; i < n; ++i) {
    const double a = point(i), b = point(i + 1);
    if (!(a < b) && !(a == b && n == 0)) continue;
    if (!negative_at(0.5 * (a + b))) continue;
    if (out.size() > first && out.back().out.t == a) {
      out.back().out = end(i + 1);  // a touch from inside: one span
    } else {
      out.add(end(i), end(i + 1));
    }
  }
}

}  // namespace raycast
