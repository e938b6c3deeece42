#include "geometry/aabb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

const Aabb kCube{{-1, -1, -1}, {1, 1, 1}};

bool slab_hit(const Aabb& b, const Vec3& o, const Vec3& d, double tmin = 0, double tmax = kInfinity,
              double* t = nullptr) {
  double te = -1;
  const bool hit = intersect_slabs(b, o, reciprocal(d), tmin, tmax, te);
  if (t) *t = te;
  return hit;
}

TEST(Aabb, DefaultBox_IsEmptyAndGrows) {
  Aabb b;
  EXPECT_TRUE(b.is_empty());
  EXPECT_EQ(b.half_area(), 0);
  b.grow(Vec3{1, 2, 3});
  EXPECT_FALSE(b.is_empty());
  EXPECT_TRUE(b.contains({1, 2, 3}));
  b.grow(Aabb{{0, 0, 0}, {2, 2, 2}});
  EXPECT_EQ(b.lo, Vec3(0, 0, 0));
  EXPECT_EQ(b.hi, Vec3(2, 2, 3));
  EXPECT_EQ(b.half_area(), 2 * 2 + 2 * 3 + 3 * 2);
}

TEST(Aabb, EmptyBox_IsNeverHit) {
  EXPECT_FALSE(slab_hit(Aabb{}, {0, 0, 0}, {1, 0, 0}));
  EXPECT_FALSE(slab_hit(Aabb{}, {0, 0, 0}, {1, 1, 1}));
}

TEST(Aabb, RaysAlongEachAxis_EnterAtTheNearFace) {
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      Vec3 o, d;
      o[a] = -5 * s;
      d[a] = 2 * s;
      double t;
      ASSERT_TRUE(slab_hit(kCube, o, d, 0, kInfinity, &t)) << "axis " << a;
      EXPECT_EQ(t, 2);       // (5 - 1) / 2, in units of d
      o[(a + 1) % 3] = 1.5;  // shifted off the box
      EXPECT_FALSE(slab_hit(kCube, o, d)) << "axis " << a;
    }
}

TEST(Aabb, RayThroughEdgeOrCorner_Hits) {
  double t;
  ASSERT_TRUE(slab_hit(kCube, {-2, 0, 0}, {1, 1, 0}, 0, kInfinity, &t));  // edge (-1, 1, z)
  EXPECT_EQ(t, 1);
  ASSERT_TRUE(slab_hit(kCube, {-2, -2, -2}, {1, 1, 1}, 0, kInfinity, &t));  // corner, diagonal
  EXPECT_EQ(t, 1);
  ASSERT_TRUE(slab_hit(kCube, {2, 0, 1}, {-1, 1, 0}, 0, kInfinity, &t));  // touches (1, 1, 1) only
  EXPECT_EQ(t, 1);
  EXPECT_FALSE(slab_hit(kCube, {2, 0.01, 1}, {-1, 1, 0}));  // passes just outside the corner
}

TEST(Aabb, OriginOnFace_HitsAtZero) {
  double t;
  ASSERT_TRUE(slab_hit(kCube, {-1, 0, 0}, {1, 0, 0}, 0, kInfinity, &t));  // entering
  EXPECT_EQ(t, 0);
  ASSERT_TRUE(slab_hit(kCube, {1, 0, 0}, {1, 0, 0}, 0, kInfinity, &t));  // leaving: closed box
  EXPECT_EQ(t, 0);
  EXPECT_FALSE(slab_hit(kCube, {1, 0, 0}, {1, 0, 0}, 1e-9, kInfinity));
}

TEST(Aabb, OriginInside_EntryClippedToTmin) {
  double t;
  ASSERT_TRUE(slab_hit(kCube, {0, 0, 0}, {0, 0, 1}, 0, kInfinity, &t));
  EXPECT_EQ(t, 0);
  ASSERT_TRUE(slab_hit(kCube, {0, 0, 0}, {0, 0, 1}, 0.5, kInfinity, &t));
  EXPECT_EQ(t, 0.5);
}

