#include "math/polynomial.h"

#include <cmath>

#include "math/fixed_degree.h"
#include "math/float_error.h"

namespace raycast {

namespace {

// Horner's rule for degree N (math/fixed_degree.h; kDynamicDegree: p.degree).

template <int N>
double horner(const Polynomial& p, double t) {
  const int n = N == kDynamicDegree ? p.degree : N;
  double y = p.c[n];
  for (int i = n - 1; i >= 0; --i) y = y * t + p.c[i];
  return y;
}

template <int N>
double horner_error(const Polynomial& p, double t, double& error) {
  const int n = N == kDynamicDegree ? p.degree : N;
  double y = p.c[n];
  double mu = 0.5 * std::abs(y);
  const double at = std::abs(t);
  for (int i = n - 1; i >= 0; --i) {
    y = y * t + p.c[i];
    mu = mu * at + std::abs(y);
  }
  // u (2 mu - |y|), made safe against the rounding of mu itself by gamma(2) on top.
  error = kMachineEpsilon * (2 * mu - std::abs(y)) * (1 + gamma(2)) + 0x1p-1074;
  return y;
}

template <int N>
double horner_derivative_error(const Polynomial& p, double t, double& derivative, double& error) {
  const int n = N == kDynamicDegree ? p.degree : N;
  double y = p.c[n];
  double dy = 0;
  double mu = 0.5 * std::abs(y);
  const double at = std::abs(t);
  for (int i = n - 1; i >= 0; --i) {
    dy = dy * t + y;
    y = y * t + p.c[i];
    mu = mu * at + std::abs(y);
  }
  derivative = dy;
  error = kMachineEpsilon * (2 * mu - std::abs(y)) * (1 + gamma(2)) + 0x1p-1074;
  return y;
}

}  // namespace

double evaluate(const Polynomial& p, double t) {
  return with_fixed_degree(p.degree, [&](auto n) { return horner<decltype(n)::value>(p, t); });
}

double evaluate(const Polynomial& p, double t, double& error) {
  return with_fixed_degree(p.degree,
                           [&](auto n) { return horner_error<decltype(n)::value>(p, t, error); });
}

double evaluate(const Polynomial& p, double t, double& derivative, double& error) {
  return with_fixed_degree(p.degree, [&](auto n) {
    return horner_derivative_error<decltype(n)::value>(p, t, derivative, error);
  });
}

Polynomial derivative(const Polynomial& p) {
  Polynomial d;
  if (p.degree == 0) return d;
  d.degree = p.degree - 1;
  for (int i = 1; i <= p.degree; ++i) d.c[i - 1] = i * p.c[i];
  return d;
}

Polynomial deflate(const Polynomial& p, double root) {
  Polynomial q;
  if (p.degree == 0) return q;
  q.degree = p.degree - 1;
  double carry = p.c[p.degree];
  for (int i = p.degree - 1; i >= 0; --i) {
    q.c[i] = carry;
    carry = carry * root + p.c[i];
  }
  return q;
}

Polynomial trimmed(const Polynomial& p) {
  Polynomial q = p;
  while (q.degree > 0 && q.c[q.degree] == 0) --q.degree;
  return q;
}

Polynomial shifted(const Polynomial& p, double shift) {
  Polynomial q = p;
  const int n = q.degree;
  for (int k = 0; k < n; ++k)
    for (int i = n - 1; i >= k; --i) q.c[i] += shift * q.c[i + 1];
  return q;
}

Polynomial multiply(const Polynomial& p, const Polynomial& q) {
  Polynomial r;
  r.degree =
      p.degree + q.degree > kMaxPolynomialDegree ? kMaxPolynomialDegree : p.degree + q.degree;
  for (int i = 0; i <= p.degree; ++i)
    for (int j = 0; j <= q.degree && i + j <= r.degree; ++j) r.c[i + j] += p.c[i] * q.c[j];
  return r;
}

}  // namespace raycast
