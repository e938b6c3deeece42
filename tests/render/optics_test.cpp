#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "render/optics.h"

namespace raycast {
namespace {

TEST(Fresnel, NormalIncidence_IsSquaredIndexRatio) {
  for (double n : {1.33, 1.5, 2.4}) {
    const double expected = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    EXPECT_NEAR(fresnel_dielectric(1, 1, n), expected, 1e-15) << n;
    EXPECT_NEAR(fresnel_dielectric(1, n, 1), expected, 1e-15) << n;  // the same from inside
  }
  EXPECT_NEAR(fresnel_dielectric(1, 1, 1.5), 0.04, 1e-15);
}

TEST(Fresnel, BrewsterAngle_OnlySPolarisationReflects) {
  const double n = 1.5;
  const double theta_b = std::atan(n);
  const double cos_i = std::cos(theta_b);
  const double cos_t = std::sin(theta_b);  // theta_i + theta_t = 90 degrees at Brewster's angle
  const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  EXPECT_NEAR(fresnel_dielectric(cos_i, 1, n), 0.5 * rs * rs, 1e-14);
}

TEST(Fresnel, BeyondCriticalAngle_IsOne) {
  const double critical = std::asin(1 / 1.5);
  EXPECT_EQ(fresnel_dielectric(std::cos(critical + 0.01), 1.5, 1), 1);
  EXPECT_LT(fresnel_dielectric(std::cos(critical - 0.01), 1.5, 1), 1);
  EXPECT_NEAR(fresnel_dielectric(0, 1, 1.5), 1, 1e-15);  // grazing from outside
}

TEST(Refract, BeyondCriticalAngle_ReportsTotalInternalReflection) {
  const double critical = std::asin(1 / 1.5);
  const Vec3 n{0, 0, -1};  // faces the incoming ray, which travels +z inside the glass
  Vec3 t;
  for (double theta : {critical + 1e-6, 1.2, 1.5}) {
    const Vec3 wi{std::sin(theta), 0, std::cos(theta)};
    EXPECT_FALSE(refract(wi, n, 1.5, t)) << theta;
  }
  const double theta = critical - 1e-6;
  EXPECT_TRUE(refract({std::sin(theta), 0, std::cos(theta)}, n, 1.5, t));
}

TEST(Refract, RandomDirections_ObeySnellsLaw) {
  const unsigned seed = 12345;
  SCOPED_TRACE(seed);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> angle(0, 0.5 * std::numbers::pi - 1e-3);
  std::uniform_real_distribution<double> phi(0, 2 * std::numbers::pi);
  const Vec3 n{0, 1, 0};
  for (int i = 0; i < 1000; ++i) {
    const double theta = angle(gen), p = phi(gen);
    const Vec3 wi{std::sin(theta) * std::cos(p), -std::cos(theta), std::sin(theta) * std::sin(p)};
    Vec3 t;
    ASSERT_TRUE(refract(wi, n, 1 / 1.5, t));
    EXPECT_NEAR(length(t), 1, 1e-14);
    const double sin_t = length(cross(t, n));
    EXPECT_NEAR(1.0 * std::sin(theta), 1.5 * sin_t, 1e-12);
    EXPECT_LT(dot(t, n), 0);                      // goes through the surface
    EXPECT_NEAR(dot(cross(wi, n), t), 0, 1e-12);  // stays in the plane of incidence
  }
}

TEST(Reflect, MirrorsAboutTheNormal) {
  const Vec3 r = reflect({1, -2, 3}, {0, 1, 0});
  EXPECT_EQ(r, (Vec3{1, 2, 3}));
}

TEST(IntegerPower, WithinItsErrorBoundOfPow_AndExactWhereThePowerIs) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (unsigned n : {1u, 2u, 3u, 7u, 20u, 40u, 120u, 200u, 1000u, 4096u}) {
    // (n + log2 n + 2) ulps relative (the bound of the header, plus pow's own ulp).
    const double tolerance = (n + std::log2(double(n)) + 2) * 0x1p-52;
    for (int k = 0; k < 2000; ++k) {
      const double x = unit(gen);
      const double expected = std::pow(x, double(n));
      if (expected < 1e-290) continue;  // subnormal results have no relative bound
      EXPECT_NEAR(integer_power(x, n), expected, tolerance * expected) << x << "^" << n;
    }
    EXPECT_EQ(integer_power(0.0, n), 0.0);
    EXPECT_EQ(integer_power(1.0, n), 1.0);
    EXPECT_EQ(integer_power(0.5, n), std::ldexp(1.0, -int(n)));  // powers of two are exact
    EXPECT_EQ(integer_power(-1.0, n), n % 2 ? -1.0 : 1.0);
  }
  EXPECT_EQ(integer_power(3.0, 5), 243.0);  // small integer results are exact
}

}  // namespace
}  // namespace raycast
