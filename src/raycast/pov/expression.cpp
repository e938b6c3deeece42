// Expressions: POV-Ray's operators from lowest to highest precedence: `? :`, `|`, `&`,
// comparisons, `+ -`, `* /`, unary `- + !`, then postfix `.x` and `[i]`. A float meets a vector
// as a vector of equal components; a shorter vector is padded with zeros; a colour meeting a
// vector makes a colour.
#include <algorithm>
#include <cmath>

#include "pov/interpreter.h"

namespace raycast::pov {

namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's tolerance for `=`, `!=` and truth

Value widen(const Value& a, int dims, bool colour) {
  Value r = a;
  if (a.kind == Value::Float) {
    r.kind = Value::Vector;
    for (int i = 0; i < dims; ++i) r.v[static_cast<std::size_t>(i)] = a.v[0];
    // A float as a colour fills r, g, b, filter and transmit alike (POV-Ray's rule).
  } else {
    for (int i = a.dims; i < dims; ++i) r.v[static_cast<std::size_t>(i)] = 0;
  }
  r.dims = dims;
  r.colour = colour;
  return r;
}

}  // namespace

double Interpreter::number_in_vector(const char* what) {
  const Pos at = tok().pos;
  const Value v = sub_expression(1);
  if (v.kind != Value::Float)
    fail_at(at, std::string("expected a float for ") + what + ", got " + kind_name(v));
  return v.v[0];
}

double Interpreter::number(const char* what) {
  const Pos at = tok().pos;
  const Value v = item_expression();
  if (v.kind != Value::Float)
    fail_at(at, std::string("expected a float for ") + what + ", got " + kind_name(v));
  return v.v[0];
}

Value Interpreter::item_expression() {
  const ParenDepth outside(*this, 0);
  return expression();
}

Vec3 Interpreter::vector(const char* what) {
  const Pos at = tok().pos;
  const Value v = item_expression();
  if (v.kind == Value::Float) return {v.v[0], v.v[0], v.v[0]};
  if (v.kind != Value::Vector)
    fail_at(at, std::string("expected a vector for ") + what + ", got " + kind_name(v));
  return {v.v[0], v.v[1], v.dims > 2 ? v.v[2] : 0};
}

std::string Interpreter::string_value(const char* what) {
  const Pos at = tok().pos;
  const Value v = expression();
  if (v.kind != Value::String)
    fail_at(at, std::string("expected a string for ") + what + ", got " + kind_name(v));
  return v.text;
}

bool Interpreter::boolean_option() {
  const Token& t = peek_operator();
  if (pending_) return true;
  if (t.kind == Token::Number ||
      (t.kind == Token::Word && (t.text == "on" || t.text == "off" || t.text == "true" ||
                                 t.text == "false" || t.text == "yes" || t.text == "no")))
    return number("a boolean") != 0;
  if (t.kind == Token::Word) {
    const Value* v = lookup(t.text);
    if (v && v->kind == Value::Float) return number("a boolean") != 0;
  }
  return true;
}

namespace {

struct Ops {
  Interpreter& in;
  int vector_depth = 0;  // inside < >, a bare '>' closes the vector

  [[noreturn]] void not_numeric(const Pos& at, const Value& v, const char* op) {
    in.fail_at(at, std::string("'") + op + "' needs floats or vectors, got " + kind_name(v));
  }

  Value combine(const Value& a, const Value& b, const Pos& at, const char* op,
                double (*f)(double, double)) {
    if (!a.is_numeric()) not_numeric(at, a, op);
    if (!b.is_numeric()) not_numeric(at, b, op);
    if (a.kind == Value::Float && b.kind == Value::Float) return Value::number(f(a.v[0], b.v[0]));
    const bool colour = a.colour || b.colour;
    const int dims = colour ? 5 : std::max(a.dims, b.dims);
    const Value x = widen(a, dims, colour), y = widen(b, dims, colour);
    Value r = x;
    for (std::size_t i = 0; i < static_cast<std::size_t>(dims); ++i) r.v[i] = f(x.v[i], y.v[i]);
    return r;
  }

  bool op(std::string_view s) {
    const Token& t = in.peek_operator();
    if (in.pending_now()) return false;
    if (!is_symbol(t, s)) return false;
    if (vector_depth > 0 && (s == ">" || s == ">=")) return false;
    in.next();
    return true;
  }

