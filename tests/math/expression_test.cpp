#include "math/expression.h"

#include <gtest/gtest.h>

#include <random>

#include "math/formula.h"
#include "math/trivariate.h"

namespace raycast {
namespace {

std::size_t error_offset(const std::string& text) {
  try {
    expand_polynomial(text);
  } catch (const ExpressionError& e) {
    return e.offset();
  }
  ADD_FAILURE() << "no error for " << text;
  return 999;
}

TEST(Expression, Precedence_PowerBeforeUnaryMinusBeforeProduct) {
  EXPECT_EQ(evaluate(expand_polynomial("-x^2"), Vec3{3, 0, 0}), -9);
  EXPECT_EQ(evaluate(expand_polynomial("2^3^2"), Vec3{}), 512);
  EXPECT_EQ(evaluate(expand_polynomial("9/4*y^2"), Vec3{0, 2, 0}), 9);
  EXPECT_EQ(evaluate(expand_polynomial("1 - 2 - 3"), Vec3{}), -4);
  EXPECT_EQ(evaluate(expand_polynomial("12 / 4 / 3"), Vec3{}), 1);
  EXPECT_EQ(evaluate(expand_polynomial("2 x y"), Vec3{3, 5, 0}), 30);  // juxtaposition
  EXPECT_EQ(evaluate(expand_polynomial("(x + 1)(x - 1)"), Vec3{3, 0, 0}), 8);
  EXPECT_EQ(evaluate(expand_polynomial(".5 + 1e-1 + 2E1"), Vec3{}), 20.6);
  EXPECT_NEAR(evaluate(expand_polynomial("2e"), Vec3{}), 2 * 2.718281828459045, 1e-15);
}

TEST(Expression, Errors_PointAtTheOffendingCharacter) {
  EXPECT_EQ(error_offset("x^2 + y^2 +* z^2"), 11u);
  EXPECT_EQ(error_offset("(x + 1"), 6u);
  EXPECT_EQ(error_offset("x + 1)"), 5u);
  EXPECT_EQ(error_offset("x + foo"), 4u);
  EXPECT_EQ(error_offset("x^2 - sin(x)"), 6u);
  EXPECT_EQ(error_offset("x^-1"), 2u);
  EXPECT_EQ(error_offset("x^1.5"), 2u);
  EXPECT_EQ(error_offset("x / y"), 2u);
  EXPECT_EQ(error_offset(""), 0u);
  EXPECT_EQ(error_offset("x + "), 4u);
  EXPECT_EQ(error_offset("x # y"), 2u);
  EXPECT_EQ(error_offset("min(x)"), 5u);
  EXPECT_EQ(error_offset("x^9 * y^9"), 4u);
  EXPECT_EQ(error_offset("x^2 + y^2 1"), 10u);
  EXPECT_EQ(error_offset("1.2.3"), 3u);
}

TEST(Expression, DeepNesting_RejectedNotCrashed) {
  EXPECT_THROW(parse_expression(std::string(100000, '(') + "x" + std::string(100000, ')')),
               ExpressionError);
  EXPECT_THROW(parse_expression(std::string(100000, '-') + "x"), ExpressionError);
}

// Random strings over the formula alphabet: every one either compiles or throws ExpressionError
// with an offset inside the text; nothing else escapes.
TEST(Expression, RandomText_ParsesOrThrowsPositionedError) {
  const std::string alphabet = "xyz0123456789.+-*/^(),e pisqrtcoanbmlgw";
  std::mt19937 rng(17);
  int parsed = 0;
  for (int i = 0; i < 5000; ++i) {
    std::string text;
    const int n = static_cast<int>(rng() % 24);
    for (int k = 0; k < n; ++k) text += alphabet[rng() % alphabet.size()];
    SCOPED_TRACE(text);
    for (int mode = 0; mode < 2; ++mode) {
      try {
        if (mode == 0) {
          expand_polynomial(text);
        } else {
          const Formula f = compile_formula(text);
          run<double>(f, 0.5, -0.25, 2.0);
          run<Interval>(f, Interval{0, 1}, Interval{-1, 0}, Interval{1, 2});
        }
        ++parsed;
      } catch (const ExpressionError& e) {
        EXPECT_LE(e.offset(), text.size());
      }
    }
  }
  EXPECT_GT(parsed, 100);
}

}  // namespace
}  // namespace raycast

// Formula::continuous lets an any-hit search stop at two parts of certain opposite signs: it
// must be false wherever f can jump or be undefined between them.
TEST(Formula, Continuous_OnlyForFormulasDefinedAndContinuousEverywhere) {
  for (const char* text :
       {"sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
        "(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)", "x^2 + y^2 + z^2 - 1",
        "abs(x) + min(y, z) - max(x, 2) + -x^3", "cos(x * y) + 1/2 * z", "x^0 + 3"})
    EXPECT_TRUE(raycast::compile_formula(text).continuous) << text;
  for (const char* text :
       {"1 / x", "x / y + z", "x^-1 + y", "tan(x) + y", "sqrt(x) - y", "log(x + 2) - y",
        "pow(x, 0.5) + y", "exp(x) - y", "x + 1/0", "sin(1 / x) + y"})
    EXPECT_FALSE(raycast::compile_formula(text).continuous) << text;
}
