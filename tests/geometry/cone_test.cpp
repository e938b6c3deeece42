#include "geometry/cone.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "objects/object.h"
#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

TEST(Cone, HandRayThroughTheSide_HitsAtHalfHeight) {
  // radius 1, height 2: r(z) = 1 - z/2, so r(1) = 0.5 and the ray along x meets x = -0.5.
  const Cone c = make_cone(1, 2);
  const Ray ray{{-5, 0, 1}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 4.5);
  const SurfaceInfo si = surface(c, ray, h);
  EXPECT_NEAR(si.n.x, -2 / std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(si.n.z, 1 / std::sqrt(5.0), 1e-15);
  EXPECT_DOUBLE_EQ(si.v, 0.5);
  EXPECT_DOUBLE_EQ(si.u, 0.5);
}

TEST(Cone, RayDownTheAxis_EntersAtTheApexAndLeavesThroughTheBase) {
  const Cone c = make_cone(1, 2);
  const Ray ray{{0, 0, 5}, {0, 0, -1}};
  SpanList sl;
  spans(c, ray, sl);
  ASSERT_FALSE(sl.empty());
  EXPECT_DOUBLE_EQ(sl[0].in.t, 3);
  EXPECT_DOUBLE_EQ(sl.back().out.t, 5);
  EXPECT_EQ(sl.back().out.part, kFrustumCap0);
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 3);
  const SurfaceInfo si = surface(c, ray, h);
  EXPECT_NEAR(length(si.n), 1, 1e-15);
  EXPECT_DOUBLE_EQ(si.n.z, 1);  // the apex: the tip's direction
}

TEST(Cone, SlantedRayThroughTheApex_IsInsideBelowIt) {
  // (-0.4, 0, 4) + t (0.2, 0, -1): the apex at t = 2, then inside (slope 0.2 < 0.5) to the base
  // at t = 4, x = 0.4.
  const Cone c = make_cone(1, 2);
  const Ray ray{{-0.4, 0, 4}, {0.2, 0, -1}};
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_NEAR(h.t, 2, 1e-12);
  SpanList sl;
  spans(c, ray, sl);
  ASSERT_FALSE(sl.empty());
  EXPECT_NEAR(sl.back().out.t, 4, 1e-12);
  EXPECT_TRUE(contains(c, ray.at(3)));
  EXPECT_FALSE(contains(c, ray.at(1)));
}

TEST(Cone, RayAlongAGenerator_HasNoSideCrossingButTheBase) {
  // (-1, 0, 0) + t (0.5, 0, 1) runs along the surface to the apex: a2 = a1 = a0 = 0.
  const Cone c = make_cone(1, 2);
  SpanList sl;
  spans(c, Ray{{-1, 0, 0}, {0.5, 0, 1}}, sl);
  EXPECT_LE(sl.size(), 1u);
}

TEST(Cone, PartialCone_SeenFromInsideThroughTheCut) {
  const Cone c = make_cone(1, 2, 180, false);
  EXPECT_FALSE(is_closed(c));
  // From the cut-away half (y < 0) towards +y at height 1: the kept side at y = +0.5 from inside.
  const Ray ray{{0, -5, 1}, {0, 1, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 5.5);
  const SurfaceInfo si = surface(c, ray, h);
  EXPECT_GT(si.n.y, 0);
  EXPECT_GT(dot(si.n, ray.d), 0);
  EXPECT_DOUBLE_EQ(si.u, 0.5);
}

TEST(Cone, TMinTMax_AreClosedAtBothEnds) {
  const Cone c = make_cone(1, 2);
  LocalHit h;
  EXPECT_TRUE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, 0, 4.5}, h));
  EXPECT_FALSE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, 0, std::nextafter(4.5, 0.0)}, h));
  EXPECT_TRUE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, 5.5, 9}, h));
  EXPECT_FALSE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, std::nextafter(5.5, 9.0), 9}, h));
}

TEST(Cone, RandomRays_SpansMatchInsideOracleAndNormalsPointOut) {
  for (int variant = 0; variant < 2; ++variant) {
    const Cone c = variant == 0 ? make_cone(0.9, 1.6)
                                : make_cone({0.2, -0.3, -0.6}, {-0.1, 0.4, 0.9}, 0.8, 0.3);
    auto inside = [&](const Vec3& p) { return contains(c, p); };
    Rng rng(53 + variant);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
      const Ray ray = testing::random_ray(rng, 3, 1.5);
      SCOPED_TRACE("seed " + std::to_string(53 + variant) + ", " + testing::describe(ray));
      ASSERT_EQ(testing::span_mismatches(c, ray, inside, -10, 10), 0);
      LocalHit h;
      const bool hit = intersect(c, ray, h);
      ASSERT_EQ(hit, testing::first_span_end(c, ray) < kInfinity);
      if (!hit) continue;
      ++hits;
      testing::expect_outward_normal(c, ray, h, inside, 1e-7);
    }
    EXPECT_GT(hits, 300);
  }
}

// The cone's side against the quadric x^2 + y^2 - (r(z))^2 solved in long double.
TEST(Cone, RandomRays_SideRootsMatchLongDouble) {
  const Cone c = make_cone(0.9, 1.6, 360, false);
  Rng rng(59);
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = testing::random_ray(rng, 3, 1.5);
    ray.tmin = -kInfinity;
    LocalHit h;
    if (!intersect(c, ray, h)) continue;
    SCOPED_TRACE("seed 59, " + testing::describe(ray));
    // Newton's method in long double from the returned t converges to the nearby root.
    const long double k = -0.9L / 1.6L;
    auto g = [&](long double t) {
      const long double x = ray.o.x + t * ray.d.x, y = ray.o.y + t * ray.d.y,
                        z = ray.o.z + t * ray.d.z;
      const long double r = 0.9L + k * z;
      return x * x + y * y - r * r;
    };
    long double t = h.t;
    for (int it = 0; it < 5; ++it) {
      const long double e = 1e-7L * (1 + std::abs(t));
      const long double slope = (g(t + e) - g(t - e)) / (2 * e);
      if (std::abs(slope) < 1e-3L) break;
      t -= g(t) / slope;
    }
    const long double slope = (g(t + 1e-6L) - g(t - 1e-6L)) / 2e-6L;
    if (std::abs(slope) < 0.05L * length(ray.d) * length(ray.d)) continue;  // near-tangent
    EXPECT_NEAR(h.t, (double)t, 1e-9 * std::max(1.0, std::abs(h.t)));
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(Cone, MakeCone_RejectsBadInput) {
  EXPECT_THROW(make_cone(0, 1), std::invalid_argument);
  EXPECT_THROW(make_cone(1, 0), std::invalid_argument);
  EXPECT_THROW(make_cone({0, 0, 0}, {0, 0, 1}, 0, 0), std::invalid_argument);
  EXPECT_THROW(make_cone({0, 0, 0}, {0, 0, 1}, -1, 1), std::invalid_argument);
  EXPECT_THROW(make_cone({0, 0, 0}, {0, 0, 0}, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