  Value ternary() {
    const Interpreter::NestingLevel level(in);
    Value c = logical_or();
    if (op("?")) {
      const Pos at = in.tok().pos;
      if (c.kind != Value::Float) in.fail_at(at, "'?' needs a float condition");
      Value a = ternary();
      in.expect_symbol(":", "in 'condition ? a : b'");
      Value b = ternary();
      c = std::fabs(c.v[0]) > kEpsilon ? a : b;
    }
    return c;
  }
  static bool truth(const Value& v) { return std::fabs(v.v[0]) > kEpsilon; }
  Value logical_or() {
    Value a = logical_and();
    while (op("|")) {
      const Value b = logical_and();
      a = Value::number(truth(a) || truth(b));
    }
    return a;
  }
  Value logical_and() {
    Value a = comparison();
    while (op("&")) {
      const Value b = comparison();
      a = Value::number(truth(a) && truth(b));
    }
    return a;
  }
  // Strings compare by their characters (POV-Ray reads `#if (Variant = "tree")`).
  Value string_comparison(const Value& a) {
    const Pos at = in.tok_pos();
    int kind;
    if (op("="))
      kind = 0;
    else if (op("!="))
      kind = 1;
    else
      return a;
    const Value b = sum();
    if (b.kind != Value::String)
      in.fail_at(at, "a string compares with a string, got " + std::string(kind_name(b)));
    return Value::number((a.text == b.text) == (kind == 0));
  }
  Value comparison() {
    Value a = sum();
    if (a.kind == Value::String && in.paren_depth_ > 0) return string_comparison(a);
    // Only a float is compared, and only inside parentheses: outside, '<' opens the next
    // vector (box { <a> <b> }, vertex_vectors { 14 <-1, 0, 0> ... }, #if (C) <1, 0, 0>).
    while (a.kind == Value::Float && in.paren_depth_ > 0) {
      const Pos at = in.tok_pos();
      int kind;
      if (op("<="))
        kind = 0;
      else if (op(">="))
        kind = 1;
      else if (op("!="))
        kind = 2;
      else if (op("="))
        kind = 3;
      else if (op("<"))
        kind = 4;
      else if (op(">"))
        kind = 5;
      else
        return a;
      const Value b = sum();
      if (!a.is_numeric() || !b.is_numeric()) not_numeric(at, a.is_numeric() ? b : a, "compare");
      const int dims = std::max(a.dims, b.dims);
      const Value x = a.kind == Value::Float ? widen(a, dims, false) : a;
      const Value y = b.kind == Value::Float ? widen(b, dims, false) : b;
      bool all = true;
      for (std::size_t i = 0; i < static_cast<std::size_t>(dims); ++i) {
        const double p = x.v[i], q = y.v[i];
        const bool r = kind == 0   ? p <= q
                       : kind == 1 ? p >= q
                       : kind == 2 ? std::fabs(p - q) > kEpsilon
                       : kind == 3 ? std::fabs(p - q) <= kEpsilon
                       : kind == 4 ? p < q
                                   : p > q;
        all = all && r;
      }
      a = Value::number(all);
    }
    return a;
  }
  Value sum() {
    Value a = product();
    for (;;) {
      const Pos at = in.tok_pos();
      if (op("+"))
        a = combine(a, product(), at, "+", [](double p, double q) { return p + q; });
      else if (op("-"))
        a = combine(a, product(), at, "-", [](double p, double q) { return p - q; });
      else
        return a;
    }
  }
  Value product() {
    Value a = unary();
    for (;;) {
      const Pos at = in.tok_pos();
      if (op("*"))
        a = combine(a, unary(), at, "*", [](double p, double q) { return p * q; });
      else if (op("/"))
        a = combine(a, unary(), at, "/", [](double p, double q) { return p / q; });
      else
        return a;
    }
  }
  Value unary() {
    const Interpreter::NestingLevel level(in);
    Value r;
    const Pos at = in.tok().pos;
    if (in.accept_symbol("-")) {
      r = unary();
      if (!r.is_numeric()) not_numeric(at, r, "-");
      for (double& c : r.v) c = -c;
    } else if (in.accept_symbol("+")) {
      r = unary();
    } else if (in.accept_symbol("!")) {
      r = unary();
      if (r.kind != Value::Float) not_numeric(at, r, "!");
      r = Value::number(!truth(r));
    } else {
      r = in.primary(vector_depth);
    }
    return r;
  }
};

}  // namespace

bool Interpreter::pending_now() const { return pending_; }
Pos Interpreter::tok_pos() { return have_ ? cur_.pos : Pos{}; }

Interpreter::NestingLevel::NestingLevel(Interpreter& in) : in_(in) {
  if (in_.expression_depth_ >= kMaxPovExpressionNesting)
    in_.fail_here("expressions, directives and objects are nested more than " +
                  std::to_string(kMaxPovExpressionNesting) + " levels deep");
  ++in_.expression_depth_;
}

Interpreter::NestingLevel::~NestingLevel() { --in_.expression_depth_; }

