#include "geometry/revolution.h"
#include "geometry/shape_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reference_roots.h"

namespace raycast {
namespace {

const std::vector<std::array<double, 2>> kVase = {{0, 0},     {0, 0},     {0, 0},     {0.8, 0},
                                                  {1.2, 0.6}, {0.5, 1.6}, {0.4, 2.4}, {0.8, 3.0},
                                                  {0.8, 3.0}, {0.8, 3.0}};

std::vector<double> crossing_ts(const Revolution& s, const Ray& r) {
  SpanList l;
  spans(s, r, l);
  std::vector<double> t;
  for (const Span& sp : l) {
    t.push_back(sp.in.t);
    if (s.closed) t.push_back(sp.out.t);
  }
  return t;
}

TEST(Revolution, CappedCylinder_HandComputed) {
  const Revolution s = make_revolution({{1, 0}, {1, 2}}, ProfileCurve::kLinear);
  EXPECT_TRUE(is_closed(s));
  const Ray side{{-5, 0, 1}, {1, 0, 0}};  // horizontal: the z1 = 0 path
  auto t = crossing_ts(s, side);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 4, 1e-12);
  EXPECT_NEAR(t[1], 6, 1e-12);
  LocalHit h;
  ASSERT_TRUE(intersect(s, side, h));
  SurfaceInfo si = surface(s, side, h);
  EXPECT_NEAR(si.n.x, -1, 1e-12);
  const Ray top{{0.3, 0.2, 5}, {0, 0, -1}};
  ASSERT_TRUE(intersect(s, top, h));
  EXPECT_NEAR(h.t, 3, 1e-12);
  si = surface(s, top, h);
  EXPECT_EQ(si.n, (Vec3{0, 0, 1}));
  t = crossing_ts(s, top);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[1], 5, 1e-12);
  EXPECT_EQ(surface(s, top, LocalHit{t[1], -1, 2, 0, 0}).n, (Vec3{0, 0, -1}));
  // The profile reversed gives the same solid and normals.
  const Revolution rev = make_revolution({{1, 2}, {1, 0}}, ProfileCurve::kLinear);
  ASSERT_TRUE(intersect(rev, top, h));
  EXPECT_EQ(surface(rev, top, h).n, (Vec3{0, 0, 1}));
  ASSERT_TRUE(intersect(rev, side, h));
  EXPECT_NEAR(surface(rev, side, h).n.x, -1, 1e-12);
}

TEST(Revolution, Uncapped_OpenSurfaceSeenFromInside) {
  const Revolution s = make_revolution({{1, 0}, {1, 2}}, ProfileCurve::kLinear, false);
  EXPECT_FALSE(is_closed(s));
  EXPECT_FALSE(contains(s, Vec3{0, 0, 1}));
  LocalHit h;
  const Ray through_top{{0.3, 0.2, 2.5}, {0.5, 0, -1}};
  ASSERT_TRUE(intersect(s, through_top, h));
  EXPECT_GT(through_top.at(h.t).z, 1);
  EXPECT_LT(through_top.at(h.t).z, 2);
  EXPECT_GT(dot(surface(s, through_top, h).n, through_top.d), 0);  // the inside is seen
  const Ray slanted{{0, 0, 1}, {1, 0, 0.1}};
  ASSERT_TRUE(intersect(s, slanted, h));
  EXPECT_NEAR(h.t, 1, 1e-12);
  EXPECT_NEAR(surface(s, slanted, h).n.x, 1, 1e-12);  // away from the axis, as the solid's
}

