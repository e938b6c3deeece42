#include "math/quadratic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace raycast {
namespace {

TEST(Quadratic, TwoRoots_ReturnsThemInOrder) {
  double t0, t1;
  ASSERT_EQ(solve_quadratic(1, -3, 2, t0, t1), 2);
  EXPECT_EQ(t0, 1);
  EXPECT_EQ(t1, 2);
  ASSERT_EQ(solve_quadratic(-2, 6, -4, t0, t1), 2);  // same roots, negative leading coefficient
  EXPECT_EQ(t0, 1);
  EXPECT_EQ(t1, 2);
}

TEST(Quadratic, NoRealRoots_ReturnsZero) {
  double t0 = 7, t1 = 7;
  EXPECT_EQ(solve_quadratic(1, 0, 1, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(1, 1, 1, t0, t1), 0);
}

TEST(Quadratic, DoubleRoot_ReportedTwiceAsEqual) {
  double t0, t1;
  ASSERT_EQ(solve_quadratic(1, -6, 9, t0, t1), 2);
  EXPECT_EQ(t0, 3);
  EXPECT_EQ(t1, 3);
  ASSERT_EQ(solve_quadratic(5, 0, 0, t0, t1), 2);
  EXPECT_EQ(t0, 0);
  EXPECT_EQ(t1, 0);
}

TEST(Quadratic, SmallRootNextToLargeOne_HasNoCancellation) {
  // t^2 - 1e8 t + 1 = 0: the naive formula loses about half the digits of the small root.
  double t0, t1;
  ASSERT_EQ(solve_quadratic(1, -1e8, 1, t0, t1), 2);
  const long double exact_small = 2.0L / (1e8L + std::sqrt(1e16L - 4.0L));
  EXPECT_NEAR(t0, static_cast<double>(exact_small), 1e-15 * 1e-8);
  EXPECT_NEAR(t1, 1e8, 1e-15 * 1e8);
  ASSERT_EQ(solve_quadratic(1, 1e8, 1, t0, t1), 2);  // mirrored: both roots negative
  EXPECT_NEAR(t1, -static_cast<double>(exact_small), 1e-15 * 1e-8);
  EXPECT_NEAR(t0, -1e8, 1e-15 * 1e8);
}

TEST(Quadratic, NearlyDoubleRoot_DiscriminantKeptExactByFma) {
  // (t - 1)(t - (1 + 2^-30)): b^2 needs 62 bits, so b*b - 4ac rounds to 0 without the fma.
  const double e = std::ldexp(1.0, -30);
  double t0, t1;
  ASSERT_EQ(solve_quadratic(1, -(2 + e), 1 + e, t0, t1), 2);
  EXPECT_EQ(t0, 1);
  EXPECT_EQ(t1, 1 + e);
}

TEST(Quadratic, ZeroLeadingCoefficient_SolvesTheLinearEquation) {
  double t0, t1;
  ASSERT_EQ(solve_quadratic(0, 2, 4, t0, t1), 1);
  EXPECT_EQ(t0, -2);
  EXPECT_EQ(t1, -2);
  EXPECT_EQ(solve_quadratic(0, 0, 4, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(0, 0, 0, t0, t1), 0);
}

TEST(Quadratic, NonFiniteInput_ReturnsZero) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  double t0, t1;
  EXPECT_EQ(solve_quadratic(nan, 1, 1, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(1, nan, 1, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(1, 1, nan, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(inf, 1, 1, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(1, -inf, 1, t0, t1), 0);
  EXPECT_EQ(solve_quadratic(0, 1e-320, 1e300, t0, t1), 0);  // the linear root overflows
}

// Pinned bug: with coefficients near 1e300, b^2 and 4ac overflowed and the roots came out NaN.
TEST(Quadratic, HugeCoefficients_NoOverflow) {
  double t0, t1;
  ASSERT_EQ(solve_quadratic(1e300, -3e300, 2e300, t0, t1), 2);
  EXPECT_NEAR(t0, 1, 1e-15);
  EXPECT_NEAR(t1, 2, 1e-15);
  ASSERT_EQ(solve_quadratic(1e-300, -3e-300, 2e-300, t0, t1), 2);
  EXPECT_NEAR(t0, 1, 1e-15);
  EXPECT_NEAR(t1, 2, 1e-15);
}

TEST(Quadratic, RandomRoots_RecoveredToRoundingError) {
  const unsigned seed = 20261122;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> root(-100, 100), scale(-3, 3);
  for (int i = 0; i < 10000; ++i) {
    const double r0 = root(rng), r1 = root(rng) * std::pow(10.0, scale(rng));
    const double a = std::pow(10.0, scale(rng));
    // Coefficients of a (t - r0)(t - r1), with their rounding; the roots move by at most the
    // coefficients' relative error over the roots' separation (condition of the problem).
    const double b = -a * (r0 + r1), c = a * r0 * r1;
    double t0, t1;
    ASSERT_EQ(solve_quadratic(a, b, c, t0, t1), 2) << r0 << " " << r1;
    const double lo = std::min(r0, r1), hi = std::max(r0, r1);
    const double sep = std::max(hi - lo, 1e-300);
    const double tol =
        1e-13 * (std::abs(lo) + std::abs(hi)) * (1 + (std::abs(lo) + std::abs(hi)) / sep);
    EXPECT_NEAR(t0, lo, tol) << "case " << i;
    EXPECT_NEAR(t1, hi, tol) << "case " << i;
  }
}

}  // namespace
}  // namespace raycast

namespace raycast {
namespace {

// solve_quadratic's power-of-two scaling by bits against frexp/ldexp (its slow path): the same
// roots, bit for bit, over coefficients from 2^-1070 to 2^1020 with either sign.
TEST(Quadratic, ScalingByBits_MatchesFrexpLdexp) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> ex(-1070, 1020), sign(0, 1), zero(0, 9);
  std::uniform_real_distribution<double> mant(0.5, 1);
  auto coefficient = [&]() {
    if (zero(rng) == 0) return 0.0;
    const double x = std::ldexp(mant(rng), ex(rng));
    return sign(rng) ? -x : x;
  };
  // The solver as it was written with frexp and ldexp.
  auto reference = [](double a, double b, double c, double& t0, double& t1) {
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return 0;
    if (a == 0) {
      if (b == 0) return 0;
      t0 = t1 = -c / b;
      return std::isfinite(t0) ? 1 : 0;
    }
    int e;
    std::frexp(std::max({std::abs(a), std::abs(b), std::abs(c)}), &e);
    a = std::ldexp(a, -e);
    b = std::ldexp(b, -e);
    c = std::ldexp(c, -e);
    const double four_ac = 4 * a * c;
    const double err = std::fma(-4 * a, c, four_ac);
    const double disc = std::fma(b, b, -four_ac) + err;
    if (disc < 0) return 0;
    const double root = std::sqrt(disc);
    const double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
    if (q == 0) {
      t0 = t1 = 0;
      return 2;
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return 2;
  };
  int solved = 0;
  for (int i = 0; i < 200000; ++i) {
    double a = coefficient(), b = coefficient(), c = coefficient();
    if (i % 3 == 0) {  // close exponents: real roots are common
      b = std::ldexp(mant(rng), std::ilogb(a == 0 ? 1.0 : a) + 1) * (sign(rng) ? 1 : -1);
      c = a * mant(rng) * (sign(rng) ? 1 : -1);
    }
    if (a == 0) continue;
    double t0 = 0, t1 = 0, r0 = 0, r1 = 0;
    const int n = solve_quadratic(a, b, c, t0, t1);
    ASSERT_EQ(n, reference(a, b, c, r0, r1)) << a << " " << b << " " << c;
    if (n == 0) continue;
    ++solved;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(t0), std::bit_cast<std::uint64_t>(r0));
    ASSERT_EQ(std::bit_cast<std::uint64_t>(t1), std::bit_cast<std::uint64_t>(r1));
  }
  EXPECT_GT(solved, 30000);
}

}  // namespace
}  // namespace raycast
