#include "geometry/plane.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

TEST(Plane, MakePlane_RejectsZeroOrNonFiniteInput) {
  EXPECT_THROW(make_plane({0, 0, 0}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(make_plane({0, std::nan(""), 1}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(make_plane({0, 0, 1}, {0, kInfinity, 0}), std::invalid_argument);
}

TEST(Plane, RayTowardsPlane_ExactHitAndNormal) {
  const Plane p = make_plane({0, 0, 2}, {0, 0, 1});
  const Ray ray{{3, 4, 5}, {0, 0, -2}};
  LocalHit h;
  ASSERT_TRUE(intersect(p, ray, h));
  EXPECT_EQ(h.t, 2);
  const SurfaceInfo si = surface(p, ray, h);
  EXPECT_EQ(si.p, Vec3(3, 4, 1));
  EXPECT_EQ(si.n, Vec3(0, 0, 1));
  // (u, v) along the plane's fixed tangent axes, measured from `point`.
  EXPECT_NEAR(si.u, dot(Vec3{3, 4, 0}, p.s), 1e-15);
  EXPECT_NEAR(si.v, dot(Vec3{3, 4, 0}, p.t), 1e-15);
  EXPECT_NEAR(dot(p.s, p.t), 0, 1e-15);
  EXPECT_NEAR(dot(p.s, p.n), 0, 1e-15);
}

TEST(Plane, ParallelRay_MissesAndSpansAllOrNothing) {
  const Plane p = make_plane({0, 1, 0}, {0, 0, 0});
  LocalHit h;
  EXPECT_FALSE(intersect(p, Ray{{0, 1, 0}, {1, 0, 0}}, h));
  EXPECT_FALSE(intersect(p, Ray{{0, -1, 0}, {1, 0, 0}}, h));
  SpanList s;
  spans(p, Ray{{0, 1, 0}, {1, 0, 0}}, s);
  EXPECT_TRUE(s.empty());
  spans(p, Ray{{0, -1, 0}, {1, 0, 0}}, s);  // inside the half-space: the whole line
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].in.t, -kInfinity);
  EXPECT_EQ(s[0].out.t, kInfinity);
  EXPECT_EQ(s[0].in.part, kNoSurface);
}

TEST(Plane, TminTmax_InclusiveAtBothEnds) {
  const Plane p = make_plane({0, 0, 1}, {0, 0, 0});
  LocalHit h;
  EXPECT_TRUE(intersect(p, Ray{{0, 0, 3}, {0, 0, -1}, 0, 3}, h));
  EXPECT_FALSE(intersect(p, Ray{{0, 0, 3}, {0, 0, -1}, 0, std::nextafter(3.0, 0.0)}, h));
  EXPECT_TRUE(intersect(p, Ray{{0, 0, 3}, {0, 0, -1}, 3, 10}, h));
  EXPECT_FALSE(intersect(p, Ray{{0, 0, 3}, {0, 0, -1}, std::nextafter(3.0, 4.0), 10}, h));
  EXPECT_FALSE(intersect(p, Ray{{0, 0, 3}, {0, 0, 1}}, h));  // behind the origin
}

TEST(Plane, Spans_AgreeWithHalfSpaceOracle) {
  const unsigned seed = 9;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  for (int i = 0; i < 300; ++i) {
    const Plane p = make_plane(rng.direction(), rng.in_box(1));
    const Ray ray = testing::random_ray(rng, 4, 2);
    testing::check_spans_against_oracle(p, ray, [&](const Vec3& q) { return contains(p, q); });
    LocalHit h;
    if (intersect(p, ray, h)) {
      const SurfaceInfo si = surface(p, ray, h);
      testing::expect_unit(si.n);
      EXPECT_NEAR(dot(si.p - p.point, p.n), 0, 1e-12);
      // Outward: a step along n leaves the half-space.
      EXPECT_FALSE(contains(p, si.p + 1e-6 * si.n));
    }
  }
}

}  // namespace
}  // namespace raycast
