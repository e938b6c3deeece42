#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "math/float_error.h"
#include "math/polynomial.h"
#include "math/polynomial_solver.h"

namespace raycast {
namespace {

// The monic polynomial with the given roots, scaled by `scale`, expanded in long double.
Polynomial from_roots(const std::vector<double>& r, double scale = 1) {
  std::vector<long double> c{1.0L};
  for (double x : r) {
    std::vector<long double> n(c.size() + 1, 0.0L);
    for (std::size_t i = 0; i < c.size(); ++i) {
      n[i + 1] += c[i];
      n[i] -= c[i] * x;
    }
    c = n;
  }
  Polynomial p;
  p.degree = static_cast<int>(r.size());
  for (std::size_t i = 0; i < c.size(); ++i) p.c[i] = static_cast<double>(c[i] * scale);
  return p;
}

// Whether r is a root of p as far as double evaluation can tell: |p(r)|, computed in long
// double, within a few times the running error bound of evaluating p(r) in double. That is the
// best any double-precision solver can do on an ill-conditioned root.
bool within_rounding(const Polynomial& p, double r) {
  long double f = 0;
  for (int i = p.degree; i >= 0; --i) f = f * r + p.c[i];
  double err;
  evaluate(p, r, err);
  return std::abs(static_cast<double>(f)) <= 4 * err;
}

std::vector<double> solve(const Polynomial& p, double lo = -kInfinity, double hi = kInfinity) {
  double r[kMaxPolynomialDegree];
  const int n = find_real_roots(p, lo, hi, r);
  return {r, r + n};
}

TEST(Polynomial, Horner_EvaluatesAndBoundsError) {
  const Polynomial p = from_roots({1, 2, 3});
  double err;
  EXPECT_EQ(evaluate(p, 4.0, err), 6.0);
  EXPECT_GT(err, 0);
  EXPECT_LT(err, 1e-12);
  double d;
  evaluate(p, 4.0, d, err);
  EXPECT_EQ(d, 3 * 16 - 12 * 4 + 11);
}

TEST(Polynomial, DerivativeDeflateShift_MatchHandComputed) {
  const Polynomial p = from_roots({1, 2, 3});  // t^3 - 6t^2 + 11t - 6
  const Polynomial d = derivative(p);
  EXPECT_EQ(d.degree, 2);
  EXPECT_EQ(d.c[0], 11);
  EXPECT_EQ(d.c[1], -12);
  EXPECT_EQ(d.c[2], 3);
  const Polynomial q = deflate(p, 1);  // (t - 2)(t - 3)
  EXPECT_EQ(q.degree, 2);
  EXPECT_EQ(q.c[0], 6);
  EXPECT_EQ(q.c[1], -5);
  const Polynomial s = shifted(p, 1);  // roots 0, 1, 2
  EXPECT_EQ(evaluate(s, 0.0), 0);
  EXPECT_EQ(evaluate(s, 2.0), 0);
  EXPECT_EQ(evaluate(s, 3.0), 6);
}

TEST(PolynomialSolver, LinearAndConstant_HandComputed) {
  Polynomial p;
  p.degree = 1;
  p.c = {-3, 2};
  ASSERT_EQ(solve(p), std::vector<double>{1.5});
  EXPECT_TRUE(solve(p, 2, 3).empty());
  Polynomial zero;
  zero.degree = 4;
  EXPECT_TRUE(solve(zero).empty());
}

TEST(PolynomialSolver, NoRealRoots_ReturnsNone) {
  Polynomial p;
  p.degree = 4;
  p.c = {1, 0, 2, 0, 1};  // (t^2 + 1)^2
  EXPECT_TRUE(solve(p).empty());
}

TEST(PolynomialSolver, RandomRootsDegree1To12_FoundToRelative1e9) {
  for (int degree = 1; degree <= 12; ++degree) {
    for (int trial = 0; trial < 200; ++trial) {
      const unsigned seed = degree * 1000 + trial;
      SCOPED_TRACE(testing::Message() << "seed " << seed);
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> u(-10, 10);
      std::vector<double> r(degree);
      for (double& x : r) x = u(rng);
      std::sort(r.begin(), r.end());
      // Keep the roots apart so that the expected accuracy holds for every one.
      bool apart = true;
      for (int i = 1; i < degree; ++i) apart = apart && r[i] - r[i - 1] > 0.3;
      if (!apart) continue;
      const auto got = solve(from_roots(r, u(rng)));
      ASSERT_EQ(got.size(), r.size());
      for (int i = 0; i < degree; ++i)
        EXPECT_NEAR(got[i], r[i], 1e-9 * std::max(1.0, std::abs(r[i])));
    }
  }
}

TEST(PolynomialSolver, Wilkinson12_AllRootsFound) {
  std::vector<double> r;
  for (int i = 1; i <= 12; ++i) r.push_back(i);
  const Polynomial p = from_roots(r);
  const auto got = solve(p);
  ASSERT_EQ(got.size(), 12u);
  for (int i = 0; i < 12; ++i) {
    // Evaluating p in double is only good to ~1e-9 relative near the middle roots, so the roots
    // are as exact as p's values can tell, and near the integers.
    EXPECT_NEAR(got[i], i + 1, 1e-7 * (i + 1));
    EXPECT_TRUE(within_rounding(p, got[i])) << got[i];
  }
}

TEST(PolynomialSolver, ClusteredRoots_AllSeparated) {
  // As close as double coefficients can still tell them apart (the cluster's values between its
  // roots must exceed the rounding of the coefficients).
  for (const std::vector<double>& r : {std::vector<double>{1.0, 1.01, 1.02, 1.03, 1.04},
                                       std::vector<double>{-1.0, 2.0, 2.0001, 2.0002, 7.0}}) {
    const Polynomial p = from_roots(r);
    const auto got = solve(p);
    ASSERT_EQ(got.size(), r.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
      EXPECT_NEAR(got[i], r[i], 1e-6);
      EXPECT_TRUE(within_rounding(p, got[i])) << got[i];
    }
  }
}

TEST(PolynomialSolver, MultipleRoots_ReportedOnceAndAccurate) {
  for (int k = 2; k <= 8; ++k) {
    SCOPED_TRACE(k);
    const std::vector<double> r(k, 0.75);  // exact in binary: the expanded coefficients are exact
    const auto got = solve(from_roots(r));
    ASSERT_EQ(got.size(), 1u);
    EXPECT_NEAR(got[0], 0.75, 1e-12);
  }
  // A double root next to simple ones.
  const auto got = solve(from_roots({-2, 0.5, 0.5, 3}));
  ASSERT_EQ(got.size(), 3u);
  EXPECT_NEAR(got[0], -2, 1e-12);
  EXPECT_NEAR(got[1], 0.5, 1e-12);
  EXPECT_NEAR(got[2], 3, 1e-12);
}

TEST(PolynomialSolver, NearlyDoubleRoot_BothFound) {
  const auto got = solve(from_roots({1.0, 1.0 + 1e-6, 5.0}));
  ASSERT_EQ(got.size(), 3u);
  // Rounding the coefficients to double alone moves these roots by ~1e-15 / |p'| ~ 3e-10.
  EXPECT_NEAR(got[0], 1.0, 1e-9);
  EXPECT_NEAR(got[1], 1.0 + 1e-6, 1e-9);
}

TEST(PolynomialSolver, HugeAndTinyCoefficients_ScaledAway) {
  for (double scale : {1e-250, 1e-100, 1.0, 1e100, 1e250}) {
    SCOPED_TRACE(scale);
    const auto got = solve(from_roots({-3, 1, 2}, scale));
    ASSERT_EQ(got.size(), 3u);
    EXPECT_NEAR(got[0], -3, 1e-12);
    EXPECT_NEAR(got[2], 2, 1e-12);
  }
  // Roots spread over 16 orders of magnitude.
  const auto got = solve(from_roots({1e-8, 1.0, 1e8}));
  ASSERT_EQ(got.size(), 3u);
  EXPECT_NEAR(got[0], 1e-8, 1e-17);
  EXPECT_NEAR(got[1], 1.0, 1e-9);
  EXPECT_NEAR(got[2], 1e8, 1e-1);
  // Huge roots: t^4 alone would overflow without scaling the variable.
  const auto big = solve(from_roots({-3e70, 1e70, 2e70, 4e70}));
  ASSERT_EQ(big.size(), 4u);
  EXPECT_NEAR(big[3], 4e70, 1e61);
}

TEST(PolynomialSolver, VanishingLeadingCoefficient_KeepsOrdinaryRoots) {
  Polynomial p;
  p.degree = 4;
  p.c = {-2, 1, 0, 0, 1e-30};  // t - 2 plus a negligible quartic term
  const auto got = solve(p, -10, 10);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_NEAR(got[0], 2, 1e-12);
  const auto all = solve(p);
  ASSERT_EQ(all.size(), 2u);  // the second root is near -(1e30)^(1/3)
  EXPECT_NEAR(all[0], -std::cbrt(1e30), 1e-3 * std::cbrt(1e30));
}

TEST(PolynomialSolver, Interval_RootsOutsideIgnoredAndEndsIncluded) {
  const Polynomial p = from_roots({-1, 0, 1, 2});
  EXPECT_EQ(solve(p, -0.5, 1.5), (std::vector<double>{0, 1}));
  EXPECT_EQ(solve(p, 0, 1), (std::vector<double>{0, 1}));
  EXPECT_TRUE(solve(p, 0.25, 0.75).empty());
  EXPECT_TRUE(solve(p, 1, 0).empty());
  EXPECT_TRUE(solve(p, std::nan(""), 1).empty());
}

TEST(PolynomialSolver, NonFiniteCoefficients_ReturnNone) {
  Polynomial p = from_roots({1, 2});
  p.c[1] = std::nan("");
  EXPECT_TRUE(solve(p).empty());
  p.c[1] = kInfinity;
  EXPECT_TRUE(solve(p).empty());
}

TEST(Cubic, ThreeAndOneRealRoots_HandComputed) {
  double r[3];
  ASSERT_EQ(solve_cubic(1, -6, 11, -6, r), 3);
  EXPECT_NEAR(r[0], 1, 1e-14);
  EXPECT_NEAR(r[1], 2, 1e-14);
  EXPECT_NEAR(r[2], 3, 1e-14);
  ASSERT_EQ(solve_cubic(2, 0, 2, -4, r), 1);  // 2(t - 1)(t^2 + t + 2)
  EXPECT_NEAR(r[0], 1, 1e-14);
  ASSERT_EQ(solve_cubic(0, 1, -3, 2, r), 2);  // a quadratic
  EXPECT_NEAR(r[1], 2, 1e-14);
}

TEST(Cubic, RandomRoots_MatchIsolatingSolver) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 2000; ++trial) {
    SCOPED_TRACE(trial);
    std::vector<double> r{u(rng), u(rng), u(rng)};
    std::sort(r.begin(), r.end());
    if (r[1] - r[0] < 0.1 || r[2] - r[1] < 0.1) continue;
    const Polynomial p = from_roots(r);
    double got[3];
    ASSERT_EQ(solve_cubic(p.c[3], p.c[2], p.c[1], p.c[0], got), 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], r[i], 1e-9 * std::max(1.0, std::abs(r[i])));
  }
}

