#include "pov/function_expr.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <sstream>

#include "pov/internal_functions.h"
#include "pov/value.h"
#include "texture/noise.h"

namespace raycast::pov {

namespace {

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

constexpr int kMaxCallDepth = 64;
constexpr double kMaxUnrolledFrequency = 64;

double eval(const FnNode& n, const std::vector<double>& a, int depth);

// A component of a pigment or pattern function's value (F(x, y, z).red); of a scalar function's
// value, the value.
double component(const FnNode& n, const std::vector<double>& a, int depth) {
  if (n.args.size() != 1) return std::nan("");
  const FnNode& call = *n.args[0];
  if (call.kind != FnNode::User || !call.callee || depth > kMaxCallDepth ||
      (!call.callee->pigment && !call.callee->pattern && !call.callee->spline))
    return eval(call, a, depth);
  double p[3] = {0, 0, 0};
  for (std::size_t i = 0; i < 3 && i < call.args.size(); ++i) p[i] = eval(*call.args[i], a, depth);
  double v[5];
  vector_value(*call.callee, p[0], p[1], p[2], v);
  const int k = static_cast<int>(n.number);
  // POV-Ray's grey of a colour: the luminance weights of its `.gray`.
  if (k == kGrayComponent) return 0.297 * v[0] + 0.589 * v[1] + 0.114 * v[2];
  return k >= 0 && k < 5 ? v[k] : std::nan("");
}

double eval(const FnNode& n, const std::vector<double>& a, int depth) {
  auto arg = [&](std::size_t i) { return eval(*n.args[i], a, depth); };
  switch (n.kind) {
    case FnNode::Number:
      return n.number;
    case FnNode::Variable:
      return a.size() > static_cast<std::size_t>(n.variable - 'x')
                 ? a[static_cast<std::size_t>(n.variable - 'x')]
                 : 0;
    case FnNode::Param: {
      const auto i = static_cast<std::size_t>(n.number);
      return i < a.size() ? a[i] : 0;
    }
    case FnNode::Negate:
      return -arg(0);
    case FnNode::Add:
      return arg(0) + arg(1);
    case FnNode::Subtract:
      return arg(0) - arg(1);
    case FnNode::Multiply:
      return arg(0) * arg(1);
    case FnNode::Divide:
      return arg(0) / arg(1);
    case FnNode::Power:
      return std::pow(arg(0), arg(1));
    case FnNode::User: {
      if (depth > kMaxCallDepth || !n.callee) return std::nan("");
      if (n.callee->pigment || n.callee->pattern || n.callee->spline) {
        // A colour read as a number: its first component.
        double v[5];
        vector_value(*n.callee, n.args.size() > 0 ? arg(0) : 0, n.args.size() > 1 ? arg(1) : 0,
                     n.args.size() > 2 ? arg(2) : 0, v);
        return v[0];
      }
      if (!n.callee->body) return std::nan("");
      std::vector<double> b;
      for (std::size_t i = 0; i < n.args.size(); ++i) b.push_back(arg(i));
      return eval(*n.callee->body, b, depth + 1);
    }
    case FnNode::Call:
      if (n.function == "component") return component(n, a, depth + 1);
      break;
  }
  const std::string& f = n.function;
  const std::size_t k = n.args.size();
  if (k == 1) {
    static const std::map<std::string, double (*)(double)> one = {
        {"sin", [](double v) { return std::sin(v); }},
        {"cos", [](double v) { return std::cos(v); }},
        {"tan", [](double v) { return std::tan(v); }},
        {"asin", [](double v) { return std::asin(v); }},
        {"acos", [](double v) { return std::acos(v); }},
        {"atan", [](double v) { return std::atan(v); }},
        {"sinh", [](double v) { return std::sinh(v); }},
        {"cosh", [](double v) { return std::cosh(v); }},
        {"tanh", [](double v) { return std::tanh(v); }},
        {"asinh", [](double v) { return std::asinh(v); }},
        {"acosh", [](double v) { return std::acosh(v); }},
        {"atanh", [](double v) { return std::atanh(v); }},
        {"sqrt", [](double v) { return std::sqrt(v); }},
        {"exp", [](double v) { return std::exp(v); }},
        {"log", [](double v) { return std::log(v); }},
        {"log10", [](double v) { return std::log10(v); }},
        {"abs", [](double v) { return std::fabs(v); }},
        {"floor", [](double v) { return std::floor(v); }},
        {"ceil", [](double v) { return std::ceil(v); }},
        {"int", [](double v) { return std::trunc(v); }},
        {"not", [](double v) { return v == 0 ? 1.0 : 0.0; }},
        {"radians", [](double v) { return v * std::numbers::pi / 180; }},
        {"degrees", [](double v) { return v * 180 / std::numbers::pi; }}};
    const auto it = one.find(f);
    if (it != one.end()) return it->second(arg(0));
  }
  if (f == "min" || f == "max") {
    double r = arg(0);
    for (std::size_t i = 1; i < k; ++i) r = f == "min" ? std::min(r, arg(i)) : std::max(r, arg(i));
    return r;
  }
  if (k == 2) {
    const double p = arg(0), q = arg(1);
    if (f == "pow") return std::pow(p, q);
    if (f == "atan2") return std::atan2(p, q);
    if (f == "mod") return std::fmod(p, q);
    if (f == "lt") return p < q;
    if (f == "le") return p <= q;
    if (f == "gt") return p > q;
    if (f == "ge") return p >= q;
    if (f == "eq") return p == q;
    if (f == "ne") return p != q;
    if (f == "and") return p != 0 && q != 0;
    if (f == "or") return p != 0 || q != 0;
  }
  if (f == "select" && (k == 3 || k == 4)) {
    const double s = arg(0);
    if (k == 3) return s < 0 ? arg(1) : arg(2);
    return s < 0 ? arg(1) : s == 0 ? arg(2) : arg(3);
  }
  if (f == "if" && k == 3) return arg(0) != 0 ? arg(1) : arg(2);
  if (f == "floor" && k == 1) return std::floor(arg(0));
  if (f == "ridged_mf" && k == 9) {
    double v[9];
    for (std::size_t i = 0; i < 9; ++i) v[i] = arg(i);
    return ridged_mf(v);
  }
  if (f == "noise3d" && k == 4)
    return texture::noise({arg(0), arg(1), arg(2)}, static_cast<int>(arg(3)));
  return std::nan("");
}

bool is_constant(const FnNode& n) {
  if (n.kind == FnNode::Variable || n.kind == FnNode::Param || n.kind == FnNode::User) return false;
  for (const auto& a : n.args)
    if (!is_constant(*a)) return false;
  return true;
}

// A comparison of constants, or a choice on a constant condition, made now: formulas have no
// comparisons, and the switches of functions.inc's functions are constant in practice. A fractal
// noise with constant parameters becomes its octaves' sum.
std::shared_ptr<const FnNode> fold_choice(const std::shared_ptr<const FnNode>& n) {
  if (n->kind != FnNode::Call) return n;
  if (n->function == "ridged_mf" && n->args.size() == 9) {  // its octaves unrolled
    double v[9] = {};
    for (std::size_t i = 3; i < 9; ++i) {
      if (!is_constant(*n->args[i])) return n;
      v[i] = eval(*n->args[i], {}, 0);
    }
    // Octaves far finer than the first make the formula's intervals useless until the pieces
    // are as fine: past a top frequency of 64 the isosurface solver would run out of steps on
    // every ray, so such a sum stays a call (not a formula: the isosurface is left out, warned).
    if (!(std::pow(std::abs(v[4]), std::clamp(v[5], 1.0, 10.0) - 1) <= kMaxUnrolledFrequency))
      return n;
    return ridged_mf_tree(n->args[0], n->args[1], n->args[2], v);
  }
  static const char* const kFoldable[] = {"if", "select", "lt",  "le", "gt", "ge",
                                          "eq", "ne",     "and", "or", "not"};
  bool foldable = false;
  for (const char* f : kFoldable) foldable = foldable || n->function == f;
  if (!foldable) return n;
  const bool choice = n->function == "if" || n->function == "select";
  for (std::size_t i = 0; i < (choice ? 1 : n->args.size()); ++i)
    if (!is_constant(*n->args[i])) return n;
  if (!choice) {
    auto r = std::make_shared<FnNode>();
    r->number = eval(*n, {}, 0);
    return r;
  }
  const double c = eval(*n->args[0], {}, 0);
  const std::size_t k = n->args.size();
  if (n->function == "if" && k == 3) return n->args[c != 0 ? 1 : 2];
  if (k == 3) return n->args[c < 0 ? 1 : 2];
  if (k == 4) return n->args[c < 0 ? 1 : (c == 0 ? 2 : 3)];
  return n;
}

// The tree with every user call replaced by the callee's body over the call's arguments.
std::shared_ptr<const FnNode> inline_calls(const std::shared_ptr<const FnNode>& n,
                                           const std::vector<std::shared_ptr<const FnNode>>& args,
                                           int depth) {
  if (depth > kMaxCallDepth) return nullptr;
  if (n->kind == FnNode::Param) {
    const auto i = static_cast<std::size_t>(n->number);
    return i < args.size() ? args[i] : nullptr;
  }
  auto out = std::make_shared<FnNode>(*n);
  for (auto& a : out->args) {
    a = inline_calls(a, args, depth);
    if (!a) return nullptr;
  }
  if (n->kind == FnNode::User) {
    if (!n->callee || !n->callee->body) return nullptr;
    return inline_calls(n->callee->body, out->args, depth + 1);
  }
  return fold_choice(out);
}

// The generator of a noise3d call when formulas can name it (noise1, noise2, noise3), else 0.
int noise_generator(const FnNode& n) {
  if (n.args.size() != 4 || !is_constant(*n.args[3])) return 0;
  const double g = eval(*n.args[3], {}, 0);
  return g == 1 || g == 2 || g == 3 ? static_cast<int>(g) : 0;
}

bool expressible(const FnNode& n) {
  if (n.kind == FnNode::Call && n.function == "noise3d") {
    if (!noise_generator(n)) return false;
    for (std::size_t i = 0; i < 3; ++i)
      if (!expressible(*n.args[i])) return false;
    return true;
  }
  if (n.kind == FnNode::Call) {
    static const char* const ok[] = {"sqrt", "exp", "log", "sin", "cos",   "tan",
                                     "abs",  "min", "max", "pow", "atan2", "floor"};
    bool found = false;
    for (const char* o : ok) found = found || n.function == o;
    if (!found) return false;
  }
  if (n.kind == FnNode::User || n.kind == FnNode::Param) return false;
  for (const auto& a : n.args)
    if (!expressible(*a)) return false;
  return true;
}

}  // namespace

double evaluate(const FunctionValue& f, const std::vector<double>& args) {
  if (f.pigment || f.pattern || f.spline) {
    double v[5];
    vector_value(f, args.size() > 0 ? args[0] : 0, args.size() > 1 ? args[1] : 0,
                 args.size() > 2 ? args[2] : 0, v);
    return v[0];
  }
  if (!f.body) return std::nan("");
  return eval(*f.body, args, 0);
}

namespace {

class UserPatternFunction final : public texture::PatternFunction {
 public:
  explicit UserPatternFunction(std::shared_ptr<const FunctionValue> f) : f_(std::move(f)) {}
  double value(const Vec3& p) const override {
    // The extra parameters of a function of more than three read 0, as in POV-Ray.
    std::vector<double> args(std::max<std::size_t>(3, f_->params.size()), 0.0);
    args[0] = p.x, args[1] = p.y, args[2] = p.z;
    return evaluate(*f_, args);
  }

