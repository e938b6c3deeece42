// Each pattern's defining property: range, period, symmetry, what it is a function of.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "texture/pattern.h"

namespace raycast::texture {
namespace {

Vec3 random_point(std::mt19937& rng, double r = 10) {
  std::uniform_real_distribution<double> u(-r, r);
  return {u(rng), u(rng), u(rng)};
}

TEST(Pattern, EveryPatternStaysInUnitRange) {
  std::mt19937 rng(7);
  for (int k = 0; k <= int(PatternKind::kWrinkles); ++k) {
    Pattern p = make_pattern(PatternKind(k));
    p.turbulence.amount = {0.5, 0.5, 0.5};
    for (int i = 0; i < 300; ++i) {
      const double v = evaluate(p, random_point(rng));
      ASSERT_GE(v, 0) << pattern_name(PatternKind(k));
      ASSERT_LE(v, 1) << pattern_name(PatternKind(k));
    }
  }
}

TEST(Pattern, NamesRoundTrip) {
  for (int k = 0; k <= int(PatternKind::kWrinkles); ++k)
    EXPECT_EQ(pattern_kind(pattern_name(PatternKind(k))), PatternKind(k));
  EXPECT_FALSE(pattern_kind("mandel"));
}

TEST(Pattern, GradientIsPeriodicWithPeriodOneAlongItsAxis) {
  const Pattern p = make_pattern(PatternKind::kGradient);
  EXPECT_DOUBLE_EQ(evaluate(p, {0.25, 3, -2}), 0.25);
  std::mt19937 rng(3);
  for (int i = 0; i < 100; ++i) {
    const Vec3 q = random_point(rng);
    EXPECT_NEAR(evaluate(p, q), evaluate(p, q + Vec3{1, 0, 0}), 1e-9);
    EXPECT_NEAR(evaluate(p, q), evaluate(p, q + Vec3{0, 5.3, -2.1}), 1e-12);  // only x matters
  }
}

TEST(Pattern, OnionIsAFunctionOfTheRadius) {
  const Pattern p = make_pattern(PatternKind::kOnion);
  EXPECT_NEAR(evaluate(p, {0.3, 0, 0}), 0.3, 1e-12);
  EXPECT_NEAR(evaluate(p, {0, 0.3, 0}), 0.3, 1e-12);
  EXPECT_NEAR(evaluate(p, {0, 0, 1.3}), 0.3, 1e-12);
  EXPECT_NEAR(evaluate(p, {0.6, 0.8, 0}), evaluate(p, {0, 0, 1}), 1e-12);
}

TEST(Pattern, CheckerAlternatesBetweenNeighbouringCells) {
  const Pattern p = make_pattern(PatternKind::kChecker);
  EXPECT_EQ(evaluate(p, {0.5, 0.5, 0.5}), 0);
  EXPECT_EQ(evaluate(p, {1.5, 0.5, 0.5}), 1);
  EXPECT_EQ(evaluate(p, {1.5, 1.5, 0.5}), 0);
  EXPECT_EQ(evaluate(p, {-0.5, 0.5, 0.5}), 1);
}

TEST(Pattern, MarbleIsATriangleWaveInX) {
  const Pattern p = make_pattern(PatternKind::kMarble);
  EXPECT_NEAR(evaluate(p, {0.25, 4, 1}), 0.5, 1e-12);
  EXPECT_NEAR(evaluate(p, {0.5, 0, 0}), 1, 1e-12);
  EXPECT_NEAR(evaluate(p, {0.75, 0, 0}), 0.5, 1e-12);
  EXPECT_NEAR(evaluate(p, {0.2, 0, 0}), evaluate(p, {-0.2, 0, 0}), 1e-12);  // symmetric
}

TEST(Pattern, WoodRingsAreAboutTheZAxis) {
  const Pattern p = make_pattern(PatternKind::kWood);
  EXPECT_NEAR(evaluate(p, {0.3, 0, 5}), evaluate(p, {0, 0.3, -2}), 1e-12);
  EXPECT_NEAR(evaluate(p, {0.25, 0, 0}), 0.5, 1e-12);
}

TEST(Pattern, RadialIsAFunctionOfTheAngleAboutY) {
  const Pattern p = make_pattern(PatternKind::kRadial);
  EXPECT_NEAR(evaluate(p, {1, 0, 0}), evaluate(p, {3, 7, 0}), 1e-12);
  EXPECT_NEAR(evaluate(p, {0, 0, 1}), 0.5, 1e-12);
  EXPECT_NEAR(evaluate(p, {1, 0, 0}), 0.75, 1e-12);
}

TEST(Pattern, SphericalCylindricalPlanarAndBoxedFallFromOneToZero) {
  EXPECT_EQ(evaluate(make_pattern(PatternKind::kSpherical), {0, 0, 0}), 1);
  EXPECT_NEAR(evaluate(make_pattern(PatternKind::kSpherical), {0.6, 0, 0}), 0.4, 1e-12);
  EXPECT_EQ(evaluate(make_pattern(PatternKind::kSpherical), {2, 0, 0}), 0);
  EXPECT_NEAR(evaluate(make_pattern(PatternKind::kCylindrical), {0.3, 9, 0.4}), 0.5, 1e-12);
  EXPECT_NEAR(evaluate(make_pattern(PatternKind::kPlanar), {9, -0.25, 9}), 0.75, 1e-12);
  EXPECT_NEAR(evaluate(make_pattern(PatternKind::kBoxed), {0.1, -0.5, 0.2}), 0.5, 1e-12);
}

TEST(Pattern, LeopardIsSymmetricAndPeriodic) {
  const Pattern p = make_pattern(PatternKind::kLeopard);
  const Vec3 q{0.3, 1.1, -0.4};
  EXPECT_NEAR(evaluate(p, q), evaluate(p, -1.0 * q), 1e-12);
  EXPECT_NEAR(evaluate(p, q), evaluate(p, q + Vec3{2 * M_PI, 0, 0}), 1e-9);
}

TEST(Pattern, CellsAreConstantWithinAUnitCell) {
  const Pattern p = make_pattern(PatternKind::kCells);
  EXPECT_EQ(evaluate(p, {2.1, 3.1, 4.1}), evaluate(p, {2.9, 3.9, 4.9}));
  EXPECT_NE(evaluate(p, {2.1, 3.1, 4.1}), evaluate(p, {3.1, 3.1, 4.1}));
}

TEST(Pattern, BlockPatternsTakeTheirListedValues) {
  std::mt19937 rng(11);
  for (PatternKind k : {PatternKind::kHexagon, PatternKind::kSquare, PatternKind::kTriangular,
                        PatternKind::kBrick}) {
    const Pattern p = make_pattern(k);
    const int n = block_count(k);
    for (int i = 0; i < 200; ++i) {
      const double v = evaluate(p, random_point(rng)) * (n - 1);
      EXPECT_NEAR(v, std::round(v), 1e-12) << pattern_name(k);
    }
  }
}

TEST(Pattern, HexagonNeighboursDiffer) {
  const Pattern p = make_pattern(PatternKind::kHexagon);
  // Centres of a flat-topped grid of side 1: neighbours 1.5 apart in x, sqrt(3)/2 in z.
  const double a = evaluate(p, {0, 0, 0}), b = evaluate(p, {1.5, 0, std::sqrt(3.0) / 2}),
               c = evaluate(p, {0, 0, std::sqrt(3.0)});
  EXPECT_NE(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(b, c);
}

TEST(Pattern, BrickHasMortarAtTheJoints) {
  const Pattern p = make_pattern(PatternKind::kBrick);
  EXPECT_EQ(evaluate(p, {4, 1.5, 2}), 1);      // inside a brick
  EXPECT_EQ(evaluate(p, {0.1, 1.5, 2}), 0);    // at a vertical joint
  EXPECT_EQ(evaluate(p, {4, 0.1, 2}), 0);      // at a horizontal joint
  EXPECT_EQ(evaluate(p, {0.1, 4.5, 1.0}), 1);  // the next row is shifted half a brick
}

TEST(Pattern, WavesFrequencyAndPhase) {
  Pattern p = make_pattern(PatternKind::kGradient);
  p.frequency = 2;
  EXPECT_NEAR(evaluate(p, {0.3, 0, 0}), 0.6, 1e-12);
  EXPECT_NEAR(evaluate(p, {0.8, 0, 0}), 0.6, 1e-12);  // period 1/2
  p.frequency = 1;
  p.phase = 0.25;
  EXPECT_NEAR(evaluate(p, {0.1, 0, 0}), 0.35, 1e-12);
  EXPECT_NEAR(apply_wave(WaveForm::kTriangle, 0.25, 1), 0.5, 1e-12);
  EXPECT_NEAR(apply_wave(WaveForm::kSine, 0.25, 1), 1, 1e-12);
  EXPECT_NEAR(apply_wave(WaveForm::kScallop, 0.5, 1), 1, 1e-12);
  EXPECT_NEAR(apply_wave(WaveForm::kCubic, 0.5, 1), 0.5, 1e-12);
  EXPECT_NEAR(apply_wave(WaveForm::kPoly, 0.5, 2), 0.25, 1e-12);
}

TEST(Pattern, TransformsMoveThePattern) {
  Pattern p = make_pattern(PatternKind::kGradient);
  transform_pattern(p, Transform::scale({2, 2, 2}));
  EXPECT_NEAR(evaluate(p, {0.5, 0, 0}), 0.25, 1e-12);
  transform_pattern(p, Transform::translate({0.5, 0, 0}));
  EXPECT_NEAR(evaluate(p, {0.5, 0, 0}), 0, 1e-12);
  EXPECT_EQ(p.steps.size(), 1u);  // merged
}

TEST(Pattern, WarpTurbulenceMovesThePointByABoundedAmount) {
  Pattern p = make_pattern(PatternKind::kGradient);
  Pattern w = p;
  PatternStep s;
  s.warp.amount = {0.1, 0, 0};
  w.steps.push_back(s);
  std::mt19937 rng(5);
  bool moved = false;
  for (int i = 0; i < 100; ++i) {
    const Vec3 q = random_point(rng, 0.4) + Vec3{0.5, 0, 0};
    const double d = std::abs(evaluate(w, q) - evaluate(p, q));
    EXPECT_LE(std::min(d, 1 - d), 0.1 * 2 + 1e-9);  // |sum omega^i| <= 2
    moved |= d > 1e-6;
  }
  EXPECT_TRUE(moved);
}

}  // namespace
}  // namespace raycast::texture
