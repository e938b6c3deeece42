// atan2 and floor in formulas: their values, and inclusions over intervals and dual numbers that
// hold every point's value and derivative.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "math/formula.h"

namespace raycast {
namespace {

TEST(FormulaAtan2Floor, ValuesAreLibms) {
  const Formula a = compile_formula("atan2(y, x)"), f = compile_formula("floor(x) + floor(-y)");
  EXPECT_DOUBLE_EQ(run<double>(a, 1.0, 1.0, 0.0), std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(run<double>(a, -1.0, 0.0, 0.0), std::numbers::pi);
  EXPECT_DOUBLE_EQ(run<double>(f, 2.5, 0.5, 0.0), 1);
  EXPECT_FALSE(a.continuous);
  EXPECT_FALSE(f.continuous);
}

TEST(FormulaAtan2Floor, IntervalsHoldEverySample) {
  const Formula a = compile_formula("atan2(y, x)"), f = compile_formula("floor(3 x)");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2), w(0, 0.7);
  for (int i = 0; i < 2000; ++i) {
    const double x0 = u(rng), y0 = u(rng), dx = w(rng), dy = w(rng);
    const Interval X{x0, x0 + dx}, Y{y0, y0 + dy};
    const Interval A = run<Interval>(a, X, Y, Interval(0.0)), F = run<Interval>(f, X, Y, 0.0);
    for (int k = 0; k <= 4; ++k)
      for (int l = 0; l <= 4; ++l) {
        const double x = x0 + dx * k / 4, y = y0 + dy * l / 4;
        EXPECT_TRUE(A.contains(run<double>(a, x, y, 0.0))) << x << " " << y;
        EXPECT_TRUE(F.contains(run<double>(f, x, y, 0.0))) << x;
      }
  }
}

TEST(FormulaAtan2Floor, DerivativesMatchDifferencesAndStepsAreUnbounded) {
  using D = Dual<double, 3>;
  const Formula a = compile_formula("atan2(y, x)");
  D x(0.6), y(-0.8), z(0.0);
  x.d[0] = 1;
  y.d[1] = 1;
  const D r = run<D>(a, x, y, z);
  EXPECT_NEAR(r.d[0], 0.8, 1e-15);  // -y / (x^2 + y^2)
  EXPECT_NEAR(r.d[1], 0.6, 1e-15);  // x / (x^2 + y^2)
  using DI = Dual<Interval, 1>;
  const Formula f = compile_formula("floor(x)");
  DI across(Interval{0.5, 1.5}), flat(Interval{1.25, 1.5});
  across.d[0] = flat.d[0] = Interval(1.0);
  EXPECT_TRUE(run<DI>(f, across, DI(0.0), DI(0.0)).d[0].contains(1e300));
  EXPECT_EQ(run<DI>(f, flat, DI(0.0), DI(0.0)).d[0].hi, 0);
}

}  // namespace
}  // namespace raycast

namespace raycast {
namespace {

// A stand-in noise with a known slope: 0.5 + 0.25 sin(x + 2 y - z) (|partials| <= 0.5).
double wave(double x, double y, double z, int generator) {
  return 0.5 + 0.25 * std::sin(x + 2 * y - z) * (generator == 3 ? -1 : 1);
}

TEST(FormulaNoise, RegisteredNoiseIsIncludedOverIntervalsWithBoundedSlopes) {
  const FormulaNoise before = formula_noise();
  set_formula_noise({&wave, 0.5});
  const Formula f = compile_formula("noise2(x, y, z) - 0.5"), g = compile_formula("noise3(x,y,z)");
  EXPECT_DOUBLE_EQ(run<double>(f, 1.0, 0.0, 0.0), 0.25 * std::sin(1.0));
  EXPECT_DOUBLE_EQ(run<double>(g, 1.0, 0.0, 0.0), 0.5 - 0.25 * std::sin(1.0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 3), w(0, 0.5);
  for (int i = 0; i < 500; ++i) {
    const double x0 = u(rng), y0 = u(rng), z0 = u(rng), h = w(rng);
    using DI = Dual<Interval, 1>;
    DI X(Interval{x0, x0 + h}), Y(Interval{y0, y0 + h}), Z(Interval{z0, z0 + h});
    X.d[0] = Interval(1.0);  // the derivative along +x
    const DI r = run<DI>(f, X, Y, Z);
    for (int k = 0; k <= 3; ++k) {
      const double x = x0 + h * k / 3, y = y0 + h * (3 - k) / 3, z = z0 + h * k / 3;
      EXPECT_TRUE(r.v.contains(run<double>(f, x, y, z)));
      EXPECT_TRUE(r.d[0].contains(0.25 * std::cos(x + 2 * y - z)));
    }
  }
  set_formula_noise(before);
}

}  // namespace
}  // namespace raycast