TEST(Revolution, ConeHorizontalAndSlantedRays_HandComputed) {
  const Revolution s = make_revolution({{1, 0}, {0, 2}}, ProfileCurve::kLinear);  // apex up
  auto t = crossing_ts(s, Ray{{-5, 0, 1}, {1, 0, 0}});
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 4.5, 1e-12);
  EXPECT_NEAR(t[1], 5.5, 1e-12);
  // Nearly horizontal rays on both sides of the switch between the two methods.
  for (double dz : {1e-7, 1e-5, 1e-3, 0.1}) {
    SCOPED_TRACE(dz);
    const Ray r{{-5, 0, 1}, {1, 0, dz}};
    t = crossing_ts(s, r);
    ASSERT_EQ(t.size(), 2u);
    for (double ti : t) {
      const Vec3 p = r.at(ti);
      EXPECT_NEAR(std::hypot(p.x, p.y), 1 - p.z / 2, 1e-10);
    }
  }
}

TEST(Revolution, TMinTMax) {
  const Revolution s = make_revolution({{1, 0}, {1, 2}}, ProfileCurve::kLinear);
  LocalHit h;
  Ray r{{-5, 0, 1}, {1, 0, 0}, 0, 4};
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 4, 1e-12);
  r.tmax = 3.9999;
  EXPECT_FALSE(occluded(s, r));
  r.tmin = 4.5;
  r.tmax = kInfinity;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 6, 1e-12);
}

