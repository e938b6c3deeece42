#include "math/expression.h"

#include <gtest/gtest.h>

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
}

TEST(Expression, DeepNesting_RejectedNotCrashed) {
  EXPECT_THROW(parse_expression(std::string(100000, '(') + "x" + std::string(100000, ')')),
               ExpressionError);
  EXPECT_THROW(parse_expression(std::string(100000, '-') + "x"), ExpressionError);
}

}  // namespace
}  // namespace raycast
