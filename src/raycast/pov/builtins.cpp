// Built-in constants and functions of floats, vectors and strings (POV-Ray 3.7's reference,
// "Float Functions", "Vector Functions", "String Functions", "Built-in Constants").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>

#include "pov/interpreter.h"
#include "texture/noise.h"

namespace raycast::pov {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

enum class Arg { F, V, S, Any };

// POV-Ray rotates about x, then y, then z, each by the right-hand rule's matrix.
Vec3 rotate_xyz(Vec3 p, const Vec3& deg) {
  const double a = deg.x * kDegree, b = deg.y * kDegree, c = deg.z * kDegree;
  p = {p.x, p.y * std::cos(a) - p.z * std::sin(a), p.y * std::sin(a) + p.z * std::cos(a)};
  p = {p.x * std::cos(b) + p.z * std::sin(b), p.y, -p.x * std::sin(b) + p.z * std::cos(b)};
  p = {p.x * std::cos(c) - p.y * std::sin(c), p.x * std::sin(c) + p.y * std::cos(c), p.z};
  return p;
}

Vec3 axis_rotate(const Vec3& p, Vec3 k, double deg) {
  const double l = length(k);
  if (!(l > 0)) return p;
  k = k / l;
  const double a = deg * kDegree, c = std::cos(a), s = std::sin(a);
  return p * c + cross(k, p) * s + k * (dot(k, p) * (1 - c));
}

Value vec3(const Vec3& v) { return Value::vector({v.x, v.y, v.z}); }

std::string format_number(double v, double width, double precision) {
  char buf[512];
  const int w = static_cast<int>(std::clamp(width, -100.0, 100.0));
  const int p = precision < 0 ? 6 : static_cast<int>(std::min(precision, 100.0));
  if (w < 0)
    std::snprintf(buf, sizeof buf, "%0*.*f", -w, p, v);
  else
    std::snprintf(buf, sizeof buf, "%*.*f", w, p, v);
  return buf;
}

const std::map<std::string, int>& float_constants() {
  static const std::map<std::string, int> k = {
      {"pi", 0},           {"true", 1},          {"yes", 1},
      {"on", 1},           {"false", 2},         {"no", 2},
      {"off", 2},          {"clock", 3},         {"clock_delta", 4},
      {"clock_on", 5},     {"final_clock", 6},   {"final_frame", 7},
      {"frame_number", 8}, {"initial_clock", 9}, {"initial_frame", 10},
      {"image_width", 11}, {"image_height", 12}, {"version", 13},
      {"tau", 14}};
  return k;
}

const std::map<std::string, std::vector<Arg>>& functions() {
  using A = Arg;
  static const std::map<std::string, std::vector<Arg>> f = {
      {"abs", {A::F}},
      {"acos", {A::F}},
      {"acosh", {A::F}},
      {"asin", {A::F}},
      {"asinh", {A::F}},
      {"atan", {A::F}},
      {"atanh", {A::F}},
      {"atan2", {A::F, A::F}},
      {"ceil", {A::F}},
      {"cos", {A::F}},
      {"cosh", {A::F}},
      {"degrees", {A::F}},
      {"div", {A::F, A::F}},
      {"exp", {A::F}},
      {"floor", {A::F}},
      {"int", {A::F}},
      {"ln", {A::F}},
      {"log", {A::F}},
      {"mod", {A::F, A::F}},
      {"pow", {A::F, A::F}},
      {"radians", {A::F}},
      {"sin", {A::F}},
      {"sinh", {A::F}},
      {"sqrt", {A::F}},
      {"tan", {A::F}},
      {"tanh", {A::F}},
      {"bitwise_and", {A::F, A::F}},
      {"bitwise_or", {A::F, A::F}},
      {"bitwise_xor", {A::F, A::F}},
      {"seed", {A::F}},
      {"vdot", {A::V, A::V}},
      {"vlength", {A::V}},
      {"vcross", {A::V, A::V}},
      {"vnormalize", {A::V}},
      {"vrotate", {A::V, A::V}},
      {"vaxis_rotate", {A::V, A::V, A::F}},
      {"vturbulence", {A::F, A::F, A::F, A::V}},
      {"strlen", {A::S}},
      {"strupr", {A::S}},
      {"strlwr", {A::S}},
      {"strcmp", {A::S, A::S}},
      {"substr", {A::S, A::F, A::F}},
      {"chr", {A::F}},
      {"asc", {A::S}},
      {"val", {A::S}},
      {"str", {A::F, A::F, A::F}},
      {"vstr", {A::F, A::V, A::S, A::F, A::F}},
      {"file_exists", {A::S}},
      {"datetime", {A::F}}};
  return f;
}

}  // namespace

