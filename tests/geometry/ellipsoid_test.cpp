#include "geometry/ellipsoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/sphere.h"
#include "objects/object.h"
#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

TEST(Ellipsoid, HandRayAlongZ_CrossesAtTheSouthAndNorthPoles) {
  const Ellipsoid e = make_ellipsoid({1, 2, 3}, {2, 3, 4});
  const Ray ray{{1, 2, -10}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(e, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 9);
  const SurfaceInfo si = surface(e, ray, h);
  EXPECT_EQ(si.n, (Vec3{0, 0, -1}));
  EXPECT_DOUBLE_EQ(si.v, 0);
  SpanList sl;
  spans(e, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 17);
}

TEST(Ellipsoid, HandRayAlongX_HitsAtMinusA) {
  const Ellipsoid e = make_ellipsoid({1, 2, 3}, {2, 3, 4});
  const Ray ray{{-10, 2, 3}, {2, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(e, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 4.5);
  const SurfaceInfo si = surface(e, ray, h);
  EXPECT_DOUBLE_EQ(si.n.x, -1);
  EXPECT_DOUBLE_EQ(si.p.x, -1);
  EXPECT_DOUBLE_EQ(si.u, 0.5);
  EXPECT_DOUBLE_EQ(si.v, 0.5);
}

TEST(Ellipsoid, RandomRays_MatchAScaledSphere) {
  // The independent method: the unit sphere placed by scale(radii) then translate(center).
  const Vec3 c{0.3, -0.2, 0.1}, r{0.5, 1.2, 0.8};
  const Ellipsoid e = make_ellipsoid(c, r);
  const Object obj{make_sphere({0, 0, 0}, 1), Transform::translate(c) * Transform::scale(r), 0, 0};
  Rng rng(3);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = testing::random_ray(rng, 3, 1.5);
    SCOPED_TRACE("seed 3, " + testing::describe(ray));
    LocalHit a, b;
    const bool ha = intersect(e, ray, a), hb = intersect(obj, ray, b);
    ASSERT_EQ(ha, hb);
    if (!ha) continue;
    ++hits;
    EXPECT_NEAR(a.t, b.t, 1e-9 * std::max(1.0, std::abs(a.t)));
    const SurfaceInfo sa = surface(e, ray, a), sb = surface(obj, ray, b);
    EXPECT_NEAR(dot(sa.n, sb.n), 1, 1e-9);
    EXPECT_NEAR(sa.u, sb.u, 1e-9);
    EXPECT_NEAR(sa.v, sb.v, 1e-9);
    // The point is on the surface to long double precision.
    const long double x = (sa.p.x - (long double)c.x) / r.x, y = (sa.p.y - (long double)c.y) / r.y,
                      z = (sa.p.z - (long double)c.z) / r.z;
    EXPECT_NEAR((double)(x * x + y * y + z * z), 1.0, 1e-12);
  }
  EXPECT_GT(hits, 500);
}

TEST(Ellipsoid, RandomRays_SpansMatchInsideOracleAndNormalsPointOut) {
  const Ellipsoid e = make_ellipsoid({0.3, -0.2, 0.1}, {0.5, 1.2, 0.8});
  auto inside = [&](const Vec3& p) { return contains(e, p); };
  Rng rng(5);
  for (int i = 0; i < 1000; ++i) {
    const Ray ray = testing::random_ray(rng, 3, 1.5);
    SCOPED_TRACE("seed 5, " + testing::describe(ray));
    ASSERT_EQ(testing::span_mismatches(e, ray, inside, -10, 10), 0);
    LocalHit h;
    if (intersect(e, ray, h)) testing::expect_outward_normal(e, ray, h, inside, 1e-7);
  }
}

TEST(Ellipsoid, StartingInsideAndTMinTMax) {
  const Ellipsoid e = make_ellipsoid({0, 0, 0}, {1, 2, 3});
  LocalHit h;
  ASSERT_TRUE(intersect(e, Ray{{0, 0, 0}, {0, 1, 0}}, h));
  EXPECT_DOUBLE_EQ(h.t, 2);
  EXPECT_TRUE(intersect(e, Ray{{0, -5, 0}, {0, 1, 0}, 0, 3}, h));
  EXPECT_FALSE(intersect(e, Ray{{0, -5, 0}, {0, 1, 0}, 0, std::nextafter(3.0, 0.0)}, h));
  EXPECT_TRUE(intersect(e, Ray{{0, -5, 0}, {0, 1, 0}, 7, 8}, h));
  EXPECT_FALSE(intersect(e, Ray{{0, -5, 0}, {0, 1, 0}, std::nextafter(7.0, 8.0), 8}, h));
  EXPECT_FALSE(occluded(e, Ray{{0, -5, 0}, {0, 1, 0}, 3.5, 6.5}));
}

TEST(Ellipsoid, TangentRay_TouchesOnce) {
  const Ellipsoid e = make_ellipsoid({0, 0, 0}, {1, 2, 3});
  SpanList sl;
  spans(e, Ray{{-5, 2, 0}, {1, 0, 0}}, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_NEAR(sl[0].in.t, 5, 1e-7);
  EXPECT_NEAR(sl[0].out.t, 5, 1e-7);
}

TEST(Ellipsoid, MakeEllipsoid_RejectsBadRadii) {
  EXPECT_THROW(make_ellipsoid({0, 0, 0}, {1, 0, 1}), std::invalid_argument);
  EXPECT_THROW(make_ellipsoid({0, 0, 0}, {1, -1, 1}), std::invalid_argument);
  EXPECT_THROW(make_ellipsoid({0, 0, 0}, {1, 1, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(make_ellipsoid({0, 0, 0}, {1, 1, 1e-320}), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
