#include "math/bernstein.h"

#include <algorithm>
#include <cmath>

#include "math/fixed_degree.h"
#include "math/float_error.h"

namespace raycast {

namespace {

// C(n, k) for n <= kMaxPolynomialDegree: exact in double.
struct Binomials {
  double c[kMaxPolynomialDegree + 1][kMaxPolynomialDegree + 1] = {};
  constexpr Binomials() {
    for (int n = 0; n <= kMaxPolynomialDegree; ++n) {
      c[n][0] = 1;
      for (int k = 1; k <= n; ++k) c[n][k] = c[n - 1][k - 1] + (k < n ? c[n - 1][k] : 0);
    }
  }
};
constexpr Binomials kBinomials;

}  // namespace

// The coefficient and its magnitude bound side by side: the two recurrences are the same
// elementwise IEEE operations on both (so the same bits as two scalar loops), in one vector.
using Pair = double __attribute__((vector_size(16)));

namespace {

// The kernels below for degree N (math/fixed_degree.h; kDynamicDegree: the form's own degree).

template <int N>
BernsteinForm bernstein_form_n(const Polynomial& p, double a, double w) {
  BernsteinForm f;
  const int n = N == kDynamicDegree ? p.degree : N;
  f.degree = n;
  // .. [0] the coefficients, then the Bernstein coefficients, in place; [1] the same computation
  // on |p|, |a|: every term's magnitude summed.
  Pair v[kMaxPolynomialDegree + 1];
  for (int i = 0; i <= n; ++i) v[i] = Pair{p.c[i], std::abs(p.c[i])};
  // Taylor shift to a (synthetic division): at most n updates of two roundings per term.
  const Pair av{a, std::abs(a)};
  for (int k = 0; k < n; ++k)
    for (int i = n - 1; i >= k; --i) v[i] += av * v[i + 1];
  // Scale by w^k and divide by C(n, k): at most k - 1 + 2 roundings.
  double wk = 1;
  for (int k = 0; k <= n; ++k) {
    const double c = kBinomials.c[n][k];
    v[k] = v[k] * wk / c;
    wk *= w;
  }
  // The binomial transform b_i = sum_k C(i, k) c_k (Pascal's triangle): at most n additions.
  for (int j = 1; j <= n; ++j)
    for (int i = n; i >= j; --i) v[i] += v[i - 1];
  // Every term passed at most 2n + (n + 1) + n < 4n + 2 roundings; gamma(4n + 4) also covers the
  // rounding of m itself. The absolute term covers underflow.
  const double g = gamma(4 * n + 4);
  for (int i = 0; i <= n; ++i) {
    f.b[i] = v[i][0];
    f.e[i] = v[i][1] * g + (4 * n + 4) * 0x1p-1074;
  }
  return f;
}

template <int N>
void bernstein_halves_n(const BernsteinForm& f, BernsteinForm& left, BernsteinForm& right) {
  const int n = N == kDynamicDegree ? f.degree : N;
  left.degree = right.degree = n;
  // (right may be f itself: copies first; element by element, as a memcpy call costs more.)
  double b[kMaxPolynomialDegree + 1], e[kMaxPolynomialDegree + 1];
  for (int i = 0; i <= n; ++i) {
    b[i] = f.b[i];
    e[i] = f.e[i];
  }
  left.b[0] = b[0];
  left.e[0] = e[0];
  right.b[n] = b[n];
  right.e[n] = e[n];
  // Each average (x + y) / 2 rounds once (halving is exact but for underflow): its error is the
  // mean of the two bounds plus u |result| (1 + 2u) + 2^-1075; the factor 1 + 8u covers the
  // roundings of computing the bound itself.
  constexpr double u = kMachineEpsilon;
  // Fully unrolled for the fixed degrees (GCC otherwise vectorises the inner loop with a
  // remainder; clang takes the same pragma).
#pragma GCC unroll 8
  for (int j = 1; j <= n; ++j) {
#pragma GCC unroll 8
    for (int i = 0; i <= n - j; ++i) {
      b[i] = 0.5 * (b[i] + b[i + 1]);
      e[i] = (0.5 * (e[i] + e[i + 1]) + u * std::abs(b[i])) * (1 + 8 * u) + 0x1p-1074;
    }
    left.b[j] = b[0];
    left.e[j] = e[0];
    right.b[n - j] = b[n - j];
    right.e[n - j] = e[n - j];
  }
}

}  // namespace

BernsteinForm bernstein_form(const Polynomial& p, double a, double w) {
  return with_fixed_degree(p.degree,
                           [&](auto n) { return bernstein_form_n<decltype(n)::value>(p, a, w); });
}

void bernstein_halves(const BernsteinForm& f, BernsteinForm& left, BernsteinForm& right) {
  return with_fixed_degree(
      f.degree, [&](auto n) { return bernstein_halves_n<decltype(n)::value>(f, left, right); });
}

namespace {

template <int N>
int max_sign_changes_n(const BernsteinForm& f) {
  const int n = N == kDynamicDegree ? f.degree : N;
  // Certain signs: count the changes.
  int changes = 0, last = 0, i = 0;
#pragma GCC unroll 8
  for (; i <= n; ++i) {
    const double b = f.b[i], e = f.e[i];
    const int sign = b > e ? 1 : (b < -e ? -1 : 0);
    if (sign == 0) break;
    changes += last != 0 && sign != last;
    last = sign;
  }
  if (i > n) return changes;
  // From the first uncertain coefficient on: the most changes of a sequence ending in a positive
  // (pos) or negative (neg) value, where an uncertain coefficient may be either; kNone: none.
  constexpr int kNone = -1000;
  int pos = last > 0 ? changes : kNone, neg = last < 0 ? changes : kNone;
  if (i == 0) {  // no certain coefficient before: the first one starts the sequence
    pos = f.b[0] >= -f.e[0] ? 0 : kNone;
    neg = f.b[0] <= f.e[0] ? 0 : kNone;
    ++i;
  }
  for (; i <= n; ++i) {
    const bool can_pos = f.b[i] >= -f.e[i], can_neg = f.b[i] <= f.e[i];
    const int p = can_pos ? std::max(pos, neg + 1) : kNone;
    const int q = can_neg ? std::max(neg, pos + 1) : kNone;
    pos = p;
    neg = q;
  }
  // Neither sign possible: a NaN coefficient; it decides nothing.
  return pos < 0 && neg < 0 ? n + 1 : std::max(pos, neg);
}

}  // namespace

int max_sign_changes(const BernsteinForm& f) {
  return with_fixed_degree(f.degree,
                           [&](auto n) { return max_sign_changes_n<decltype(n)::value>(f); });
}

}  // namespace raycast
