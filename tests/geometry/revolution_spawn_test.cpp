// Secondary rays leaving a surface of revolution must not find that surface again at once
// (the shadow-acne speckles the vase scene showed before p_error covered the root's error).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/revolution.h"
#include "geometry/spawn.h"
#include "support/random.h"

namespace raycast {
namespace {

// Counts rays spawned into the outer hemisphere at random hits that hit the surface again
// closer than `near` (a tiny fraction of the shape's size).
int count_rehits(const Revolution& shape, unsigned seed) {
  testing::Rng rng(seed);
  constexpr double kNear = 1e-7;
  int rehits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 target{0, 0, std::uniform_real_distribution<double>(0.1, 2.9)(rng)};
    const Vec3 o = target + 6.0 * rng.direction();
    const Ray ray{o, target - o};
    LocalHit hit;
    if (!intersect(shape, ray, hit)) continue;
    const SurfaceInfo si = surface(shape, ray, hit);
    Vec3 w = rng.direction();
    if (dot(w, si.n) < 0) w = -w;
    const Ray out{offset_ray_origin(si, w), w};
    LocalHit again;
    if (intersect(shape, out, again) && again.t < kNear) ++rehits;
  }
  return rehits;
}

TEST(RevolutionSpawn, BSplineVase_SpawnedRaysDoNotRehit) {
  const std::vector<std::array<double, 2>> profile = {
      {0, 0},     {0, 0},     {0, 0},     {0.8, 0},   {1.2, 0.6},
      {0.5, 1.6}, {0.4, 2.4}, {0.8, 3.0}, {0.8, 3.0}, {0.8, 3.0}};
  const Revolution vase = make_revolution(profile, ProfileCurve::kBSpline, true);
  SCOPED_TRACE("seed 7");
  EXPECT_EQ(count_rehits(vase, 7), 0);
}

TEST(RevolutionSpawn, LinearGoblet_SpawnedRaysDoNotRehit) {
  const std::vector<std::array<double, 2>> profile = {
      {0, 0}, {0.7, 0}, {0.7, 0.1}, {0.1, 0.3}, {0.1, 1.2}, {0.8, 1.6}, {0.9, 2.4}};
  const Revolution goblet = make_revolution(profile, ProfileCurve::kLinear, true);
  SCOPED_TRACE("seed 11");
  EXPECT_EQ(count_rehits(goblet, 11), 0);
}

}  // namespace
}  // namespace raycast
