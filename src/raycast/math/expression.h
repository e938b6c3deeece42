#pragma once
// Parsing of formula text in x, y, z (the `equation` of algebraic and the `function` of implicit
// surfaces) into a small syntax tree, with the character offset of every node for messages.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raycast {

/// A malformed formula: `offset` is the 0-based character offset in the text where it went wrong.
class ExpressionError : public std::invalid_argument {
 public:
  ExpressionError(std::size_t offset, const std::string& message)
      : std::invalid_argument(message), offset_(offset) {}
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

enum class ExprOp : std::uint8_t {
  kConst,
  kX,
  kY,
  kZ,
  kAdd,
  kSub,
  kMul,
  kDiv,
  kPow,
  kMin,
  kMax,
  kAtan2,  // binary
  kNeg,
  kSqrt,
  kExp,
  kLog,
  kSin,
  kCos,
  kTan,
  kAbs,
  kFloor,  // unary
  kNoise1,
  kNoise2,
  kNoise3,  // ternary: solid noise of generator 1, 2, 3 (math/formula_noise.h)
};

/// One node: a constant (value), a variable, or an operation on children a (and b, c).
struct ExprNode {
  ExprOp op = ExprOp::kConst;
  double value = 0;
  int a = -1, b = -1;
  std::size_t offset = 0;  // where the node's text starts (operators: the operator character)
  int c = -1;
};

/// A syntax tree; nodes refer to children by index, children come before parents.
struct Expression {
  std::vector<ExprNode> nodes;
  int root = -1;
};

/// Parses formula text. Grammar (whitespace ignored):
///   expr    := term (('+' | '-') term)*
///   term    := unary (('*' | '/') unary | juxtaposed unary)*      "2 x", "2 (x + z)"; a
///              juxtaposed factor starts with a name or '(' (so "x 2" is an error)
///   unary   := ('-' | '+') unary | power
///   power   := primary ('^' unary)?                               right associative; -x^2 = -(x^2)
///   primary := number | x | y | z | pi | e | name '(' expr (',' expr)* ')' | '(' expr ')'
/// Numbers: 12, 0.5, .5, 1e-3. Functions: sqrt exp log sin cos tan abs floor (one argument), min
/// max pow atan2 (two), noise1 noise2 noise3 (three: solid noise in [0, 1] of POV-Ray's
/// generators 1, 2, 3, where a scene loader has registered it: math/formula_noise.h). Throws
/// ExpressionError with the offending offset.
Expression parse_expression(std::string_view text);

/// Whether the subtree at `node` uses no variable.
bool is_constant(const Expression& e, int node);

}  // namespace raycast