Value Interpreter::expression() {
  const NestingLevel level(*this);
  Ops o{*this};
  return o.ternary();
}

Value Interpreter::sub_expression(int vector_depth) {
  const NestingLevel level(*this);
  Ops o{*this};
  o.vector_depth = vector_depth;
  return o.ternary();
}

Value Interpreter::vector_literal(const Pos& at) {
  Value r;
  r.kind = Value::Vector;
  r.dims = 0;
  for (;;) {
    const Pos cp = tok().pos;
    const Value c = [&] {
      const ParenDepth component(*this, 0);
      return sub_expression(1);
    }();
    if (c.kind != Value::Float) fail_at(cp, "a vector's components must be floats");
    if (r.dims == 5) fail_at(cp, "a vector has at most 5 components");
    r.v[static_cast<std::size_t>(r.dims++)] = c.v[0];
    if (accept_symbol(",")) {
      if (is_symbol(">")) {  // a trailing comma: <1, 2, 3,>
        next();
        break;
      }
      continue;
    }
    if (is_symbol(">")) {
      next();
      break;
    }
    // POV-Ray reads components separated by spaces alone (< -1 0 0 >) where unambiguous.
    const Token& n = tok();
    if (n.kind == Token::Number || n.kind == Token::Word || pov::is_symbol(n, "(") ||
        pov::is_symbol(n, "-") || pov::is_symbol(n, "+"))
      continue;
    unexpected("',' or '>' in the vector");
  }
  if (r.dims < 2) {
    // POV-Ray reads <a> as the float a.
    return Value::number(r.v[0]);
  }
  (void)at;
  return r;
}

namespace {
double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
}  // namespace

Value Interpreter::colour_keyword(const Token& kw) {
  // rgb / rgbf / rgbt / rgbft and their srgb forms read one operand (unary level).
  const std::string& w = kw.text;
  const bool s = w[0] == 's';
  const std::string base = s ? w.substr(1) : w;
  const int want = base == "rgb" ? 3 : base == "rgbft" ? 5 : 4;
  Ops o{*this};
  const Pos at = tok().pos;
  Value v = o.unary();
  if (!v.is_numeric()) fail_at(at, w + " needs a float or a vector, got " + kind_name(v));
  Value c;
  c.kind = Value::Vector;
  c.colour = true;
  c.dims = 5;
  if (v.kind == Value::Float) {
    for (int i = 0; i < want; ++i) c.v[static_cast<std::size_t>(i)] = v.v[0];
  } else {
    for (int i = 0; i < std::min(v.dims, want); ++i)
      c.v[static_cast<std::size_t>(i)] = v.v[static_cast<std::size_t>(i)];
  }
  if (base == "rgbt") c.v[4] = c.v[3], c.v[3] = 0;
  if (base == "rgb") c.v[3] = c.v[4] = 0;
  if (s)
    for (int i = 0; i < 3; ++i)
      c.v[static_cast<std::size_t>(i)] = srgb_to_linear(c.v[static_cast<std::size_t>(i)]);
  return c;
}

Value Interpreter::colour_expression(const Pos& at) {
  // `color` EXPR, then any of red/green/blue/filter/transmit/gray VALUE.
  Value c;
  c.kind = Value::Vector;
  c.colour = true;
  c.dims = 5;
  const Token& t = tok();
  const bool component_first =
      t.kind == Token::Word &&
      (t.text == "red" || t.text == "green" || t.text == "blue" || t.text == "filter" ||
       t.text == "transmit" || t.text == "gray" || t.text == "grey");
  if (!component_first) {
    const Value v = expression();
    if (!v.is_numeric()) fail_at(at, std::string("color needs a colour, got ") + kind_name(v));
    if (v.kind == Value::Float) {
      for (int i = 0; i < 5; ++i) c.v[static_cast<std::size_t>(i)] = v.v[0];
    } else {
      for (int i = 0; i < v.dims; ++i)
        c.v[static_cast<std::size_t>(i)] = v.v[static_cast<std::size_t>(i)];
    }
  }
  return colour_modifiers(c);
}

Value Interpreter::colour_modifiers(Value c) {
  for (;;) {
    const Token& n = peek_operator();
    if (pending_ || n.kind != Token::Word) break;
    int k = n.text == "red"                          ? 0
            : n.text == "green"                      ? 1
            : n.text == "blue"                       ? 2
            : n.text == "filter"                     ? 3
            : n.text == "transmit"                   ? 4
            : (n.text == "gray" || n.text == "grey") ? 5
                                                     : -1;
    if (k < 0) break;
    if (c.kind == Value::Float) {
      const double f = c.v[0];
      c = Value::vector({f, f, f, 0, 0});
    }
    c.kind = Value::Vector;
    c.colour = true;
    c.dims = 5;
    next();
    const double x = number("a colour component");
    if (k == 5)
      c.v[0] = c.v[1] = c.v[2] = x;
    else
      c.v[static_cast<std::size_t>(k)] = x;
  }
  return c;
}