bool Interpreter::is_builtin(const std::string& w) const {
  static constexpr std::string_view special[] = {"x",
                                                 "y",
                                                 "z",
                                                 "t",
                                                 "u",
                                                 "v",
                                                 "min",
                                                 "max",
                                                 "select",
                                                 "concat",
                                                 "defined",
                                                 "dimensions",
                                                 "dimension_size",
                                                 "rand",
                                                 "inside",
                                                 "trace",
                                                 "min_extent",
                                                 "max_extent",
                                                 "now"};
  for (const std::string_view s : special)
    if (s == w) return true;
  return float_constants().count(w) || functions().count(w);
}

Value Interpreter::builtin_constant(const Token& t) {
  if (!float_constants().count(t.text)) return Value::string("");
  // builtin() consumes its name token: give it one, then restore the stream's lookahead.
  const Token keep = cur_;
  const bool had = have_, was_pending = pending_;
  cur_ = t;
  have_ = true;
  pending_ = false;
  Value v = builtin(t);
  cur_ = keep;
  have_ = had;
  pending_ = was_pending;
  return v;
}

Value Interpreter::builtin(const Token& t) {
  const std::string& w = t.text;
  const std::string_view word = w;  // compared with literals inline
  next();
  if (w.size() == 1 && std::string("xyztuv").find(w[0]) != std::string::npos) {
    if (word == "x") return Value::vector({1, 0, 0});
    if (word == "y") return Value::vector({0, 1, 0});
    if (word == "z") return Value::vector({0, 0, 1});
    if (word == "t") return Value::vector({0, 0, 0, 1});
    if (word == "u") return Value::vector({1, 0});
    return Value::vector({0, 1});
  }
  if (const auto c = float_constants().find(w); c != float_constants().end()) {
    const Options& o = options_;
    switch (c->second) {
      case 0:
        return Value::number(std::numbers::pi);
      case 1:
        return Value::number(1);
      case 2:
        return Value::number(0);
      case 3:
        return Value::number(o.clock);
      case 4:
        return Value::number(o.final_frame > o.initial_frame ? (o.final_clock - o.initial_clock) /
                                                                   (o.final_frame - o.initial_frame)
                                                             : 0);
      case 5:
        return Value::number(o.clock_on);
      case 6:
        return Value::number(o.final_clock);
      case 7:
        return Value::number(o.final_frame);
      case 8:
        return Value::number(o.frame);
      case 9:
        return Value::number(o.initial_clock);
      case 10:
        return Value::number(o.initial_frame);
      case 11:
        return Value::number(o.width > 0 ? o.width : 640);
      case 12:
        return Value::number(o.height > 0 ? o.height : 480);
      case 13:
        return Value::number(scene_.settings.version);
      default:
        return Value::number(2 * std::numbers::pi);
    }
  }
  if (word == "now") return Value::number(0);
  expect_symbol("(", ("after " + w).c_str());
  if (word == "defined") {
    const Token nt = raw_name();
    if (nt.kind != Token::Word)
      fail_at(nt.pos, "expected a name in defined( ), got " + describe(nt));
    const bool d = find_symbol(nt.text) != nullptr;
    expect_symbol(")", "to close defined(");
    return Value::number(d);
  }
  // The arguments, read whole.
  std::vector<Value> a;
  std::vector<Pos> at;
  std::optional<Token> normal_name;  // trace's fourth argument: receives the normal
  std::optional<ParenDepth> arguments(std::in_place, *this, 1);
  if (!is_symbol(")")) {
    for (;;) {
      at.push_back(tok().pos);
      if (w == "trace" && a.size() == 3) {  // the normal's output variable, maybe undeclared
        normal_name = raw_name();
        if (normal_name->kind != Token::Word)
          fail_at(normal_name->pos, "trace's fourth argument is a name");
        a.push_back(Value::number(0));
      } else {
        a.push_back(rvalue());
      }
      if (!accept_symbol(",")) break;
    }
  }
  arguments.reset();
  if (!is_symbol(")")) unexpected("')' to close " + w + "(");
  next();
  if (w == "trace" || w == "inside" || w == "min_extent" || w == "max_extent")
    return object_query(t, a, at, normal_name);
  return call_builtin(t, a, at);
}

