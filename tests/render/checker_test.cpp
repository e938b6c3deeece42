// The checker's cell parity (render/texture.cpp) against its definition: floor(x/s) + floor(y/s) +
// floor(z/s) summed in double, even -> c0, odd -> c1, anything not finite or from 2^53 up -> c0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "render/texture.h"

namespace raycast {
namespace {

Color by_definition(const CheckerTexture& t, const Vec3& p) {
  const double sum =
      std::floor(p.x / t.scale) + std::floor(p.y / t.scale) + std::floor(p.z / t.scale);
  if (!std::isfinite(sum) || std::abs(sum) >= 0x1p53) return t.c0;
  return std::fmod(std::abs(sum), 2) == 0 ? t.c0 : t.c1;
}

TEST(Checker, ParityEqualsTheFloorSumDefinition) {
  CheckerTexture t;
  t.c0 = {1, 0, 0};
  t.c1 = {0, 0, 1};
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Whole numbers and their neighbours, zeros of both signs, the 2^51 and 2^53 edges, huge,
  // infinite and NaN values.
  std::vector<double> edges = {0.0,    -0.0,    0.5,    -0.5,     1.0,       -1.0,
                               3.0,    -3.0,    0x1p51, -0x1p51,  0x1p52,    -0x1p52,
                               0x1p53, -0x1p53, 0x1p60, -0x1p60,  1e300,     -1e300,
                               inf,    -inf,    nan,    4.9e-324, -4.9e-324, 2.2e-308};
  for (const double e : std::vector<double>(edges)) {
    edges.push_back(std::nextafter(e, inf));
    edges.push_back(std::nextafter(e, -inf));
  }
  for (const double scale : {1.0, 0.5, 0.3, 2.0, 7.25, 1e-300}) {
    t.scale = scale;
    for (const double x : edges)
      for (const double y : edges)
        for (const double z : {0.0, -0.0, 1.0, -2.5, 0x1p51, -0x1p52, 0x1p53, nan}) {
          const Vec3 p{x, y, z};
          const Color got = checker(t, p), want = by_definition(t, p);
          ASSERT_EQ(got.x, want.x) << x << " " << y << " " << z << " scale " << scale;
          ASSERT_EQ(got.z, want.z) << x << " " << y << " " << z << " scale " << scale;
        }
  }
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> exponent(-20, 60), unit(-1, 1);
  for (int i = 0; i < 200000; ++i) {
    t.scale = std::exp2(exponent(rng) / 4);
    const Vec3 p{unit(rng) * std::exp2(exponent(rng)), unit(rng) * std::exp2(exponent(rng)),
                 unit(rng) * std::exp2(exponent(rng))};
    const Color got = checker(t, p), want = by_definition(t, p);
    ASSERT_EQ(got.x, want.x) << p.x << " " << p.y << " " << p.z << " scale " << t.scale;
  }
}

}  // namespace
}  // namespace raycast
