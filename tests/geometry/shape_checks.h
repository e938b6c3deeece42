#pragma once
// Shared checks for the shape tests: seeded random rays, the spans-vs-inside oracle, and
// surface-record invariants. Header-only; every helper reports through gtest.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "geometry/shape.h"
#include "math/vec3.h"

namespace raycast::testing {

inline Vec3 random_in_box(std::mt19937_64& rng, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  return {u(rng), u(rng), u(rng)};
}

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3 v{g(rng), g(rng), g(rng)};
    const double l = length(v);
    if (l > 1e-6) return v / l;
  }
}

/// A ray from a random point in [-half, half]^3 towards a random point in [-aim, aim]^3, with a
/// direction of random length (t is in units of d, so this exercises the scaling).
inline Ray random_ray(std::mt19937_64& rng, double half, double aim) {
  std::uniform_real_distribution<double> len(0.1, 10);
  Ray r;
  r.o = random_in_box(rng, half);
  Vec3 d = random_in_box(rng, aim) - r.o;
  if (length_squared(d) == 0) d = {1, 0, 0};
  r.d = normalize(d) * len(rng);
  return r;
}

inline void expect_unit(const Vec3& n, const std::string& what = "normal") {
  EXPECT_NEAR(length(n), 1, 1e-12) << what << " not unit";
}

/// For a closed shape: samples the line at many t and checks that `inside(p)` agrees with the
/// union of the spans everywhere except within `guard` (relative) of a span end.
template <class S, class Inside>
void check_spans_against_oracle(const S& s, const Ray& ray, Inside inside, double lo = -20,
                                double hi = 20, int samples = 401) {
  SpanList list;
  spans(s, ray, list);  // found by argument-dependent lookup
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_LE(list[i].in.t, list[i].out.t) << "span " << i << " reversed";
    if (i > 0) {
      EXPECT_LE(list[i - 1].out.t, list[i].in.t) << "spans not sorted";
    }
  }
  const double guard = 1e-9 * (hi - lo);
  for (int k = 0; k < samples; ++k) {
    const double t = lo + (hi - lo) * (k + 0.37) / samples;
    bool in_span = false, near_end = false;
    for (const Span& sp : list) {
      if (t >= sp.in.t && t <= sp.out.t) in_span = true;
      if (std::abs(t - sp.in.t) < guard || std::abs(t - sp.out.t) < guard) near_end = true;
    }
    if (near_end) continue;
    EXPECT_EQ(in_span, inside(ray.at(t))) << "t = " << t;
  }
}

}  // namespace raycast::testing