Value Interpreter::call_builtin(const Token& t, const std::vector<Value>& a,
                                const std::vector<Pos>& at) {
  const std::string& w = t.text;
  const std::string_view word = w;  // compared with literals inline
  auto need = [&](std::size_t n) {
    if (a.size() != n)
      fail_at(t.pos,
              w + " takes " + std::to_string(n) + " argument(s), got " + std::to_string(a.size()));
  };
  auto f = [&](std::size_t i) {
    if (a[i].kind != Value::Float) fail_at(at[i], w + ": expected a float, got " + kind_name(a[i]));
    return a[i].v[0];
  };
  auto s = [&](std::size_t i) -> const std::string& {
    if (a[i].kind != Value::String)
      fail_at(at[i], w + ": expected a string, got " + kind_name(a[i]));
    return a[i].text;
  };
  if (word == "min" || word == "max") {
    if (a.empty()) fail_at(t.pos, w + " needs at least one argument");
    double r = f(0);
    for (std::size_t i = 1; i < a.size(); ++i)
      r = word == "min" ? std::min(r, f(i)) : std::max(r, f(i));
    return Value::number(r);
  }
  if (word == "select") {
    if (a.size() != 3 && a.size() != 4) fail_at(t.pos, "select takes 3 or 4 arguments");
    const double c = f(0);
    if (a.size() == 3) return c < 0 ? a[1] : a[2];
    return c < 0 ? a[1] : c == 0 ? a[2] : a[3];
  }
  if (word == "concat") {
    std::string r;
    for (std::size_t i = 0; i < a.size(); ++i) r += s(i);
    if (r.size() > options_.limits.string_bytes) fail_at(t.pos, "the string is too long");
    return Value::string(r);
  }
  if (word == "dimensions" || word == "dimension_size") {
    if (a.empty() || a[0].kind != Value::Array) fail_at(t.pos, w + " needs an array");
    const auto& sizes = a[0].array->sizes;
    if (word == "dimensions") return Value::number(static_cast<double>(sizes.size()));
    need(2);
    const double d = f(1);
    if (!(d >= 1 && d <= sizes.size())) return Value::number(0);
    return Value::number(sizes[static_cast<std::size_t>(d) - 1]);
  }
  if (word == "rand") {
    need(1);
    const double id = f(0);
    if (!(id >= 0 && id < static_cast<double>(random_streams_.size())))
      fail_at(at[0], "rand needs a stream made by seed( )");
    // POV-Ray's sequence: a 32-bit linear congruential generator per stream, its state over
    // 2^32 - 1 as the number in [0, 1].
    std::uint32_t& st = random_streams_[static_cast<std::size_t>(id)];
    st = st * 1812433253u + 12345u;
    return Value::number(static_cast<double>(st) / 4294967295.0);
  }
  const auto& sig = functions().at(w);
  if (word == "str" || word == "vstr" || word == "substr" || word == "vturbulence" ||
      word == "vaxis_rotate")
    need(sig.size());
  else if (word == "datetime")
    ;
  else
    need(sig.size());
  if (word == "seed") {
    // The seed as a 32-bit integer (truncated; outside that range, or NaN, the lowest one, as
    // POV-Ray on x86-64 converts it), so that scenes place their random things where POV-Ray does.
    const double x = std::trunc(f(0));
    const bool in_range = x >= std::numeric_limits<std::int32_t>::min() &&
                          x <= std::numeric_limits<std::int32_t>::max();
    const std::int32_t s =
        in_range ? static_cast<std::int32_t>(x) : std::numeric_limits<std::int32_t>::min();
    random_streams_.push_back(static_cast<std::uint32_t>(s));
    return Value::number(static_cast<double>(random_streams_.size() - 1));
  }
  if (sig.size() == 1 && sig[0] == Arg::F) return float_builtin(t, f(0), at[0]);
  return vector_string_builtin(t, a, at);
}