TEST(Aabb, ZeroTimesInfinity_OnSlabPlaneLeavesAxisUnconstrained) {
  // The origin lies on the plane x = -1 and the ray is parallel to it: (lo.x - o.x) * (1 / 0)
  // is 0 * inf = NaN, which must not turn into a miss (nor into a hit off the box).
  for (double zero : {0.0, -0.0}) {
    EXPECT_TRUE(slab_hit(kCube, {-1, -5, 0}, {zero, 1, 0})) << zero;
    EXPECT_TRUE(slab_hit(kCube, {1, -5, 0}, {zero, 1, 0})) << zero;
    EXPECT_FALSE(slab_hit(kCube, {std::nextafter(-1.0, -2.0), -5, 0}, {zero, 1, 0})) << zero;
    EXPECT_FALSE(slab_hit(kCube, {std::nextafter(1.0, 2.0), -5, 0}, {zero, 1, 0})) << zero;
  }
  // A flat box (lo == hi on x) with the origin on it: both slab ends are NaN on that axis.
  const Aabb flat{{0, -1, -1}, {0, 1, 1}};
  EXPECT_TRUE(slab_hit(flat, {0, -5, 0}, {0, 1, 0}));
  double a = 0, b = 0;
  EXPECT_TRUE(slab_interval(kCube, {-1, -5, 0}, reciprocal(Vec3{0, 1, 0}), a, b));
  EXPECT_EQ(a, 4);
  EXPECT_EQ(b, 6);
}

TEST(Aabb, TminTmax_InclusiveAtBothEnds) {
  const Aabb b{{1, -1, -1}, {2, 1, 1}};
  const Vec3 o{0, 0, 0}, d{1, 0, 0};
  EXPECT_TRUE(slab_hit(b, o, d, 0, 1));  // tmax exactly at the entry
  EXPECT_FALSE(slab_hit(b, o, d, 0, std::nextafter(1.0, 0.0)));
  EXPECT_TRUE(slab_hit(b, o, d, 2, kInfinity));  // tmin exactly at the exit
  EXPECT_FALSE(slab_hit(b, o, d, 2.001, kInfinity));
  EXPECT_FALSE(slab_hit(b, o, d, -5, -0.5));  // segment entirely before the box
}

TEST(Aabb, SlabInterval_IsTheUnclippedWholeLine) {
  double a = 0, b = 0;
  ASSERT_TRUE(slab_interval(kCube, {0, 0, 0}, reciprocal(Vec3{0.5, 0, 0}), a, b));
  EXPECT_EQ(a, -2);
  EXPECT_EQ(b, 2);
  EXPECT_FALSE(slab_interval(kCube, {0, 3, 0}, reciprocal(Vec3{1, 0, 0}), a, b));
}

TEST(Aabb, RandomRays_AgreeWithPointSampling) {
  const unsigned seed = 101;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  const Aabb b{{-1, -0.5, -2}, {1.5, 0.5, 0.25}};
  for (int i = 0; i < 2000; ++i) {
    const Ray r = testing::random_ray(rng, 4, 2.5);
    double a, c;
    const bool hit = slab_interval(b, r.o, reciprocal(r.d), a, c);
    // The midpoint of a reported interval is inside; sampling finds no inside point otherwise.
    if (hit) {
      EXPECT_TRUE(b.contains(r.at(0.5 * (a + c)))) << "case " << i;
    } else {
      for (int k = 0; k <= 200; ++k) EXPECT_FALSE(b.contains(r.at(-20 + 0.2 * k))) << "case " << i;
    }
  }
}

TEST(Aabb, TransformBounds_ContainsEveryTransformedCorner) {
  const unsigned seed = 5;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  std::uniform_real_distribution<double> deg(-180, 180);
  for (int i = 0; i < 200; ++i) {
    const Transform xf = Transform::translate(rng.in_box(10)) *
                         Transform::rotate(rng.direction(), deg(rng)) *
                         Transform::scale({2, 0.5, 3});
    const Aabb tb = transform_bounds(xf, kCube);
    for (int c = 0; c < 8; ++c) {
      const Vec3 corner{c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, c & 4 ? 1.0 : -1.0};
      EXPECT_TRUE(tb.contains(xf.point(corner))) << "case " << i;
    }
  }
  // An unbounded box stays unbounded where the rotation mixes in the infinite axis.
  const Aabb half{{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, 0}};
  const Aabb r = transform_bounds(Transform::rotate({1, 0, 0}, 30), half);
  EXPECT_FALSE(r.is_bounded());
  EXPECT_EQ(r.lo.x, -kInfinity);
}

}  // namespace
}  // namespace raycast
