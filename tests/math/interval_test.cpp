#include "math/interval.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "math/dual.h"
#include "math/formula.h"

namespace raycast {
namespace {

// For random intervals and random points in them, every operation's result must contain the
// point result (the inclusion property).
TEST(Interval, RandomPoints_ContainedInInclusions) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20000; ++trial) {
    SCOPED_TRACE(trial);
    const double scale = std::pow(10.0, 3 * u(rng));
    double a0 = scale * u(rng), a1 = scale * u(rng), b0 = u(rng), b1 = u(rng);
    if (a0 > a1) std::swap(a0, a1);
    if (b0 > b1) std::swap(b0, b1);
    const Interval A{a0, a1}, B{b0, b1};
    const double s = 0.5 + 0.5 * u(rng), w = 0.5 + 0.5 * u(rng);
    const double x = a0 + s * (a1 - a0), y = b0 + w * (b1 - b0);
    EXPECT_TRUE((A + B).contains(x + y));
    EXPECT_TRUE((A - B).contains(x - y));
    EXPECT_TRUE((A * B).contains(x * y));
    if (!B.contains(0)) {
      EXPECT_TRUE((A / B).contains(x / y));
    }
    EXPECT_TRUE(sin(A).contains(std::sin(x)));
    EXPECT_TRUE(cos(A).contains(std::cos(x)));
    EXPECT_TRUE(exp(B).contains(std::exp(y)));
    EXPECT_TRUE(abs(A).contains(std::abs(x)));
    EXPECT_TRUE(min(A, B).contains(std::min(x, y)));
    EXPECT_TRUE(max(A, B).contains(std::max(x, y)));
    for (int n = 0; n <= 5; ++n) EXPECT_TRUE(pow_int(B, n).contains(pow_int(y, n))) << n;
    if (x > 0) {
      EXPECT_TRUE(sqrt(A).contains(std::sqrt(x)));
      EXPECT_TRUE(log(A).contains(std::log(x)));
    }
    const Interval tn = tan(A);
    if (!tn.is_empty()) {
      EXPECT_TRUE(tn.contains(std::tan(x)));
    }
  }
}

TEST(Interval, UlpSteps_MatchRepeatedNextafter) {
  const double inf = std::numeric_limits<double>::infinity();
  const double max = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double normal_min = std::numeric_limits<double>::min();
  std::vector<double> values = {0.0,        -0.0,        tiny,  -tiny,  2 * tiny, -3 * tiny,
                                normal_min, -normal_min, 1.0,   -1.0,   max,      -max,
                                inf,        -inf,        1e300, -1e-300};
  std::mt19937_64 rng(20261122);
  for (int i = 0; i < 2000; ++i) {
    const double v = std::bit_cast<double>(rng());
    if (!std::isnan(v)) values.push_back(v);
  }
  for (const double v : values)
    for (int ulps = 1; ulps <= 6; ++ulps) {
      double up = v, down = v;
      for (int i = 0; i < ulps; ++i) {
        up = std::nextafter(up, inf);
        down = std::nextafter(down, -inf);
      }
      // Compare values (a zero may come out as -0 or +0).
      EXPECT_EQ(interval_detail::up(v, ulps), up) << v << " " << ulps;
      EXPECT_EQ(interval_detail::down(v, ulps), down) << v << " " << ulps;
    }
  EXPECT_TRUE(std::isnan(interval_detail::up(std::nan(""), 3)));
  EXPECT_TRUE(std::isnan(interval_detail::down(std::nan(""), 3)));
}

TEST(Interval, HandComputedRanges) {
  const Interval c = cos(Interval{-0.5, 4.0});  // passes 0 and pi
  EXPECT_EQ(c.lo, -1);
  EXPECT_EQ(c.hi, 1);
  const Interval s = sin(Interval{0.1, 1.0});
  EXPECT_LE(s.lo, std::sin(0.1));
  EXPECT_GE(s.hi, std::sin(1.0));
  EXPECT_LT(s.hi, 0.85);
  EXPECT_TRUE(sqrt(Interval{-2, -1}).is_empty());
  EXPECT_TRUE(log(Interval{-2, 0}).is_empty());
  EXPECT_EQ(pow_int(Interval{-2, 1}, 2).lo, 0);
  EXPECT_TRUE((Interval{1, 2} / Interval{-1, 1}).contains(1e300));
  EXPECT_TRUE(tan(Interval{1, 2}).contains(1e300));  // the pole at pi / 2
  EXPECT_TRUE((Interval::empty() + Interval{1, 2}).is_empty());
}

TEST(Dual, Gradient_MatchesAnalytic) {
  const Formula f = compile_formula("sin(x) * y^2 + exp(z) - sqrt(x) / z + max(x, y) + pow(x, z)");
  const double x = 0.7, y = -1.3, z = 0.4;
  using D = Dual<double, 3>;
  D cx(x), cy(y), cz(z);
  cx.d[0] = cy.d[1] = cz.d[2] = 1;
  const D r = run<D>(f, cx, cy, cz);
  EXPECT_NEAR(r.v, std::sin(x) * y * y + std::exp(z) - std::sqrt(x) / z + x + std::pow(x, z),
              1e-14);
  EXPECT_NEAR(r.d[0], std::cos(x) * y * y - 0.5 / std::sqrt(x) / z + 1 + z * std::pow(x, z - 1),
              1e-13);
  EXPECT_NEAR(r.d[1], 2 * y * std::sin(x), 1e-14);
  EXPECT_NEAR(r.d[2], std::exp(z) + std::sqrt(x) / (z * z) + std::log(x) * std::pow(x, z), 1e-13);
}

TEST(Formula, IntervalRun_ContainsPointRuns) {
  const Formula f = compile_formula("(2 - cos(x)) cos(z) + (y + sin(x)) sin(z) + cos(x + z)");
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 2000; ++i) {
    const double x0 = u(rng), y0 = u(rng), z0 = u(rng), w = 0.1 * std::abs(u(rng));
    const Interval X{x0, x0 + w}, Y{y0, y0 + w}, Z{z0, z0 + w};
    const Interval F = run<Interval>(f, X, Y, Z);
    const double v = run<double>(f, x0 + w / 2, y0 + w / 3, z0 + w);
    EXPECT_TRUE(F.contains(v)) << i;
  }
}

TEST(Formula, ConstantsFoldedAndPrecedence) {
  EXPECT_NEAR(run<double>(compile_formula("2 pi - 2 * pi + e^2"), 0.0, 0.0, 0.0), std::exp(2.0),
              1e-14);
  EXPECT_EQ(run<double>(compile_formula("-x^2"), 3.0, 0.0, 0.0), -9);
  EXPECT_TRUE(std::isnan(run<double>(compile_formula("sqrt(x)"), -1.0, 0.0, 0.0)));
  EXPECT_THROW(compile_formula("foo(x)"), ExpressionError);
  EXPECT_THROW(compile_formula("sin x"), ExpressionError);
}

}  // namespace
}  // namespace raycast
