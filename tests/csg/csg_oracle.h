#pragma once
// Shared checks for CSG tests: a scene built from YAML text, and the spans / hit / normal of an
// object compared with an inside(p) oracle sampled densely along random rays.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "load/loader.h"
#include "support/random.h"

namespace raycast::csg_test {

using Oracle = std::function<bool(const Vec3&)>;

inline Scene scene_of(const std::string& objects_yaml) {
  return load_scene_text("objects:\n" + objects_yaml);
}

// Distance along the ray kept clear of span ends when sampling, in units of t (|d| ~ 1).
inline constexpr double kSampleGuard = 1e-7;
// Step off a surface when checking which side is inside.
inline constexpr double kSideStep = 1e-6;

/// Checks the object's spans on `ray` against the oracle at `samples` points of [-range, range],
/// that every finite end is a real transition of the oracle, and the nearest hit and its normal.
/// Returns the number of spans (so callers can make sure the rays exercise something).
inline int check_ray(const Object& obj, const Oracle& inside, const Ray& ray, double range,
                     int samples) {
  SpanList list;
  spans(obj, ray, list);
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_LT(list[i].in.t, list[i].out.t) << "span " << i;
    if (i > 0) {
      EXPECT_LT(list[i - 1].out.t, list[i].in.t) << "spans " << i - 1 << " and " << i;
    }
  }
  auto near_end = [&](double t) {
    for (const Span& s : list)
      if (std::abs(t - s.in.t) < kSampleGuard || std::abs(t - s.out.t) < kSampleGuard) return true;
    return false;
  };
  for (int k = 0; k <= samples; ++k) {
    const double t = -range + 2 * range * k / samples;
    if (near_end(t)) continue;
    bool in_span = false;
    for (const Span& s : list) in_span |= s.in.t <= t && t <= s.out.t;
    EXPECT_EQ(in_span, inside(ray.at(t))) << "at t = " << t;
  }
  for (const Span& s : list) {
    for (const LocalHit* e : {&s.in, &s.out}) {
      if (!std::isfinite(e->t)) continue;
      EXPECT_NE(inside(ray.at(e->t - kSideStep)), inside(ray.at(e->t + kSideStep)))
          << "end t = " << e->t;
    }
  }
  // The nearest hit is the first finite end at or after tmin, and its normal points out.
  double expected = kInfinity;
  for (const Span& s : list) {
    for (const LocalHit* e : {&s.in, &s.out})
      if (std::isfinite(e->t) && e->t >= ray.tmin && e->t < expected) expected = e->t;
  }
  LocalHit hit;
  const bool found = intersect(obj, ray, hit);
  EXPECT_EQ(found, expected < kInfinity);
  EXPECT_EQ(occluded(obj, ray), found);
  if (found) {
    EXPECT_EQ(hit.t, expected);
    const SurfaceInfo si = surface(obj, ray, hit);
    EXPECT_NEAR(length(si.n), 1, 1e-12);
    const Vec3 step = kSideStep * si.n;
    EXPECT_TRUE(inside(si.p - step)) << "normal points into the solid at t = " << hit.t;
    EXPECT_FALSE(inside(si.p + step)) << "normal points into the solid at t = " << hit.t;
  }
  return static_cast<int>(list.size());
}

/// Random rays through the region [-extent, extent]^3: half start far outside and cross it, half
/// start at a random point inside the region (often inside the solid), with tmin 0. Directions
/// have random lengths in [0.25, 4] (t is in units of d).
inline void check_random_rays(const Object& obj, const Oracle& inside, unsigned seed, int rays,
                              double extent, int samples = 400) {
  raycast::testing::Rng rng(seed);
  int with_spans = 0;
  for (int i = 0; i < rays; ++i) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed << " ray " << i);
    const Vec3 target = rng.in_box(extent);
    const Vec3 unit = rng.direction();
    const double scale = std::exp(rng.uniform(std::log(0.25), std::log(4.0)));
    const Vec3 o = i % 2 ? target : target - 3.0 * extent * unit;
    with_spans += check_ray(obj, inside, Ray{o, scale * unit, 0, kInfinity}, 6.0 * extent / scale,
                            samples) > 0;
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(with_spans, rays / 10) << "the rays hardly meet the solid: the test would prove little";
}

}  // namespace raycast::csg_test