 private:
  std::shared_ptr<const FunctionValue> f_;
};

}  // namespace

std::shared_ptr<const texture::PatternFunction> pattern_function(
    std::shared_ptr<const FunctionValue> f) {
  return std::make_shared<UserPatternFunction>(std::move(f));
}

std::array<double, 5> spline_at(const SplineValue& s, double t) {
  const std::size_t n = s.t.size();
  if (n == 0) return {};
  // A cubic_spline's first and last points only steer its ends (POV-Ray): the curve runs from
  // the second point to the last but one and keeps their values beyond them.
  const std::size_t first = s.type == SplineValue::Cubic && n >= 4 ? 1 : 0;
  const std::size_t last = n - 1 - first;
  if (n == 1 || t <= s.t[first]) return s.p[first];
  if (t >= s.t[last]) return s.p[last];
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(s.t.begin(), s.t.end(), t) - s.t.begin()) - 1;
  const double u = (t - s.t[i]) / (s.t[i + 1] - s.t[i]);
  std::array<double, 5> r{};
  if (s.type == SplineValue::Linear || n < 3) {
    for (int k = 0; k < 5; ++k)
      r[static_cast<std::size_t>(k)] = s.p[i][static_cast<std::size_t>(k)] * (1 - u) +
                                       s.p[i + 1][static_cast<std::size_t>(k)] * u;
    return r;
  }
  // Catmull-Rom through the points, the end tangents from the end segments.
  const auto& p0 = s.p[i > 0 ? i - 1 : i];
  const auto& p1 = s.p[i];
  const auto& p2 = s.p[i + 1];
  const auto& p3 = s.p[i + 2 < n ? i + 2 : i + 1];
  for (std::size_t k = 0; k < 5; ++k) {
    const double a = (-p0[k] + 3 * p1[k] - 3 * p2[k] + p3[k]) * 0.5;
    const double b = (2 * p0[k] - 5 * p1[k] + 4 * p2[k] - p3[k]) * 0.5;
    const double c = (p2[k] - p0[k]) * 0.5;
    r[k] = ((a * u + b) * u + c) * u + p1[k];
  }
  return r;
}