Value Interpreter::float_builtin(const Token& t, double x, const Pos& at0) {
  const std::string& w = t.text;
  const std::string_view word = w;  // compared with literals inline
  double r;
  if (word == "abs")
    r = std::fabs(x);
  else if (word == "acos")
    r = std::acos(x);
  else if (word == "acosh")
    r = std::acosh(x);
  else if (word == "asin")
    r = std::asin(x);
  else if (word == "asinh")
    r = std::asinh(x);
  else if (word == "atan")
    r = std::atan(x);
  else if (word == "atanh")
    r = std::atanh(x);
  else if (word == "ceil")
    r = std::ceil(x);
  else if (word == "cos")
    r = std::cos(x);
  else if (word == "cosh")
    r = std::cosh(x);
  else if (word == "degrees")
    r = x / kDegree;
  else if (word == "exp")
    r = std::exp(x);
  else if (word == "floor")
    r = std::floor(x);
  else if (word == "int")
    r = std::trunc(x);
  else if (word == "ln")
    r = std::log(x);
  else if (word == "log")
    r = std::log10(x);
  else if (word == "radians")
    r = x * kDegree;
  else if (word == "sin")
    r = std::sin(x);
  else if (word == "sinh")
    r = std::sinh(x);
  else if (word == "sqrt")
    r = std::sqrt(x);
  else if (word == "tan")
    r = std::tan(x);
  else if (word == "tanh")
    r = std::tanh(x);
  else if (word == "chr") {
    if (!(x >= 1 && x < 256)) fail_at(at0, "chr needs a code in [1, 255]");
    return Value::string(std::string(1, static_cast<char>(static_cast<int>(x))));
  } else if (word == "datetime") {
    return Value::string("2000-01-01 00:00:00");
  } else
    r = x;
  if (std::isnan(r)) fail_at(t.pos, w + "(" + format_number(x, 0, 6) + ") is not a number");
  return Value::number(r);
}

Vec3 Interpreter::vector_argument(const std::string& function, const Value& v, const Pos& at) {
  if (v.kind == Value::Float) return {v.v[0], v.v[0], v.v[0]};
  if (v.kind != Value::Vector) fail_at(at, function + ": expected a vector, got " + kind_name(v));
  return {v.v[0], v.v[1], v.dims > 2 ? v.v[2] : 0};
}

