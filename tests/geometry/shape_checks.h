#pragma once
// The shared helpers of every shape test: the random rays of support/random.h, the
// spans-vs-inside oracle, outward normals by stepping off the surface, surface-record invariants.
// Header-only; every helper reports through gtest.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "geometry/shape.h"
#include "math/vec3.h"
#include "support/random.h"

namespace raycast::testing {

inline void expect_unit(const Vec3& n, const std::string& what = "normal") {
  EXPECT_NEAR(length(n), 1, 1e-12) << what << " not unit";
}

inline std::string describe(const Ray& ray) {
  std::ostringstream s;
  s.precision(17);
  s << "ray o=(" << ray.o.x << ", " << ray.o.y << ", " << ray.o.z << ") d=(" << ray.d.x << ", "
    << ray.d.y << ", " << ray.d.z << ") tmin=" << ray.tmin << " tmax=" << ray.tmax;
  return s.str();
}

/// Spans are sorted, each in <= out; and a point sampled on the line (away from the ends by a
/// guard of 1e-7 relative) is inside the oracle exactly when it lies in a span. Returns the
/// number of samples that disagree.
template <class S, class Inside>
int span_mismatches(const S& s, const Ray& ray, Inside inside, double t_lo, double t_hi,
                    int samples = 200) {
  SpanList sl;
  spans(s, ray, sl);
  int bad = 0;
  for (std::size_t i = 0; i < sl.size(); ++i) {
    if (!(sl[i].in.t <= sl[i].out.t)) ++bad;
    if (i + 1 < sl.size() && !(sl[i].out.t <= sl[i + 1].in.t)) ++bad;
  }
  for (int k = 0; k < samples; ++k) {
    const double t = t_lo + (k + 0.5) / samples * (t_hi - t_lo);
    const double guard = 1e-7 * (1 + std::abs(t));
    bool near = false, in = false;
    for (const Span& sp : sl) {
      near = near || std::abs(t - sp.in.t) < guard || std::abs(t - sp.out.t) < guard;
      in = in || (sp.in.t <= t && t <= sp.out.t);
    }
    if (!near && in != inside(ray.at(t))) ++bad;
  }
  return bad;
}

/// The hit's normal is unit, and a step of h along it leaves the solid while a step back enters.
template <class S, class Inside>
void expect_outward_normal(const S& s, const Ray& ray, const LocalHit& hit, Inside inside,
                           double h) {
  const SurfaceInfo si = surface(s, ray, hit);
  EXPECT_NEAR(length(si.n), 1.0, 1e-12);
  EXPECT_FALSE(inside(si.p + h * si.n)) << "part " << hit.part;
  EXPECT_TRUE(inside(si.p - h * si.n)) << "part " << hit.part;
}

/// The nearest span end in [tmin, tmax] with a surface, or inf: what intersect must return.
template <class S>
double first_span_end(const S& s, const Ray& ray) {
  SpanList sl;
  spans(s, ray, sl);
  for (const Span& sp : sl)
    for (const LocalHit& h : {sp.in, sp.out})
      if (h.part != kNoSurface && h.t >= ray.tmin && h.t <= ray.tmax) return h.t;
  return kInfinity;
}

/// For a closed shape: span_mismatches over [lo, hi] must find no disagreement.
template <class S, class Inside>
void check_spans_against_oracle(const S& s, const Ray& ray, Inside inside, double lo = -20,
                                double hi = 20, int samples = 401) {
  EXPECT_EQ(span_mismatches(s, ray, inside, lo, hi, samples), 0) << describe(ray);
}

}  // namespace raycast::testing
