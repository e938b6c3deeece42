#pragma once
// A polynomial in the Bernstein basis of an interval, with a bound on each coefficient's rounding
// error: its sign pattern bounds the number of roots there (Descartes' rule of signs), and
// de Casteljau halving refines it. The isolating solver uses it to skip and separate roots early.
#include "math/polynomial.h"

namespace raycast {

/// p(a + s w) = sum_i b[i] C(n, i) s^i (1 - s)^(n - i) on s in [0, 1], n = p.degree; |b[i] - the
/// exact coefficient| <= e[i] (the coefficients of p taken as exact). b[0] is p(a), b[n] p(a + w).
struct BernsteinForm {
  int degree = 0;
  double b[kMaxPolynomialDegree + 1];
  double e[kMaxPolynomialDegree + 1];
};

/// The Bernstein form of p on [a, a + w] (w > 0, finite): Taylor shift to a, scaling by w, then the
/// binomial transform; the error bounds are gamma(4n + 4) times the same computation on |p|, |a|.
BernsteinForm bernstein_form(const Polynomial& p, double a, double w);

/// The two halves of f's interval (de Casteljau at 1/2), each coefficient's bound carried through
/// the averaging and widened by its own rounding. `left` or `right` may be `f` itself.
void bernstein_halves(const BernsteinForm& f, BernsteinForm& left, BernsteinForm& right);

/// The most sign changes the exact coefficients can have: a coefficient within its error bound may
/// have either sign (or be zero, which Descartes' rule skips: never more changes than either sign).
/// By Descartes' rule on the interval, the exact polynomial has at most that many roots inside it
/// (counted with multiplicity), and 0 means none on the closed interval.
int max_sign_changes(const BernsteinForm& f);

}  // namespace raycast
