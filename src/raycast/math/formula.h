#pragma once
// Formulas in x, y, z compiled to a small stack bytecode, run over double, Interval and Dual.
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "math/dual.h"
#include "math/expression.h"
#include "math/formula_noise.h"
#include "math/interval.h"

namespace raycast {

/// The deepest evaluation stack a formula may need (deeper ones are refused when compiled).
inline constexpr int kMaxFormulaStack = 64;

enum class Opcode : std::uint8_t {
  kConst,
  kX,
  kY,
  kZ,
  kAdd,
  kSub,
  kMul,
  kDiv,
  kNeg,
  kPowInt,
  kPow,
  kSqrt,
  kExp,
  kLog,
  kSin,
  kCos,
  kTan,
  kAbs,
  kMin,
  kMax,
  kAtan2,  // atan2(below, top): the angle of the point (top, below)
  kFloor,
  kNoise,   // noise_of the top three (x, y, z) for generator n
  kSinVar,  // sin of variable n (0, 1, 2 = x, y, z), computed once per run with its cosine
  kCosVar,  // cos of variable n
};

struct Instruction {
  Opcode op = Opcode::kConst;
  int n = 0;         // kPowInt's exponent, kNoise's generator
  double value = 0;  // kConst's value
};

/// A compiled formula: postfix code over a stack; constant subtrees are folded. sin and cos of
/// a bare variable read a table filled once per run (bit v of trig_vars: variable v needs it), so
/// a formula with both sin(x) and cos(x), like the gyroid, pays for one sin_cos of x.
struct Formula {
  std::vector<Instruction> code;
  int stack_size = 0;
  unsigned trig_vars = 0;
  /// f is defined and continuous on all of R^3: its code holds only finite constants, the
  /// variables, + - * and negation, whole powers >= 0, sin, cos, abs, min and max. Then two
  /// points of a line where f has certain opposite signs enclose a root between them.
  bool continuous = false;
};

/// sin(a) and cos(a) together, for every type run() takes (over Interval and Dual<Interval>, one
/// sin_cos of the value's ends).
inline void sin_cos(double a, double* s, double* c) { interval_detail::sincos(a, s, c); }
template <class T, int N>
void sin_cos(const Dual<T, N>& a, Dual<T, N>* s, Dual<T, N>* c) {
  T sv, cv;
  sin_cos(a.v, &sv, &cv);
  s->v = sv;
  c->v = cv;
  for (int i = 0; i < N; ++i) {
    s->d[i] = cv * a.d[i];
    c->d[i] = -sv * a.d[i];
  }
}

/// Parses and compiles formula text (grammar: parse_expression). `^` and pow with a constant
/// whole exponent become exact repeated products; other exponents mean exp(b log a), a > 0.
/// Throws ExpressionError at the offending offset (also for a formula too deep to evaluate).
Formula compile_formula(std::string_view text);

/// The formula at (x, y, z) for T = double, Interval or Dual<...>. Outside a function's domain
/// the double result is NaN and the interval result empty.
template <class T>
T run(const Formula& f, const T& x, const T& y, const T& z) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::exp;
  using std::floor;
  using std::log;
  using std::max;
  using std::min;
  using std::pow;
  using std::sin;
  using std::sqrt;
  using std::tan;
  std::array<T, kMaxFormulaStack> s;
  T sin_var[3], cos_var[3];
  if (f.trig_vars) {
    const T* vars[3] = {&x, &y, &z};
    for (int v = 0; v < 3; ++v)
      if (f.trig_vars & (1u << v)) sin_cos(*vars[v], &sin_var[v], &cos_var[v]);
  }
  int top = -1;
  for (const Instruction& in : f.code) {
    switch (in.op) {
      case Opcode::kConst:
        s[++top] = T(in.value);
        break;
      case Opcode::kX:
        s[++top] = x;
        break;
      case Opcode::kY:
        s[++top] = y;
        break;
      case Opcode::kZ:
        s[++top] = z;
        break;
      case Opcode::kAdd:
        s[top - 1] = s[top - 1] + s[top];
        --top;
        break;
      case Opcode::kSub:
        s[top - 1] = s[top - 1] - s[top];
        --top;
        break;
      case Opcode::kMul:
        s[top - 1] = s[top - 1] * s[top];
        --top;
        break;
      case Opcode::kDiv:
        s[top - 1] = s[top - 1] / s[top];
        --top;
        break;
      case Opcode::kPow:
        s[top - 1] = pow(s[top - 1], s[top]);
        --top;
        break;
      case Opcode::kMin:
        s[top - 1] = min(s[top - 1], s[top]);
        --top;
        break;
      case Opcode::kMax:
        s[top - 1] = max(s[top - 1], s[top]);
        --top;
        break;
      case Opcode::kAtan2:
        s[top - 1] = atan2(s[top - 1], s[top]);
        --top;
        break;
      case Opcode::kFloor:
        s[top] = floor(s[top]);
        break;
      case Opcode::kNoise:
        s[top - 2] = noise_of(s[top - 2], s[top - 1], s[top], in.n);
        top -= 2;
        break;
      case Opcode::kNeg:
        s[top] = -s[top];
        break;
      case Opcode::kPowInt:
        s[top] = pow_int(s[top], in.n);
        break;
      case Opcode::kSqrt:
        s[top] = sqrt(s[top]);
        break;
      case Opcode::kExp:
        s[top] = exp(s[top]);
        break;
      case Opcode::kLog:
        s[top] = log(s[top]);
        break;
      case Opcode::kSin:
        s[top] = sin(s[top]);
        break;
      case Opcode::kCos:
        s[top] = cos(s[top]);
        break;
      case Opcode::kTan:
        s[top] = tan(s[top]);
        break;
      case Opcode::kAbs:
        s[top] = abs(s[top]);
        break;
      case Opcode::kSinVar:
        s[++top] = sin_var[in.n];
        break;
      case Opcode::kCosVar:
        s[++top] = cos_var[in.n];
        break;
    }
  }
  return s[0];
}

}  // namespace raycast
