#pragma once
// Real roots of univariate polynomials: an isolating solver for any degree, and a cubic.
#include "math/polynomial.h"

namespace raycast {

/// The real roots of p in the closed interval [lo, hi] (infinite ends allowed: a root bound is
/// used), written to `roots` in increasing order, each once; returns their count (<= degree).
/// A multiple root (a tangent touch) is reported once when p vanishes there to within the
/// rounding error of its evaluation; two roots closer than that merge into one.
/// Method: the derivative sequence (Collins and Loos 1976): the real roots of p' split [lo, hi]
/// into pieces on which p is monotone, so each holds at most one root, found by a sign change and
/// polished by Newton's method safeguarded by bisection. The derivatives' roots come from the same
/// method recursively. Coefficients and the variable are scaled by powers of two first (exact),
/// so huge and tiny coefficients work; leading coefficients may vanish. Non-finite coefficients,
/// the zero polynomial and NaN bounds give 0 roots. `roots` needs room for p.degree values.
int find_real_roots(const Polynomial& p, double lo, double hi, double* roots);

/// A predicate on roots (a reference to any callable taking a double; the callable must outlive
/// the filter).
class RootFilter {
 public:
  template <class F>
  RootFilter(const F& f)  // NOLINT(google-explicit-constructor): a lambda passes as is
      : object_(&f),
        call_([](const void* o, double x) { return (*static_cast<const F*>(o))(x); }) {}
  bool operator()(double x) const { return call_(object_, x); }

 private:
  const void* object_;
  bool (*call_)(const void*, double);
};

/// The first root that `accept` takes, trying them in increasing order, of those
/// find_real_roots(p, lo, hi) reports; false when it takes none. The isolation stops at that root,
/// so a caller that wants only the first root in some range (a ray's nearest hit) does not refine
/// the later ones. The root has find_real_roots' bits, except where its full isolation falls back
/// to the derivative sequence over a piece right of the root: then the root is the Bernstein
/// isolation's (the same certified root, refined from its own bracket).
bool find_first_real_root(const Polynomial& p, double lo, double hi, const RootFilter& accept,
                          double& root);

/// The real roots of a t^3 + b t^2 + c t + d = 0 in increasing order (a double root once);
/// returns the count. Closed form (trigonometric for three real roots, Cardano otherwise, on the
/// depressed cubic), then two Newton steps on the original cubic. a == 0 falls back to
/// find_real_roots on the quadratic.
int solve_cubic(double a, double b, double c, double d, double roots[3]);

}  // namespace raycast