Value Interpreter::vector_string_builtin(const Token& t, const std::vector<Value>& a,
                                         const std::vector<Pos>& at) {
  const std::string& w = t.text;
  const std::string_view word = w;  // compared with literals inline
  auto f = [&](std::size_t i) {
    if (a[i].kind != Value::Float) fail_at(at[i], w + ": expected a float, got " + kind_name(a[i]));
    return a[i].v[0];
  };
  auto vv = [&](std::size_t i) { return vector_argument(w, a[i], at[i]); };
  auto s = [&](std::size_t i) -> const std::string& {
    if (a[i].kind != Value::String)
      fail_at(at[i], w + ": expected a string, got " + kind_name(a[i]));
    return a[i].text;
  };
  if (word == "atan2") return Value::number(std::atan2(f(0), f(1)));
  if (word == "div") return Value::number(std::trunc(f(0) / f(1)));
  if (word == "mod") return Value::number(std::fmod(f(0), f(1)));
  if (word == "pow") return Value::number(std::pow(f(0), f(1)));
  if (w.rfind("bitwise_", 0) == 0) {
    const auto p = saturate<std::int64_t>(f(0)), q = saturate<std::int64_t>(f(1));
    return Value::number(static_cast<double>(word == "bitwise_and"  ? (p & q)
                                             : word == "bitwise_or" ? (p | q)
                                                                    : (p ^ q)));
  }
  if (word == "vdot") return Value::number(dot(vv(0), vv(1)));
  if (word == "vlength") return Value::number(length(vv(0)));
  if (word == "vcross") return vec3(cross(vv(0), vv(1)));
  if (word == "vnormalize") {
    const Vec3 p = vv(0);
    const double l = length(p);
    return vec3(l > 0 ? p / l : Vec3{0, 0, 0});
  }
  if (word == "vrotate") return vec3(rotate_xyz(vv(0), vv(1)));
  if (word == "vaxis_rotate") return vec3(axis_rotate(vv(0), vv(1), f(2)));
  if (word == "vturbulence") {  // vturbulence(Lambda, Omega, Octaves, P): turbulence's push
    texture::Turbulence turbulence;
    turbulence.amount = {1, 1, 1};
    turbulence.lambda = f(0);
    turbulence.omega = f(1);
    turbulence.octaves = static_cast<int>(std::clamp(std::trunc(f(2)), 1.0, 10.0));
    // POV-Ray's default noise (noise_generator 2).
    return vec3(texture::turbulence_offset(vv(3), turbulence, 2));
  }
  if (word == "strlen") return Value::number(static_cast<double>(s(0).size()));
  if (word == "strupr" || word == "strlwr") {
    std::string r = s(0);
    for (char& c : r)
      c = static_cast<char>(word == "strupr" ? std::toupper(static_cast<unsigned char>(c))
                                             : std::tolower(static_cast<unsigned char>(c)));
    return Value::string(r);
  }
  if (word == "strcmp") return Value::number(s(0).compare(s(1)) < 0 ? -1 : s(0) == s(1) ? 0 : 1);
  if (word == "substr") {
    const std::string& x = s(0);
    const double start = f(1), len = f(2);
    if (!(start >= 1 && len >= 0 && start - 1 + len <= x.size()))
      fail_at(t.pos, "substr: the range is outside the string");
    return Value::string(
        x.substr(static_cast<std::size_t>(start) - 1, static_cast<std::size_t>(len)));
  }
  if (word == "asc") return Value::number(s(0).empty() ? 0 : static_cast<unsigned char>(s(0)[0]));
  if (word == "val") return Value::number(std::strtod(s(0).c_str(), nullptr));
  if (word == "str") return Value::string(format_number(f(0), f(1), f(2)));
  if (word == "vstr") {
    const double n = f(0);
    const Value& v = a[1];
    if (v.kind != Value::Vector && v.kind != Value::Float) fail_at(at[1], "vstr needs a vector");
    std::string r;
    for (int i = 0; i < std::clamp(saturate<int>(n), 1, 5); ++i) {
      if (i) r += s(2);
      const double c = v.kind == Value::Float ? v.v[0]
                       : i < v.dims           ? v.v[static_cast<std::size_t>(i)]
                                              : 0;
      r += format_number(c, f(3), f(4));
    }
    return Value::string(r);
  }
  if (word == "file_exists") {
    std::error_code ec;
    const std::string& name = s(0);
    namespace fs = std::filesystem;
    if (fs::is_regular_file(fs::path(dirs_[0]) / name, ec)) return Value::number(1);
    for (const std::string& d : options_.library_paths)
      if (fs::is_regular_file(fs::path(d) / name, ec)) return Value::number(1);
    return Value::number(0);
  }
  fail_at(t.pos, "the function " + w + " is not available");
}

}  // namespace raycast::pov
