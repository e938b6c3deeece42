#pragma once
// Polynomials in x, y, z: expansion from formula text, evaluation, gradient and restriction to a
// line.
#include <string_view>
#include <utility>
#include <vector>

#include "math/expression.h"
#include "math/polynomial.h"
#include "math/vec3.h"

namespace raycast {

/// sum of c x^i y^j z^k over the terms; total degree <= kMaxPolynomialDegree.
struct Trivariate {
  struct Term {
    int i = 0, j = 0, k = 0;
    double c = 0;
  };
  std::vector<Term> terms;  // sorted by (i, j, k), no zero coefficients
  int degree = 0;

  /// The formula as written (before expansion), as postfix code over polynomials in t: when its
  /// products cost fewer multiplications than the expanded terms' (a product or power of sums,
  /// like Taubin's heart or two tori multiplied), restrict_to_line runs this instead. A
  /// subexpression written more than once (the heart's x^2 and z^3) is computed once: kStore
  /// keeps a copy of the top in a slot, kLoad pushes it again (the same coefficients, bit for bit,
  /// as computing it anew).
  struct LineOp {
    enum Kind : unsigned char {
      kConst,
      kVar,
      kAdd,
      kSub,
      kMul,
      kNeg,
      kDiv,
      kPow,
      kStore,
      kLoad
    } kind;
    int n = 0;         // kVar: 0, 1, 2 = x, y, z; kPow: the exponent; kStore, kLoad: the slot
    double value = 0;  // kConst: the value; kDiv: the constant divisor
  };
  std::vector<LineOp> line_code;
  bool line_code_cheaper = false;

  /// line_code translated once into steps over registers, each value computed into its own
  /// register (no stack copies; a stored value is its register, loads cost nothing), with the
  /// operands' degrees fixed per step and products of small degrees unrolled: the same
  /// operations in the same order, so the same coefficients bit for bit. Registers 0..2 hold the
  /// lines of x, y, z; `line_constants` the (register, value) pairs of the constants. Empty when
  /// the code needs more registers than restrict_code_to_line keeps (it then runs line_code).
  struct LineStep {
    using Run = void (*)(const LineStep&, double (*reg)[kMaxPolynomialDegree + 1]);
    Run run = nullptr;
    unsigned char dst = 0, a = 0, b = 0, da = 0, db = 0;
    double value = 0;  // the constant of a scaling, division or (+1 / -1) sum
  };
  std::vector<LineStep> line_steps;
  std::vector<std::pair<int, double>> line_constants;
  int line_result = 0, line_result_degree = 0;
};

/// Expands formula text into a polynomial: + - *, / by constants, ^ with non-negative whole
/// exponents, parentheses, pi and e. Anything else (a function, division by a variable
/// expression, a fractional exponent of a variable, degree above kMaxPolynomialDegree) throws
/// ExpressionError at the offending offset.
Trivariate expand_polynomial(std::string_view text);

double evaluate(const Trivariate& f, const Vec3& p);
/// f and its gradient in long double (x87 extended precision where available), for polishing hits
/// where f is badly conditioned.
long double evaluate_extended(const Trivariate& f, long double x, long double y, long double z);
void gradient_extended(const Trivariate& f, long double x, long double y, long double z,
                       long double g[3]);
/// The gradient (df/dx, df/dy, df/dz) at p.
Vec3 gradient(const Trivariate& f, const Vec3& p);

/// f(o + t d) as a polynomial in t, of degree <= f.degree: from the expanded terms (the powers of
/// the three linear forms built once per call, then terms sharing (i, j) summed before the
/// products), or from f.line_code where that is cheaper (the same polynomial up to rounding).
Polynomial restrict_to_line(const Trivariate& f, const Vec3& o, const Vec3& d);
/// The two ways, for tests and benchmarks.
Polynomial restrict_expanded_to_line(const Trivariate& f, const Vec3& o, const Vec3& d);
Polynomial restrict_code_to_line(const Trivariate& f, const Vec3& o, const Vec3& d);

}  // namespace raycast
