// function { } and spline { } values, and calling them in expressions.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "pov/internal_functions.h"
#include "pov/interpreter.h"

namespace raycast::pov {

namespace {
std::shared_ptr<const FnNode> make(FnNode::Kind k, std::vector<std::shared_ptr<const FnNode>> a) {
  auto f = std::make_shared<FnNode>();
  f->kind = k;
  f->args = std::move(a);
  return f;
}
std::shared_ptr<const FnNode> num(double v) {
  auto f = std::make_shared<FnNode>();
  f->number = v;
  return f;
}
std::shared_ptr<const FnNode> call(const std::string& name,
                                   std::vector<std::shared_ptr<const FnNode>> a) {
  auto f = std::make_shared<FnNode>();
  f->kind = FnNode::Call;
  f->function = name;
  f->args = std::move(a);
  return f;
}
}  // namespace

// The function language, POV-Ray's float expression syntax over the parameters, read by
// recursive descent from the interpreter's token stream into a tree of FnNode.
class FunctionParser {
 public:
  Interpreter& in;
  const std::vector<std::string>& params;
  int depth;
  std::shared_ptr<const FnNode> cond() {
    auto c = logic();
    if (in.accept_symbol("?")) {
      auto a = cond();
      in.expect_symbol(":", "in 'a ? b : c'");
      auto b = cond();
      return call("if", {c, a, b});
    }
    return c;
  }
  std::shared_ptr<const FnNode> logic() {
    auto a = compare();
    for (;;) {
      if (in.accept_symbol("&"))
        a = call("and", {a, compare()});
      else if (in.accept_symbol("|"))
        a = call("or", {a, compare()});
      else
        return a;
    }
  }
  std::shared_ptr<const FnNode> compare() {
    auto a = sum();
    for (;;) {
      const char* n = in.is_symbol("<")    ? "lt"
                      : in.is_symbol("<=") ? "le"
                      : in.is_symbol(">")  ? "gt"
                      : in.is_symbol(">=") ? "ge"
                      : in.is_symbol("=")  ? "eq"
                      : in.is_symbol("!=") ? "ne"
                                           : nullptr;
      if (!n) return a;
      in.next();
      a = call(n, {a, sum()});
    }
  }
  std::shared_ptr<const FnNode> sum() {
    auto a = product();
    for (;;) {
      if (in.accept_symbol("+"))
        a = make(FnNode::Add, {a, product()});
      else if (in.accept_symbol("-"))
        a = make(FnNode::Subtract, {a, product()});
      else
        return a;
    }
  }
  std::shared_ptr<const FnNode> product() {
    auto a = unary();
    for (;;) {
      if (in.accept_symbol("*"))
        a = make(FnNode::Multiply, {a, unary()});
      else if (in.accept_symbol("/"))
        a = make(FnNode::Divide, {a, unary()});
      else
        return a;
    }
  }
  std::shared_ptr<const FnNode> unary() {
    if (++depth > kMaxPovNesting) in.fail_here("the function is nested too deeply");
    std::shared_ptr<const FnNode> r;
    if (in.accept_symbol("-"))
      r = make(FnNode::Negate, {unary()});
    else if (in.accept_symbol("+"))
      r = unary();
    else if (in.accept_symbol("!"))
      r = call("not", {unary()});
    else
      r = primary();
    --depth;
    return r;
  }
  std::vector<std::shared_ptr<const FnNode>> args() {
    in.expect_symbol("(", "to open the arguments");
    std::vector<std::shared_ptr<const FnNode>> a;
    if (!in.is_symbol(")")) {
      for (;;) {
        a.push_back(cond());
        if (!in.accept_symbol(",")) break;
      }
    }
    in.expect_symbol(")", "to close the arguments");
    return a;
  }
  std::shared_ptr<const FnNode> primary() {
    const Token t = in.tok();
    if (t.kind == Token::Number) {
      in.next();
      return num(t.number);
    }
    if (in.accept_symbol("(")) {
      auto e = cond();
      in.expect_symbol(")", "to close '('");
      return e;
    }
    if (t.kind != Token::Word) in.unexpected("a number, a parameter or a function");
    in.next();
    for (std::size_t i = 0; i < params.size(); ++i)
      if (params[i] == t.text) {
        auto f = std::make_shared<FnNode>();
        f->kind = FnNode::Param;
        f->number = static_cast<double>(i);
        return f;
      }
    if (t.text == "pi") return num(std::numbers::pi);
    if (!in.lookup(t.text) && in.is_builtin(t.text) && t.text != "x" && t.text != "y" &&
        t.text != "z" && t.text != "min" && t.text != "max" && t.text != "select" &&
        !in.is_symbol("(")) {
      // A constant of the scene (clock, image_width ...), fixed when the function is read.
      const Value c = in.builtin_constant(t);
      if (c.kind == Value::Float) return num(c.v[0]);
    }
    if (t.text == "internal") {
      args();
      auto f = std::make_shared<FnNode>();
      f->kind = FnNode::Call;
      f->function = "internal";
      return f;
    }
    if (const Value* v = in.lookup(t.text)) {
      if (v->kind == Value::Float) return num(v->v[0]);
      if (v->kind == Value::Function) {
        auto f = std::make_shared<FnNode>();
        f->kind = FnNode::User;
        f->callee = v->function;
        f->args = args();
        if (in.is_symbol(".")) {  // a component of a vector or colour function's value
          in.next();
          const Token c = in.tok();
          const int k = component_index(c.text);
          if (k < 0) in.fail_at(c.pos, "unknown component '." + c.text + "'");
          in.next();
          auto pick = std::make_shared<FnNode>();
          pick->kind = FnNode::Call;
          pick->function = "component";
          pick->number = k;
          pick->args = {f};
          return pick;
        }
        return f;
      }
      if (v->kind == Value::Vector && in.is_symbol(".")) {
        in.next();
        const std::string c = in.tok().text;
        in.next();
        const int k = c == "x" || c == "u"   ? 0
                      : c == "y" || c == "v" ? 1
                      : c == "z"             ? 2
                      : c == "t"             ? 3
                                             : 4;
        return num(v->v[static_cast<std::size_t>(std::min(k, 4))]);
      }
      in.fail_at(t.pos, "'" + t.text + "' is " + kind_name(*v) + ", not a float or a function");
    }
    if (t.text == "ln") return call("log", args());
    if (t.text == "log") return make(FnNode::Divide, {call("log", args()), num(std::log(10.0))});
    static const char* const known[] = {
        "sin",   "cos",   "tan",   "asin",  "acos", "atan",   "sinh",    "cosh",   "tanh",
        "asinh", "acosh", "atanh", "sqrt",  "exp",  "abs",    "floor",   "ceil",   "int",
        "min",   "max",   "pow",   "atan2", "mod",  "select", "radians", "degrees"};
    for (const char* k : known)
      if (t.text == k) {
        auto a = args();
        if (t.text == "pow" && a.size() == 2) return make(FnNode::Power, a);
        return call(t.text, a);
      }
    if (t.text == "x" || t.text == "y" || t.text == "z") {
      auto f = std::make_shared<FnNode>();
      f->kind = FnNode::Variable;
      f->variable = t.text[0];
      return f;
    }
    in.fail_at(t.pos, "unknown word '" + t.text + "' in a function");
  }
};

std::shared_ptr<const FnNode> Interpreter::function_expression(
    int depth, const std::vector<std::string>& params) {
  if (depth > kMaxPovNesting) fail_here("the function is nested too deeply");
  FunctionParser p{*this, params, depth};
  return p.cond();
}

Value Interpreter::function_block(const Pos& at) {
  auto f = std::make_shared<FunctionValue>();
  f->params = {"x", "y", "z"};
  if (accept_symbol("(")) {
    f->params.clear();
    while (!accept_symbol(")")) {
      if (tok().kind != Token::Word) unexpected("a parameter name");
      f->params.push_back(tok().text);
      next();
      accept_symbol(",");
    }
  }
  expect_symbol("{", "after function");
  if (is_word("pigment") || is_word("pattern")) {
    // A pigment function: the pigment read whole; a pattern function: the pattern of a
    // pigment read the same way (its colour map unused). One using what raycast does not
    // render is opaque, warned about where it is called (include files declare many).
    const std::string kind = tok().text + " function";
    const bool pattern = kind == "pattern function";
    next();
    struct Quiet {
      Interpreter& in;
      bool outer;
      explicit Quiet(Interpreter& i) : in(i), outer(i.quiet_missed_) {
        ++in.quiet_;
        in.quiet_missed_ = false;
      }
      ~Quiet() {
        --in.quiet_;
        in.quiet_missed_ = outer;
      }
    };
    bool missed = false;
    Pigment p;
    {
      const Quiet quiet(*this);
      p = pigment_block(Pigment{});
      missed = quiet_missed_;
    }
    if (missed || (pattern && !p.model)) {
      f->opaque = kind;
    } else if (pattern) {
      f->pattern = std::make_shared<const texture::Pattern>(p.model->pattern);
    } else if (p.model) {
      f->pigment = p.model;
    } else {
      texture::Pigment solid;
      solid.color = {{p.c0.r, p.c0.g, p.c0.b}, p.c0.filter, p.c0.transmit};
      f->pigment = std::make_shared<const texture::Pigment>(solid);
    }
    expect_symbol("}", "to close the function");
  } else if (is_word("spline")) {
    next();
    f->spline = spline_block(at).spline;
    expect_symbol("}", "to close the function");
  } else if (is_word("transform")) {
    f->opaque = tok().text + " function";
    next();
    skip_block_rest("function");
  } else if (is_word("internal")) {
    // functions.inc's built-in functions, by number: raycast's own definitions, with their
    // parameter lists (x, y, z and the documented extra parameters).
    next();
    expect_symbol("(", "after internal");
    const double number = this->number("an internal function's number");
    expect_symbol(")", "to close internal( )");
    expect_symbol("}", "to close the function");
    if (auto known = internal_function(static_cast<int>(number))) {
      *f = *known;
    } else {
      f->body = call("internal", {});
      f->opaque = "internal function";
    }
  } else {
    f->body = function_expression(0, f->params);
    expect_symbol("}", "to close the function");
  }
  Value v;
  v.kind = Value::Function;
  v.function = f;
  return v;
}

Value Interpreter::spline_block(const Pos& at) {
  expect_symbol("{", "after spline");
  auto s = std::make_shared<SplineValue>();
  if (const Value* base = tok().kind == Token::Word ? lookup(tok().text) : nullptr;
      base && base->kind == Value::Spline) {
    *s = *base->spline;
    next();
  }
  while (!accept_symbol("}")) {
    if (is_word("linear_spline")) {
      next();
      s->type = SplineValue::Linear;
      continue;
    }
    if (is_word("quadratic_spline")) {
      next();
      s->type = SplineValue::Quadratic;
      continue;
    }
    if (is_word("cubic_spline")) {
      next();
      s->type = SplineValue::Cubic;
      continue;
    }
    if (is_word("natural_spline")) {
      next();
      s->type = SplineValue::Natural;
      continue;
    }
    const double t = number("a spline's parameter");
    expect_symbol(",", "after the spline's parameter");
    const Value p = expression();
    if (!p.is_numeric()) fail_at(at, "a spline's points are vectors");
    std::array<double, 5> c{};
    for (int i = 0; i < 5; ++i)
      c[static_cast<std::size_t>(i)] =
          p.kind == Value::Float ? p.v[0] : p.v[static_cast<std::size_t>(i)];
    s->dims = std::max(s->dims, p.dims);
    // Kept sorted by parameter (POV-Ray sorts the points).
    auto it = std::lower_bound(s->t.begin(), s->t.end(), t);
    const auto k = it - s->t.begin();
    s->t.insert(it, t);
    s->p.insert(s->p.begin() + k, c);
    accept_symbol(",");
  }
  Value v;
  v.kind = Value::Spline;
  v.spline = s;
  return v;
}

Value Interpreter::call_value(const Value& f, const Token& name) {
  expect_symbol("(", ("after " + name.text).c_str());
  std::vector<double> args;
  std::vector<Value> raw_args;
  std::optional<ParenDepth> arguments(std::in_place, *this, 1);
  if (!is_symbol(")")) {
    for (;;) {
      const Value a = expression();
      if (a.kind == Value::Float) args.push_back(a.v[0]);
      raw_args.push_back(a);
      if (!accept_symbol(",")) break;
    }
  }
  arguments.reset();
  if (!is_symbol(")")) unexpected("')' to close the call of " + name.text);
  next();
  if (f.kind == Value::Spline) {
    if (args.empty()) fail_at(name.pos, "a spline takes its parameter: " + name.text + "(t)");
    const auto r = spline_at(*f.spline, args[0]);
    Value v;
    v.kind = Value::Vector;
    v.dims = std::max(2, f.spline->dims);
    for (int i = 0; i < 5; ++i) v.v[static_cast<std::size_t>(i)] = r[static_cast<std::size_t>(i)];
    return v;
  }
  if (!f.function->opaque.empty()) {
    unsupported_warning(name.pos, "calls of a " + f.function->opaque, "its value is 0");
    return Value::number(0);
  }
  if (f.function->pigment || f.function->pattern || f.function->spline) {
    // A pigment function's colour (a pattern function's value in every channel, a spline's
    // point).
    double c[5];
    vector_value(*f.function, args.size() > 0 ? args[0] : 0, args.size() > 1 ? args[1] : 0,
                 args.size() > 2 ? args[2] : 0, c);
    if (f.function->pattern) return Value::number(c[0]);
    return Value::vector({c[0], c[1], c[2], c[3], c[4]});
  }
  if (args.size() != raw_args.size() || args.size() != f.function->params.size())
    fail_at(name.pos, name.text + " takes " + std::to_string(f.function->params.size()) +
                          " float argument(s)");
  return Value::number(evaluate(*f.function, args));
}

}  // namespace raycast::pov