// A frustum from a linear profile against its own definition in long double.
TEST(Revolution, Frustum_RandomRaysMatchLongDoubleReference) {
  const Revolution s = make_revolution({{1, 0}, {0.5, 2}}, ProfileCurve::kLinear);
  int compared = 0;
  for (unsigned seed = 0; seed < 800; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const Vec3 o{3 * u(rng), 3 * u(rng), 1 + 3 * u(rng)};
    const Ray r{o, Vec3{u(rng), u(rng), 1 + u(rng)} - o};
    auto g = [&](long double t) {
      const long double x = r.o.x + t * r.d.x, y = r.o.y + t * r.d.y, z = r.o.z + t * r.d.z;
      return std::max({std::sqrt(x * x + y * y) - (1 - z / 4), -z, z - 2});
    };
    const auto ref = testing_reference::sign_change_roots(g, 0, 3, 3000);
    LocalHit h;
    const bool hit = intersect(s, r, h);
    if (ref.empty()) continue;
    ASSERT_TRUE(hit);
    EXPECT_NEAR(h.t, (double)ref[0], 1e-9 * std::max(1.0, (double)ref[0]));
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

// The vase's z(s) is monotone, so its radius is a function of z: a reference by bisection.
long double vase_radius_at(const Revolution& s, long double z) {
  for (const auto& g : s.segments) {
    auto zs = [&](long double t) {
      long double v = 0;
      for (int k = g.z.degree; k >= 0; --k) v = v * t + g.z.c[k];
      return v;
    };
    if (z < zs(0) || z > zs(1) || zs(1) == zs(0)) continue;
    long double a = 0, b = 1;
    for (int i = 0; i < 80; ++i) {
      const long double m = 0.5L * (a + b);
      (zs(m) < z ? a : b) = m;
    }
    long double r = 0;
    for (int k = g.r.degree; k >= 0; --k) r = r * a + g.r.c[k];
    return r;
  }
  return -1;
}

TEST(Revolution, BSplineVase_RandomRaysMatchLongDoubleReference) {
  const Revolution s = make_revolution(kVase, ProfileCurve::kBSpline);
  int compared = 0;
  for (unsigned seed = 0; seed < 300; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const Vec3 o{4 * u(rng), 4 * u(rng), 1.5 + 1.2 * u(rng)};
    const Ray r{o, Vec3{0.8 * u(rng), 0.8 * u(rng), 1.5 + 1.2 * u(rng)} - o};
    auto g = [&](long double t) {
      const long double x = r.o.x + t * r.d.x, y = r.o.y + t * r.d.y, z = r.o.z + t * r.d.z;
      if (z <= 0.05L || z >= 2.95L) return 1.0L;  // only the curved middle is compared
      return std::sqrt(x * x + y * y) - vase_radius_at(s, z);
    };
    const auto ref = testing_reference::sign_change_roots(g, 0, 1.2, 1500);
    if (ref.empty()) continue;
    const Vec3 p = r.at((double)ref[0]);
    if (p.z <= 0.06 || p.z >= 2.94) continue;
    LocalHit h;
    ASSERT_TRUE(intersect(s, r, h));
    EXPECT_NEAR(h.t, (double)ref[0], 1e-9 * std::max(1.0, (double)ref[0]));
    ++compared;
  }
  EXPECT_GT(compared, 30);
}

TEST(Revolution, BSplineVase_SpansMatchInsideOracleAndNormalsOutward) {
  const Revolution s = make_revolution(kVase, ProfileCurve::kBSpline);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  int normals = 0;
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE(i);
    const Vec3 o{3 * u(rng), 3 * u(rng), 1.5 + 3 * u(rng)};
    const Ray r{o, Vec3{u(rng), u(rng), 1.5 + 1.5 * u(rng)} - o};
    testing::check_spans_against_oracle(
        s, r, [&](const Vec3& p) { return contains(s, p); }, -1, 3.0, 300);
    LocalHit h;
    if (!intersect(s, r, h)) continue;
    const SurfaceInfo si = surface(s, r, h);
    EXPECT_NEAR(length(si.n), 1, 1e-12);
    if (std::hypot(si.p.x, si.p.y) > 1e-3) {
      EXPECT_FALSE(contains(s, si.p + 1e-6 * si.n));
      EXPECT_TRUE(contains(s, si.p - 1e-6 * si.n));
      ++normals;
    }
  }
  EXPECT_GT(normals, 50);
}

TEST(Revolution, EndsOnTheAxis_ClosedWithoutCaps) {
  const Revolution s =
      make_revolution({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, ProfileCurve::kLinear, false);
  EXPECT_TRUE(is_closed(s));
  EXPECT_TRUE(s.caps.empty());
  EXPECT_TRUE(contains(s, Vec3{0.5, 0, 0.5}));
  EXPECT_FALSE(contains(s, Vec3{1.5, 0, 0.5}));
  const Ray down{{0.2, 0.1, 3}, {0, 0, -1}};  // through the annulus top (a horizontal segment)
  SpanList l;
  spans(s, down, l);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_NEAR(l[0].in.t, 2, 1e-12);
  EXPECT_NEAR(l[0].out.t, 3, 1e-12);
  EXPECT_NEAR(surface(s, down, l[0].in).n.z, 1, 1e-12);
  EXPECT_NEAR(surface(s, down, l[0].out).n.z, -1, 1e-12);
  // One end off the axis: open unless capped, then one cap.
  const Revolution cup = make_revolution({{0, 0}, {1, 0}, {1, 1}}, ProfileCurve::kLinear, false);
  EXPECT_FALSE(is_closed(cup));
  const Revolution capped = make_revolution({{0, 0}, {1, 0}, {1, 1}}, ProfileCurve::kLinear, true);
  EXPECT_TRUE(is_closed(capped));
  EXPECT_EQ(capped.caps.size(), 1u);
}

TEST(Revolution, MakeRevolution_RejectsBadProfiles) {
  EXPECT_THROW(make_revolution({{1, 0}}, ProfileCurve::kLinear), std::invalid_argument);
  EXPECT_THROW(make_revolution({{1, 0}, {1, 1}, {1, 2}}, ProfileCurve::kBSpline),
               std::invalid_argument);
  EXPECT_THROW(make_revolution({{-1, 0}, {1, 1}}, ProfileCurve::kLinear), std::invalid_argument);
  EXPECT_THROW(make_revolution({{0, 0}, {0, 1}}, ProfileCurve::kLinear), std::invalid_argument);
  EXPECT_THROW(make_revolution({{1, 1}, {1, 1}}, ProfileCurve::kLinear), std::invalid_argument);
  EXPECT_THROW(make_revolution({{std::nan(""), 0}, {1, 1}}, ProfileCurve::kLinear),
               std::invalid_argument);
}

}  // namespace
}  // namespace raycast
