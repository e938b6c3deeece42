#pragma once
// The nearest hit and the spans of a shape that finds every crossing of the whole line at once,
// sorted by t (surfaces of revolution, prisms): each crossing carries its t, the surface part
// and the curve parameter s kept as LocalHit::a for surface().
#include <cstddef>

#include "geometry/hit.h"
#include "geometry/ray.h"
#include "geometry/span_list.h"

namespace raycast {

struct CurveCrossing {
  double t;
  int part;  // the shape's own numbering of its surface parts (never -1: kNoSurface)
  double s;
};

inline LocalHit to_hit(const CurveCrossing& c) {
  return LocalHit{.t = c.t, .part = c.part, .a = c.s};
}

/// The first of the n sorted crossings within [ray.tmin, ray.tmax].
inline bool first_crossing_in_range(const CurveCrossing* c, int n, const Ray& ray, LocalHit& hit) {
  for (int i = 0; i < n; ++i) {
    if (c[i].t >= ray.tmin && c[i].t <= ray.tmax) {
      hit = to_hit(c[i]);
      return true;
    }
  }
  return false;
}

/// The spans of the n sorted crossings: each crossing alone for an open surface; for a solid,
/// the stretches between consecutive crossings whose middle `inside` holds, touching ones merged.
template <class Inside>
void spans_from_crossings(const CurveCrossing* c, int n, const Ray& ray, bool solid,
                          const Inside& inside, SpanList& out) {
  if (!solid) {
    for (int i = 0; i < n; ++i) out.add(to_hit(c[i]), to_hit(c[i]));
    return;
  }
  const std::size_t first = out.size();
  for (int i = 0; i + 1 < n; ++i) {
    if (!(c[i].t < c[i + 1].t)) continue;
    if (!inside(ray.at(0.5 * (c[i].t + c[i + 1].t)))) continue;
    if (out.size() > first && out.back().out.t == c[i].t)
      out.back().out = to_hit(c[i + 1]);
    else
      out.add(to_hit(c[i]), to_hit(c[i + 1]));
  }
}

}  // namespace raycast