int component_index(const std::string& c) {
  if (c == "x" || c == "red" || c == "r" || c == "u") return 0;
  if (c == "y" || c == "green" || c == "g" || c == "v") return 1;
  if (c == "z" || c == "blue" || c == "b") return 2;
  if (c == "filter" || c == "f" || c == "t") return 3;
  if (c == "transmit") return 4;
  if (c == "gray" || c == "grey") return kGrayComponent;
  return -1;
}

bool vector_value(const FunctionValue& f, double x, double y, double z, double out[5]) {
  if (f.pigment) {
    const texture::Rgbft c = texture::evaluate(*f.pigment, {x, y, z});
    out[0] = c.rgb.x, out[1] = c.rgb.y, out[2] = c.rgb.z, out[3] = c.filter, out[4] = c.transmit;
    return true;
  }
  if (f.spline) {
    const std::array<double, 5> p = spline_at(*f.spline, x);
    for (std::size_t i = 0; i < 5; ++i) out[i] = p[i];
    return true;
  }
  if (f.pattern) {
    const double v = texture::evaluate(*f.pattern, {x, y, z});
    for (int i = 0; i < 5; ++i) out[i] = v;
    return true;
  }
  for (int i = 0; i < 5; ++i) out[i] = std::nan("");
  return false;
}

