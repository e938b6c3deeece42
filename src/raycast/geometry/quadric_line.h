#pragma once
// Where a line is inside a quadric solid: the sign pattern of f(t) = a2 t^2 + a1 t + a0 < 0, and
// the clipping of such intervals to a range of t whose ends are other surfaces (box faces, caps).
// Shared by the quadric, cylinder and cone.
#include <cmath>
#include <initializer_list>

#include "geometry/hit.h"
#include "math/quadratic.h"

namespace raycast {

/// One end of an interval of t: the parameter and which surface makes it (kNoSurface at +-inf).
struct LineEnd {
  double t;
  int part;
};
struct LineInterval {
  LineEnd in, out;
};

/// The intervals (at most 2, sorted) of the whole line where a2 t^2 + a1 t + a0 < 0 (closed at
/// finite roots, which carry `part`). Tangent lines give a zero-length interval (a2 > 0) or two
/// touching ones (a2 < 0), so a touch counts as two crossings. a2 = 0 gives the linear case.
inline int quadratic_inside(double a2, double a1, double a0, int part, LineInterval out[2]) {
  const LineEnd lo{-kInfinity, kNoSurface}, hi{kInfinity, kNoSurface};
  auto end = [part](double t) { return LineEnd{t, std::isfinite(t) ? part : kNoSurface}; };
  if (a2 == 0) {
    if (a1 == 0) {
      if (!(a0 < 0)) return 0;
      out[0] = {lo, hi};
      return 1;
    }
    const double t = -a0 / a1;
    if (std::isnan(t)) return 0;
    out[0] = a1 > 0 ? LineInterval{lo, end(t)} : LineInterval{end(t), hi};
    return 1;
  }
  double t0, t1;
  if (solve_quadratic(a2, a1, a0, t0, t1) == 0) {
    if (!(a2 < 0) || !std::isfinite(a1) || !std::isfinite(a0)) return 0;  // f > 0 everywhere
    out[0] = {lo, hi};
    return 1;
  }
  if (a2 > 0) {
    out[0] = {end(t0), end(t1)};
    return 1;
  }
  out[0] = {lo, end(t0)};
  out[1] = {end(t1), hi};
  return 2;
}

/// Clips `s` to [b.in.t, b.out.t]; the ends that come from b take b's parts. False when empty.
inline bool clip_interval(const LineInterval& s, const LineInterval& b, LineInterval& out) {
  out.in = s.in.t >= b.in.t ? s.in : b.in;
  out.out = s.out.t <= b.out.t ? s.out : b.out;
  return out.in.t <= out.out.t;
}

/// The first finite end with part != kNoSurface inside [tmin, tmax] over sorted intervals.
inline bool first_end(const LineInterval* iv, int n, double tmin, double tmax, LineEnd& hit) {
  for (int i = 0; i < n; ++i) {
    for (const LineEnd& e : {iv[i].in, iv[i].out}) {
      if (e.part == kNoSurface || e.t < tmin) continue;
      if (e.t > tmax) return false;
      hit = e;
      return true;
    }
  }
  return false;
}

}  // namespace raycast
