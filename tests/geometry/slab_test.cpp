#include "geometry/slab.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

TEST(Slab, HandRay_EntersAtD0AndLeavesAtD1) {
  // 1 <= 2z <= 3, i.e. 0.5 <= z <= 1.5.
  const Slab s = make_slab({0, 0, 2}, 1, 3);
  const Ray ray{{0, 0, -1}, {0, 0, 0.5}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 3);
  EXPECT_EQ(surface(s, ray, h).n, (Vec3{0, 0, -1}));
  SpanList sl;
  spans(s, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 5);
  EXPECT_EQ(surface(s, ray, sl[0].out).n, (Vec3{0, 0, 1}));
  // From the other side the order and the normals swap.
  const Ray down{{0, 0, 4}, {0, 0, -1}};
  ASSERT_TRUE(intersect(s, down, h));
  EXPECT_DOUBLE_EQ(h.t, 2.5);
  EXPECT_EQ(surface(s, down, h).n, (Vec3{0, 0, 1}));
  EXPECT_EQ(bounds(s).lo.x, -kInfinity);
  EXPECT_NEAR(bounds(s).lo.z, 0.5, 1e-15);
  EXPECT_NEAR(bounds(s).hi.z, 1.5, 1e-15);
}

TEST(Slab, ParallelRays_AreWhollyInsideOrOutside) {
  const Slab s = make_slab({0, 1, 0}, -1, 1);
  LocalHit h;
  EXPECT_FALSE(intersect(s, Ray{{0, 0, 0}, {1, 0, 0}}, h));
  SpanList in, out;
  spans(s, Ray{{0, 0, 0}, {1, 0, 0}}, in);
  spans(s, Ray{{0, 2, 0}, {1, 0, 0}}, out);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].in.t, -kInfinity);
  EXPECT_EQ(in[0].out.part, kNoSurface);
  EXPECT_TRUE(out.empty());
}

TEST(Slab, StartingInsideAndTMinTMax) {
  const Slab s = make_slab({1, 1, 0}, -1, 1);
  LocalHit h;
  ASSERT_TRUE(intersect(s, Ray{{0, 0, 0}, {1, 0, 0}}, h));
  EXPECT_DOUBLE_EQ(h.t, 1);
  EXPECT_TRUE(intersect(s, Ray{{-3, 0, 0}, {1, 0, 0}, 0, 2}, h));
  EXPECT_FALSE(intersect(s, Ray{{-3, 0, 0}, {1, 0, 0}, 0, std::nextafter(2.0, 0.0)}, h));
  EXPECT_TRUE(intersect(s, Ray{{-3, 0, 0}, {1, 0, 0}, 4, 5}, h));
  EXPECT_FALSE(intersect(s, Ray{{-3, 0, 0}, {1, 0, 0}, std::nextafter(4.0, 5.0), 5}, h));
}

TEST(Slab, RandomRays_MatchLongDoubleAndTheInsideOracle) {
  const Vec3 n{0.3, -1.2, 0.7};
  const Slab s = make_slab(n, -0.4, 0.9);
  auto inside = [&](const Vec3& p) { return contains(s, p); };
  Rng rng(71);
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = testing::random_ray(rng, 4, 2);
    SCOPED_TRACE("seed 71, " + testing::describe(ray));
    ASSERT_EQ(testing::span_mismatches(s, ray, inside, -20, 20), 0);
    SpanList sl;
    spans(s, ray, sl);
    ASSERT_EQ(sl.size(), 1u);
    const long double nd =
        (long double)n.x * ray.d.x + (long double)n.y * ray.d.y + (long double)n.z * ray.d.z;
    const long double no =
        (long double)n.x * ray.o.x + (long double)n.y * ray.o.y + (long double)n.z * ray.o.z;
    const long double t0 = (-0.4L - no) / nd, t1 = (0.9L - no) / nd;
    const double lo = (double)std::min(t0, t1), hi = (double)std::max(t0, t1);
    EXPECT_NEAR(sl[0].in.t, lo, 1e-9 * std::max(1.0, std::abs(lo)));
    EXPECT_NEAR(sl[0].out.t, hi, 1e-9 * std::max(1.0, std::abs(hi)));
    LocalHit h;
    if (intersect(s, ray, h)) testing::expect_outward_normal(s, ray, h, inside, 1e-7);
  }
}

TEST(Slab, MakeSlab_RejectsBadInput) {
  EXPECT_THROW(make_slab({0, 0, 0}, 0, 1), std::invalid_argument);
  EXPECT_THROW(make_slab({0, 0, 1}, 1, 1), std::invalid_argument);
  EXPECT_THROW(make_slab({0, 0, 1}, 2, 1), std::invalid_argument);
  EXPECT_THROW(make_slab({0, 0, 1}, 0, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
