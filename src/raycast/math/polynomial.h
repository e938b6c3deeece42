#pragma once
// Dense univariate polynomials in double with fixed storage (no allocation in hot paths).
#include <array>

namespace raycast {

/// The largest degree any polynomial of the engine may have (algebraic surfaces up to this degree).
inline constexpr int kMaxPolynomialDegree = 16;

/// sum_{i=0}^{degree} c[i] t^i. Coefficients above `degree` are ignored (kept zero by the helpers).
/// The zero polynomial has degree 0 and c[0] == 0.
struct Polynomial {
  int degree = 0;
  std::array<double, kMaxPolynomialDegree + 1> c{};
};

/// p(t) by Horner's rule.
double evaluate(const Polynomial& p, double t);

/// p(t) by Horner's rule, and in `error` a bound on the rounding error of that evaluation
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., algorithm 5.1: running
/// error bound). The coefficients are taken as exact.
double evaluate(const Polynomial& p, double t, double& error);

/// p(t) and p'(t) together (Horner on both).
double evaluate(const Polynomial& p, double t, double& derivative, double& error);

/// The derivative p'.
Polynomial derivative(const Polynomial& p);

/// The quotient of p by (t - root), the remainder dropped (synthetic division).
Polynomial deflate(const Polynomial& p, double root);

/// p with exactly-zero leading coefficients removed (degree lowered).
Polynomial trimmed(const Polynomial& p);

/// p(t + shift) (Taylor shift by repeated synthetic division, O(degree^2)).
Polynomial shifted(const Polynomial& p, double shift);

/// The product p q; degrees must add to at most kMaxPolynomialDegree (the excess is dropped).
Polynomial multiply(const Polynomial& p, const Polynomial& q);

}  // namespace raycast