Value Interpreter::postfix(Value v) {
  for (;;) {
    const Token& t = peek_operator();
    if (pending_) return v;
    if (pov::is_symbol(t, ".")) {
      const Pos at = t.pos;
      next();
      if (tok().kind != Token::Word) unexpected("a component name after '.'");
      const std::string c = tok().text;
      next();
      int k = c == "x" || c == "u" || c == "red"     ? 0
              : c == "y" || c == "v" || c == "green" ? 1
              : c == "z" || c == "blue"              ? 2
              : c == "t" || c == "filter"            ? 3
              : c == "transmit"                      ? 4
              : c == "gray" || c == "grey"           ? 5
              : c == "hf"                            ? 6
                                                     : -1;
      if (k < 0) fail_at(at, "unknown component '." + c + "'");
      if (v.kind == Value::Float && k == 0) continue;
      if (v.kind != Value::Vector) fail_at(at, "'." + c + "' needs a vector, got " + kind_name(v));
      if (k == 5) {
        v = Value::number(0.297 * v.v[0] + 0.589 * v.v[1] + 0.114 * v.v[2]);
      } else if (k == 6) {
        v = Value::number(v.v[0] + v.v[1] / 256.0);
      } else {
        // A shorter vector reads 0 past its end (POV-Ray keeps every vector at 5 components).
        v = Value::number(k < v.dims ? v.v[static_cast<std::size_t>(k)] : 0);
      }
    } else if (pov::is_symbol(t, "[") && v.kind == Value::Array) {
      const Pos at = t.pos;
      const std::shared_ptr<ArrayValue> a = v.array;
      std::size_t index = 0;
      for (std::size_t k = 0; k < a->sizes.size(); ++k) {
        expect_symbol("[", "for the array's next index");
        const Pos ip = tok().pos;
        const double i = number("an array index");
        if (!is_symbol("]")) unexpected("']' after the index");
        next();
        if (!(i >= 0 && i < a->sizes[k]))
          fail_at(ip, "array index " + std::to_string(static_cast<long long>(std::floor(i))) +
                          " out of range [0, " + std::to_string(a->sizes[k] - 1) + "]");
        index = index * static_cast<std::size_t>(a->sizes[k]) + static_cast<std::size_t>(i);
      }
      if (!a->elements[index]) fail_at(at, "this array element was never assigned");
      v = *a->elements[index];
      // A function held in an array is called as a declared one: Fns[0](1, 2).
      if ((v.kind == Value::Function || v.kind == Value::Spline) &&
          pov::is_symbol(peek_operator(), "(") && !pending_) {
        const Value f = v;
        v = call_value(f, Token{Token::Word, "the array's function", 0, at});
      }
    } else {
      return v;
    }
  }
}

Value Interpreter::primary(int vector_depth) {
  const Token t = tok();
  switch (t.kind) {
    case Token::Number:
      next();
      return postfix(Value::number(t.number));
    case Token::String:
      next();
      return Value::string(t.text);
    case Token::Symbol:
      if (t.text == "(") {
        next();
        const Value v = [&] {
          const ParenDepth inside(*this, paren_depth_ + 1);
          return sub_expression(0);
        }();
        if (!is_symbol(")")) unexpected("')'");
        next();
        return postfix(v);
      }
      if (t.text == "<") {
        next();
        return postfix(vector_literal(t.pos));
      }
      unexpected("a value");
    case Token::Word:
      break;
    default:
      unexpected("a value");
  }
  (void)vector_depth;
  const std::string& w = t.text;
  const std::string_view word = w;  // compared with literals inline
  if (Symbol* s = find_symbol(w)) {
    next();
    const Value& v = s->value;
    if (v.kind == Value::Function || v.kind == Value::Spline) {
      if (!pov::is_symbol(peek_operator(), "(") || pending_) return v;
      return postfix(call_value(v, t));
    }
    return postfix(v);
  }
  if (word == "rgb" || word == "rgbf" || word == "rgbt" || word == "rgbft" || word == "srgb" ||
      word == "srgbf" || word == "srgbt" || word == "srgbft") {
    next();
    return colour_keyword(t);
  }
  if (word == "color" || word == "colour") {
    next();
    return colour_expression(t.pos);
  }
  if (is_builtin(w)) return postfix(builtin(t));
  fail_at(t.pos, "unknown word '" + w + "' (not #declared, and not a keyword of an expression)");
}

}  // namespace raycast::pov
