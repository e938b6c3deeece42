// The float four-box test (accel/box4.h) against the double slab test it stands in for: it must
// pass every box the double test passes (it is a conservative cull), and pass few others; the SSE
// and scalar versions agree bit for bit.
#include "accel/box4.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "corner_rays.h"
#include "support/random.h"

namespace raycast {
namespace {

struct Case {
  std::vector<Aabb> boxes;  // four
  Ray ray;
};

Box4 pack(const std::vector<Aabb>& boxes) {
  Box4 b;
  for (int l = 0; l < 4; ++l) set_box4_lane(b, l, boxes[std::size_t(l)]);
  return b;
}

Box4Scale scale_of(const Box4& b) {
  double m[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a)
    for (int row : {a, 3 + a})
      for (float p : b.plane[row])
        if (std::isfinite(p)) m[a] = std::max(m[a], double(std::abs(p)));
  return make_box4_scale(m);
}

// Checks the float test against intersect_slabs on each lane; returns how many lanes the float
// test passed that the double test did not.
int check(const std::vector<Aabb>& boxes, const Ray& ray, const char* what, int n) {
  const Box4 b = pack(boxes);
  const Vec3 inv = reciprocal(ray.d);
  const Box4Ray r = make_box4_ray(ray, inv, scale_of(b));
  const float tmax_up = float_up(ray.tmax);
  alignas(16) float t_simd[4], t_scalar[4];
  const unsigned mask = box4_hits(b, r, tmax_up, t_simd);
  const unsigned scalar = box4_hits_scalar(b, r, tmax_up, t_scalar);
  EXPECT_EQ(mask, scalar) << what << " " << n;
  int extra = 0;
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(t_simd[l]), std::bit_cast<std::uint32_t>(t_scalar[l]))
        << what << " " << n << " lane " << l;
    double t_enter;
    const bool exact =
        intersect_slabs(boxes[std::size_t(l)], ray.o, inv, ray.tmin, ray.tmax, t_enter);
    const bool passed = (mask >> l & 1) != 0;
    if (exact) {
      EXPECT_TRUE(passed) << what << " " << n << " lane " << l;
      // The entry it reports may order the box before a lowered tmax: never after the exact one.
      if (passed) {
        EXPECT_TRUE(box4_enters_before(t_simd[l], float_up(t_enter))) << what << " " << n;
      }
    }
    extra += passed && !exact;
  }
  return extra;
}

std::vector<Aabb> random_boxes(testing::Rng& rng, double scale) {
  std::vector<Aabb> boxes;
  for (int l = 0; l < 4; ++l) {
    const Vec3 c = rng.in_box(scale);
    const Vec3 h{rng.uniform(0, scale / 4), rng.uniform(0, scale / 4), rng.uniform(0, scale / 4)};
    boxes.push_back({c - h, c + h});
  }
  return boxes;
}

TEST(Box4, RandomBoxesAndRays_PassEveryBoxTheDoubleTestPasses) {
  testing::Rng rng(77);
  int extra = 0, total = 0;
  for (double scale : {1e-3, 1.0, 1e3, 1e6}) {
    for (int n = 0; n < 4000; ++n) {
      const std::vector<Aabb> boxes = random_boxes(rng, scale);
      Ray ray = testing::random_ray(rng, 1.5 * scale, 0.5 * scale);
      if (n % 3 == 1) ray.tmax = rng.uniform(0, 1.5 * scale);
      if (n % 3 == 2) ray.tmin = rng.uniform(0, 0.5 * scale);
      extra += check(boxes, ray, "random", n);
      total += 4;
    }
  }
  // Conservative, not vacuous: the boxes it passes beyond the double test's are rare.
  EXPECT_LT(extra, total / 200);
}

TEST(Box4, RaysThroughCornersAndAlongFaces_Pass) {
  testing::Rng rng(5);
  for (int n = 0; n < 4000; ++n) {
    const std::vector<Aabb> boxes = random_boxes(rng, 10);
    const Aabb& b = boxes[std::size_t(n % 4)];
    // Aim at a corner, or slide along a face (testing::corner_ray).
    const Ray ray = testing::corner_ray(b, n & 7, n, rng);
    check(boxes, ray, "corner", n);
  }
}

