// Noise: range, continuity, lattice values; turbulence's bounds.
#include <gtest/gtest.h>

#include <random>

#include "texture/noise.h"

namespace raycast::texture {
namespace {

TEST(Noise, RangeAndLatticeValue) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-50, 50);
  for (int g = 1; g <= 3; ++g) {
    double lo = 1, hi = 0;
    for (int i = 0; i < 20000; ++i) {
      const double n = noise({u(rng), u(rng), u(rng)}, g);
      ASSERT_GE(n, 0);
      ASSERT_LE(n, 1);
      lo = std::min(lo, n), hi = std::max(hi, n);
    }
    EXPECT_LT(lo, 0.2) << g;  // spread over the range, not stuck near 0.5
    EXPECT_GT(hi, 0.8) << g;
    EXPECT_EQ(noise({3, -4, 7}, g), 0.5);  // gradient noise is zero on the lattice
  }
}

TEST(Noise, IsContinuous) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-20, 20);
  for (int g : {2, 3})
    for (int i = 0; i < 2000; ++i) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      // Lipschitz: the gradients are bounded, so a step of 1e-6 changes little.
      EXPECT_NEAR(noise(p, g), noise(p + Vec3{1e-6, -1e-6, 1e-6}, g), 1e-5);
    }
}

TEST(Noise, DeterministicAndNotConstant) {
  EXPECT_EQ(noise({0.3, 0.7, 0.1}, 3), noise({0.3, 0.7, 0.1}, 3));
  EXPECT_NE(noise({0.3, 0.7, 0.1}, 3), noise({0.4, 0.7, 0.1}, 3));
  EXPECT_EQ(noise({NAN, 0, 0}, 3), 0.5);
  EXPECT_NE(noise({0.3, 0.7, 0.1}, 2), noise({0.3, 0.7, 0.1}, 3));
}

TEST(Turbulence, StaysWithinItsBounds) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-20, 20);
  Turbulence t;
  t.amount = {0.5, 1, 0};
  const double bound = (1 - std::pow(0.5, 6)) / 0.5;  // sum of omega^i
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 d = turbulence_offset(p, t, 2);
    EXPECT_LE(std::abs(d.x), 0.5 * bound + 1e-12);
    EXPECT_LE(std::abs(d.y), 1 * bound + 1e-12);
    EXPECT_EQ(d.z, 0);
    const double s = turbulence_value(p, 6, 0.5, 2, 3);
    EXPECT_GE(s, 0);
    EXPECT_LE(s, bound + 1e-12);
  }
}

}  // namespace
}  // namespace raycast::texture
