// The two-box test (accel/box_pair.h) against the slab test it vectorises: the same answer and
// the same entry, bit for bit, as intersect_slabs on each lane, and the SSE and scalar versions
// agree, on random boxes and rays, rays through corners and along faces, d = +-0 components,
// infinite box sides and an empty lane.
#include "accel/box_pair.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "corner_rays.h"
#include "support/random.h"

namespace raycast {
namespace {

// Checks both lanes of the pair of `a` and `b` against intersect_slabs.
void check(const Aabb& a, const Aabb& b, const Ray& ray, const char* what, int n) {
  const Vec3 inv = reciprocal(ray.d);
  BoxPair p;
  set_box_pair_lane(p, 0, a, ray_octant(inv));
  set_box_pair_lane(p, 1, b, ray_octant(inv));
  double t_simd[2], t_scalar[2];
  const unsigned mask = box_pair_hits(p, ray.o, inv, ray.tmin, ray.tmax, t_simd);
  const unsigned scalar = box_pair_hits_scalar(p, ray.o, inv, ray.tmin, ray.tmax, t_scalar);
  EXPECT_EQ(mask, scalar) << what << " " << n;
  for (int l = 0; l < 2; ++l) {
    double t_enter = 0;
    const bool exact = intersect_slabs(l == 0 ? a : b, ray.o, inv, ray.tmin, ray.tmax, t_enter);
    EXPECT_EQ(exact, (mask >> l & 1) != 0) << what << " " << n << " lane " << l;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(t_simd[l]), std::bit_cast<std::uint64_t>(t_scalar[l]))
        << what << " " << n << " lane " << l;
    if (exact) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(t_simd[l]), std::bit_cast<std::uint64_t>(t_enter))
          << what << " " << n << " lane " << l;
    }
  }
}

Aabb random_box(testing::Rng& rng, double scale) {
  const Vec3 c = rng.in_box(scale);
  const Vec3 h{rng.uniform(0, scale / 4), rng.uniform(0, scale / 4), rng.uniform(0, scale / 4)};
  return {c - h, c + h};
}

TEST(BoxPair, RandomBoxesAndRays_AreTheSlabTest) {
  testing::Rng rng(77);
  int passed = 0;
  for (double scale : {1e-3, 1.0, 1e3, 1e6}) {
    for (int n = 0; n < 4000; ++n) {
      const Aabb a = random_box(rng, scale), b = random_box(rng, scale);
      Ray ray = testing::random_ray(rng, 1.5 * scale, 0.5 * scale);
      if (n % 3 == 1) ray.tmax = rng.uniform(0, 1.5 * scale);
      if (n % 3 == 2) ray.tmin = rng.uniform(0, 0.5 * scale);
      check(a, b, ray, "random", n);
      double t;
      passed += intersect_slabs(a, ray.o, reciprocal(ray.d), ray.tmin, ray.tmax, t);
    }
  }
  EXPECT_GT(passed, 200);  // not vacuous (about 360 of the 16,000 pairs)
}

TEST(BoxPair, RaysThroughCornersAndAlongFaces_AreTheSlabTest) {
  testing::Rng rng(5);
  for (int n = 0; n < 4000; ++n) {
    const Aabb a = random_box(rng, 10), b = random_box(rng, 10);
    const Aabb& box = n % 2 ? a : b;
    // Aim at a corner, or slide along a face (testing::corner_ray).
    const Ray ray = testing::corner_ray(box, n >> 1 & 7, n, rng);
    check(a, b, ray, "corner", n);
  }
}

TEST(BoxPair, InfiniteSidesAndAnEmptyLane_AreTheSlabTest) {
  testing::Rng rng(13);
  for (int n = 0; n < 2000; ++n) {
    Aabb a = random_box(rng, 3);
    if (n % 3 == 0) a.lo.x = -kInfinity;
    if (n % 3 == 1) a.hi = {kInfinity, kInfinity, 1};
    Ray ray = testing::random_ray(rng, 6, 2);
    if (n % 4 == 0) ray.d.y = n % 8 ? 0.0 : -0.0;
    check(a, Aabb{}, ray, "infinite", n);  // the empty box: an odd set's last lane
    double t[2];
    BoxPair p;
    const Vec3 inv = reciprocal(ray.d);
    set_box_pair_lane(p, 0, Aabb{}, ray_octant(inv));
    set_box_pair_lane(p, 1, Aabb{}, ray_octant(inv));
    EXPECT_EQ(box_pair_hits(p, ray.o, inv, ray.tmin, ray.tmax, t), 0u) << n;
  }
}

}  // namespace
}  // namespace raycast
