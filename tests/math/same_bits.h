#pragma once
// Bit-for-bit comparison of doubles for tests of exact fast paths (any NaN matches any NaN:
// payloads are not the engine's concern), and the special values such tests draw inputs from.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <random>

#include "math/vec3.h"

namespace raycast {

inline void expect_same_bits(double a, double b, const char* what) {
  if (std::isnan(a) && std::isnan(b)) return;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b))
      << what << ": " << a << " vs " << b;
}

inline void expect_same_bits(const Vec3& a, const Vec3& b, const char* what) {
  expect_same_bits(a.x, b.x, what);
  expect_same_bits(a.y, b.y, what);
  expect_same_bits(a.z, b.z, what);
}

/// One of +-0, +-1, 0.45, -3.5, +-1e-310 (subnormal), +-1e300, +-inf and NaN.
inline double special_double(std::mt19937_64& rng) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double values[] = {0.0,
                               -0.0,
                               1.0,
                               -1.0,
                               0.45,
                               -3.5,
                               1e-310,
                               -1e-310,
                               1e300,
                               -1e300,
                               inf,
                               -inf,
                               std::numeric_limits<double>::quiet_NaN()};
  return values[std::uniform_int_distribution<int>(0, int(std::size(values)) - 1)(rng)];
}

}  // namespace raycast