// find_first_real_root against the full list: the first root the filter takes, or none. Random
// roots (clusters and pairs within 1e-9 included, where the isolation may fall back to the
// derivative sequence) and filters by threshold and by window; the root must match the full
// solver's to 1e-12 (bit for bit but for that fallback) and be found exactly when it exists.
TEST(PolynomialSolver, FirstRoot_MatchesTheFullListsFirstTaken) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  int found = 0, bits_equal = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    SCOPED_TRACE(trial);
    const int degree = 3 + trial % 6;
    std::vector<double> roots;
    for (int i = 0; i < degree; ++i) {
      double r = u(rng);
      if (i > 0 && trial % 5 == 0) r = roots.back() + 1e-9 * (1 + i);  // a close pair
      roots.push_back(r);
    }
    Polynomial p = from_roots(roots, 1 + 3 * std::abs(u(rng)));
    if (trial % 7 == 0) p.c[0] += 0.01 * u(rng);  // some roots turn complex
    const double lo = -1.5 + 0.5 * std::abs(u(rng)), hi = 1.5 - 0.5 * std::abs(u(rng));
    const double threshold = u(rng);
    const bool window = trial % 3 == 0;  // else a threshold
    const auto accept = [&](double x) {
      return window ? (x >= threshold && x <= threshold + 0.2) : x > threshold;
    };
    const std::vector<double> all = solve(p, lo, hi);
    double want = 0;
    bool exists = false;
    for (double x : all)
      if (accept(x)) {
        want = x;
        exists = true;
        break;
      }
    double got = -7;
    const bool has = find_first_real_root(p, lo, hi, accept, got);
    ASSERT_EQ(has, exists);
    if (!has) continue;
    ++found;
    bits_equal += got == want;
    EXPECT_NEAR(got, want, 1e-12 * (1 + std::abs(want)));
  }
  EXPECT_GT(found, 1500);
  EXPECT_GT(bits_equal, found * 9 / 10);
}

}  // namespace
}  // namespace raycast