TEST(Box4, AxisParallelRays_PassOnlyBoxesOnTheirLine) {
  testing::Rng rng(9);
  int passed_outside = 0;
  for (int n = 0; n < 3000; ++n) {
    const std::vector<Aabb> boxes = random_boxes(rng, 5);
    Ray ray;
    ray.o = rng.in_box(8);
    const int a = n % 3;
    ray.d = {0, 0, 0};
    ray.d[a] = n % 2 ? 1.0 : -2.0;
    if (n % 4 == 0) ray.o[(a + 1) % 3] = boxes[0].lo[(a + 1) % 3];  // on a slab plane
    check(boxes, ray, "parallel", n);
    // An axis with d = 0 constrains nothing in the float test (conservative), but the others do:
    // a box beside the ray on two axes is rejected unless the ray runs along one of them.
    const Box4 b = pack(boxes);
    alignas(16) float t[4];
    const unsigned mask =
        box4_hits(b, make_box4_ray(ray, reciprocal(ray.d), scale_of(b)), float_up(ray.tmax), t);
    for (int l = 0; l < 4; ++l) {
      double te;
      passed_outside += (mask >> l & 1) && !intersect_slabs(boxes[std::size_t(l)], ray.o,
                                                            reciprocal(ray.d), 0, kInfinity, te);
    }
  }
  EXPECT_GT(passed_outside, 0);  // the documented cost of d = 0 axes, seen at least once
}

TEST(Box4, UnusualRays_PassEveryBox) {
  testing::Rng rng(11);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int n = 0; n < 400; ++n) {
    const std::vector<Aabb> boxes = random_boxes(rng, 2);
    Ray ray = testing::random_ray(rng, 4, 1);
    switch (n % 5) {
      case 0:
        ray.d.x = nan;
        break;
      case 1:
        ray.d = {kInfinity, 1, 1};
        break;
      case 2:
        ray.tmin = -1;
        break;  // a negative tmin: every box passes
      case 3:
        ray.d = ray.d * 1e-120;
        break;
      case 4:
        ray.o.y = 1e120;
        break;
    }
    const Box4 b = pack(boxes);
    alignas(16) float t[4];
    const Box4Ray r = make_box4_ray(ray, reciprocal(ray.d), scale_of(b));
    const unsigned mask = box4_hits(b, r, float_up(ray.tmax), t);
    if (n % 5 == 2) {
      EXPECT_EQ(mask, 0xFu) << n;
    }
    check(boxes, ray, "unusual", n);
  }
}

TEST(Box4, HugeAndInfiniteBoxSides_AreConservative) {
  testing::Rng rng(13);
  for (int n = 0; n < 2000; ++n) {
    std::vector<Aabb> boxes = random_boxes(rng, 3);
    boxes[0].lo.x = -1e200;  // beyond float: stored as infinite
    boxes[1].hi.y = 1e35;
    boxes[2].lo = {-kInfinity, -1, -1};
    check(boxes, testing::random_ray(rng, 6, 2), "huge", n);
  }
}

TEST(Box4, FloatRounding_GoesOutwards) {
  for (double x : {0.0, -0.0, 1e-46, -1e-46, 0.1, -0.1, 1.0 / 3, 3e38, -3e38, 1e39, -1e39,
                   kInfinity, -kInfinity}) {
    EXPECT_LE(double(float_down(x)), x) << x;
    EXPECT_GE(double(float_up(x)), x) << x;
  }
  // The steps are one float: nothing representable lies strictly between x and its bound.
  testing::Rng rng(3);
  for (int n = 0; n < 2000; ++n) {
    const double x = rng.uniform(-1, 1) * std::pow(10.0, rng.uniform(-40, 38));
    EXPECT_GT(double(std::nextafter(float_down(x), INFINITY)), x) << x;
    EXPECT_LT(double(std::nextafter(float_up(x), -INFINITY)), x) << x;
  }
}

}  // namespace
}  // namespace raycast
