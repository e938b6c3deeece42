#include "math/expression.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace raycast {

namespace {

// Deeper nesting than this is refused rather than risking the parser's stack.
constexpr int kMaxNesting = 200;

struct FunctionInfo {
  const char* name;
  ExprOp op;
  int arity;
};
constexpr FunctionInfo kFunctions[] = {
    {"sqrt", ExprOp::kSqrt, 1},     {"exp", ExprOp::kExp, 1},       {"log", ExprOp::kLog, 1},
    {"sin", ExprOp::kSin, 1},       {"cos", ExprOp::kCos, 1},       {"tan", ExprOp::kTan, 1},
    {"abs", ExprOp::kAbs, 1},       {"min", ExprOp::kMin, 2},       {"max", ExprOp::kMax, 2},
    {"pow", ExprOp::kPow, 2},       {"atan2", ExprOp::kAtan2, 2},   {"floor", ExprOp::kFloor, 1},
    {"noise1", ExprOp::kNoise1, 3}, {"noise2", ExprOp::kNoise2, 3}, {"noise3", ExprOp::kNoise3, 3},
};

class Parser {
 public:
  explicit Parser(std::string_view text) : s_(text) {}

  Expression parse() {
    skip_space();
    if (pos_ >= s_.size()) throw ExpressionError(pos_, "expected a formula, got nothing");
    e_.root = expr(0);
    skip_space();
    if (pos_ < s_.size()) {
      if (s_[pos_] == ')') throw ExpressionError(pos_, "unbalanced ')'");
      throw ExpressionError(pos_, std::string("unexpected '") + s_[pos_] + "'");
    }
    return std::move(e_);
  }

 private:
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  char peek() {
    skip_space();
    return pos_ < s_.size() ? s_[pos_] : '\0';
  }
  int add(ExprOp op, std::size_t offset, int a = -1, int b = -1, double value = 0) {
    e_.nodes.push_back(ExprNode{op, value, a, b, offset});
    return static_cast<int>(e_.nodes.size()) - 1;
  }
  // A juxtaposed factor starts with a name or '(' ("2 x", "x (y + 1)"); a number right after a
  // factor ("x 2", "1.2.3") is refused as a likely typo.
  static bool starts_juxtaposed(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '(' || c == '_';
  }
  void check_depth(int depth) {
    if (depth > kMaxNesting) throw ExpressionError(pos_, "formula nested too deeply");
  }

  int expr(int depth) {
    check_depth(depth);
    int left = term(depth);
    for (char c = peek(); c == '+' || c == '-'; c = peek()) {
      const std::size_t at = pos_++;
      const int right = term(depth);
      left = add(c == '+' ? ExprOp::kAdd : ExprOp::kSub, at, left, right);
    }
    return left;
  }

  int term(int depth) {
    int left = unary(depth);
    for (char c = peek(); c == '*' || c == '/' || starts_juxtaposed(c); c = peek()) {
      const std::size_t at = pos_;
      if (c == '*' || c == '/') ++pos_;
      const int right = unary(depth);
      left = add(c == '/' ? ExprOp::kDiv : ExprOp::kMul, at, left, right);
    }
    return left;
  }

  int unary(int depth) {
    check_depth(depth);
    const char c = peek();
    if (c == '-' || c == '+') {
      const std::size_t at = pos_++;
      const int operand = unary(depth + 1);
      return c == '-' ? add(ExprOp::kNeg, at, operand) : operand;
    }
    return power(depth);
  }

  int power(int depth) {
    const int base = primary(depth);
    if (peek() == '^') {
      const std::size_t at = pos_++;
      const int exponent = unary(depth + 1);
      return add(ExprOp::kPow, at, base, exponent);
    }
    return base;
  }

  int primary(int depth) {
    const char c = peek();
    const std::size_t at = pos_;
    if (c == '\0') throw ExpressionError(at, "expected a number, a variable or '(' at the end");
    if (c == '(') {
      ++pos_;
      const int inner = expr(depth + 1);
      if (peek() != ')')
        throw ExpressionError(pos_,
                              "expected ')' to close the '(' at offset " + std::to_string(at + 1));
      ++pos_;
      return inner;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name(depth);
    throw ExpressionError(at, std::string("expected a number, a variable or '(', got '") + c + "'");
  }

  int number() {
    const std::size_t at = pos_;
    std::size_t i = pos_;
    bool digits = false;
    while (i < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i]))) ++i, digits = true;
    if (i < s_.size() && s_[i] == '.') {
      ++i;
      while (i < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i]))) ++i, digits = true;
    }
    if (!digits) throw ExpressionError(at, "expected digits");
    // An exponent only when digits follow, so "2e" stays 2 times the constant e.
    if (i < s_.size() && (s_[i] == 'e' || s_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      if (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) {
        while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
        i = j;
      }
    }
    const std::string text(s_.substr(at, i - at));
    const double v = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(v)) throw ExpressionError(at, "number " + text + " is out of range");
    pos_ = i;
    return add(ExprOp::kConst, at, -1, -1, v);
  }

  int name(int depth) {
    const std::size_t at = pos_;
    std::size_t i = pos_;
    while (i < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i])) || s_[i] == '_')) ++i;
    const std::string id(s_.substr(at, i - at));
    pos_ = i;
    if (peek() == '(') {
      for (const FunctionInfo& f : kFunctions) {
        if (id != f.name) continue;
        ++pos_;
        const int a = expr(depth + 1);
        int b = -1;
        if (f.arity >= 2) {
          if (peek() != ',')
            throw ExpressionError(pos_, id + " takes " + (f.arity == 2 ? "two" : "three") +
                                            " arguments: expected ','");
          ++pos_;
          b = expr(depth + 1);
        }
        int c = -1;
        if (f.arity == 3) {
          if (peek() != ',')
            throw ExpressionError(pos_, id + " takes three arguments: expected ','");
          ++pos_;
          c = expr(depth + 1);
        }
        if (peek() != ')') throw ExpressionError(pos_, "expected ')' after the arguments of " + id);
        ++pos_;
        const int node = add(f.op, at, a, b);
        e_.nodes[static_cast<std::size_t>(node)].c = c;
        return node;
      }
    }
    if (id == "x") return add(ExprOp::kX, at);
    if (id == "y") return add(ExprOp::kY, at);
    if (id == "z") return add(ExprOp::kZ, at);
    if (id == "pi") return add(ExprOp::kConst, at, -1, -1, std::numbers::pi);
    if (id == "e") return add(ExprOp::kConst, at, -1, -1, std::numbers::e);
    for (const FunctionInfo& f : kFunctions)
      if (id == f.name) throw ExpressionError(pos_, "expected '(' after " + id);
    throw ExpressionError(at, "unknown name '" + id +
                                  "' (expected x, y, z, pi, e, or sqrt exp log sin cos tan abs "
                                  "floor min max pow atan2 noise1 noise2 noise3)");
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  Expression e_;
};

}  // namespace

Expression parse_expression(std::string_view text) { return Parser(text).parse(); }

bool is_constant(const Expression& e, int node) {
  const ExprNode& n = e.nodes[node];
  if (n.op == ExprOp::kX || n.op == ExprOp::kY || n.op == ExprOp::kZ) return false;
  if (n.a >= 0 && !is_constant(e, n.a)) return false;
  if (n.b >= 0 && !is_constant(e, n.b)) return false;
  if (n.c >= 0 && !is_constant(e, n.c)) return false;
  return true;
}

}  // namespace raycast