std::string formula_text(const FunctionValue& f, bool mirror_z) {
  if (!f.body || !f.opaque.empty()) return "";
  std::vector<std::shared_ptr<const FnNode>> xyz;
  for (char c : {'x', 'y', 'z'}) {
    auto v = std::make_shared<FnNode>();
    v->kind = FnNode::Variable;
    v->variable = c;
    xyz.push_back(v);
  }
  const auto body = inline_calls(f.body, xyz, 0);
  if (!body || !expressible(*body)) return "";
  return formula_text(*body, mirror_z);
}

std::string formula_text(const FnNode& f, bool mirror_z) {
  // Every compound is parenthesised: the text is for the formula parser, with its own precedence.
  std::ostringstream o;
  auto arg = [&](std::size_t i) { return formula_text(*f.args[i], mirror_z); };
  const char* op = nullptr;
  switch (f.kind) {
    case FnNode::Number:
      if (f.number < 0)
        o << "(" << number_text(f.number) << ")";
      else
        o << number_text(f.number);
      return o.str();
    case FnNode::Variable:
      if (mirror_z && f.variable == 'z') return "(-z)";
      return std::string(1, f.variable);
    case FnNode::Negate:
      o << "(-" << arg(0) << ")";
      return o.str();
    case FnNode::Add:
      op = " + ";
      break;
    case FnNode::Subtract:
      op = " - ";
      break;
    case FnNode::Multiply:
      op = " * ";
      break;
    case FnNode::Divide:
      op = " / ";
      break;
    case FnNode::Power:
      o << "pow(" << arg(0) << ", " << arg(1) << ")";
      return o.str();
    case FnNode::Call:
      if (f.function == "noise3d" && noise_generator(f)) {
        o << "noise" << noise_generator(f) << "(" << arg(0) << ", " << arg(1) << ", " << arg(2)
          << ")";
        return o.str();
      }
      o << f.function << "(";
      for (std::size_t i = 0; i < f.args.size(); ++i) o << (i ? ", " : "") << arg(i);
      o << ")";
      return o.str();
    case FnNode::Param:
    case FnNode::User:
      return "0";
  }
  o << "(" << arg(0) << op << arg(1) << ")";
  return o.str();
}

}  // namespace raycast::pov
