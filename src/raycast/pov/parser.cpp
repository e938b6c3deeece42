#include "pov/parser.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "pov/parser_impl.h"

namespace raycast::pov {

namespace {

constexpr double kDegrees = 180 / std::numbers::pi;

Val scalar(double f) {
  Val r;
  r.v[0] = f;
  return r;
}

Val vec(std::initializer_list<double> xs) {
  Val r;
  r.dims = static_cast<int>(xs.size());
  int i = 0;
  for (double x : xs) r.v[static_cast<std::size_t>(i++)] = x;
  return r;
}

// POV-Ray promotes a float to a vector of equal components when it meets one.
Val widen(const Val& a, int dims) {
  if (a.dims >= dims) return a;
  Val r;
  r.dims = dims;
  for (int i = 0; i < dims; ++i)
    r.v[static_cast<std::size_t>(i)] = a.dims == 1  ? a.v[0]
                                       : i < a.dims ? a.v[static_cast<std::size_t>(i)]
                                                    : 0;
  return r;
}

template <class F>
Val combine(const Val& a, const Val& b, F op) {
  const int d = std::max(a.dims, b.dims);
  const Val x = widen(a, d), y = widen(b, d);
  Val r;
  r.dims = d;
  for (std::size_t i = 0; i < static_cast<std::size_t>(d); ++i) r.v[i] = op(x.v[i], y.v[i]);
  return r;
}

Vec3 to_vec3(const Val& a) {
  if (a.dims == 1) return {a.v[0], a.v[0], a.v[0]};
  return {a.v[0], a.v[1], a.dims > 2 ? a.v[2] : 0};
}

}  // namespace

Parser::Parser(const std::string& text, const std::string& name, const std::string& dir) {
  open(text, name, name, dir);
  next();
}

void Parser::open(std::string text, const std::string& name, const std::string& path,
                  const std::string& dir) {
  auto f = std::make_unique<OpenFile>();
  f->text = std::move(text);
  f->dir = dir;
  const int index = static_cast<int>(scene_.sources.names.size());
  scene_.sources.names.push_back(name);
  scene_.sources.paths.push_back(path);
  f->lexer = std::make_unique<Lexer>(f->text, index, scene_.sources);
  files_.push_back(std::move(f));
}

Token Parser::raw_next() {
  while (!replay_.empty()) {
    Replay& r = replay_.back();
    if (r.at < r.tokens.size()) return r.tokens[r.at++];
    replay_.pop_back();
  }
  Token t = files_.back()->lexer->next();
  while (t.kind == Token::End && files_.size() > 1) {
    files_.pop_back();
    t = files_.back()->lexer->next();
  }
  return t;
}

void Parser::next() {
  cur_ = raw_next();
  while (cur_.kind == Token::Word && macros_.count(cur_.text)) expand_macro();
}

namespace {
constexpr std::size_t kMaxMacroNesting = 64;
constexpr std::size_t kMaxMacroTokens = std::size_t{1} << 22;
bool is_symbol_token(const Token& t, char c) {
  return t.kind == Token::Symbol && t.text.size() == 1 && t.text[0] == c;
}
}  // namespace

void Parser::define_macro(const Pos& at) {
  // #macro Name(a, b) ... #end, read as raw tokens (nothing in the body is evaluated yet).
  Token name = raw_next();
  if (name.kind != Token::Word) fail_at(name.pos, "expected a macro name after #macro");
  Macro m;
  Token t = raw_next();
  if (!is_symbol_token(t, '(')) fail_at(t.pos, "expected '(' after the macro's name");
  t = raw_next();
  while (!is_symbol_token(t, ')')) {
    if (t.kind != Token::Word) fail_at(t.pos, "expected a parameter name in #macro");
    m.params.push_back(t.text);
    t = raw_next();
    if (is_symbol_token(t, ',')) t = raw_next();
  }
  int depth = 0;
  for (;;) {
    t = raw_next();
    if (t.kind == Token::End) fail_at(at, "#macro " + name.text + " is never closed by #end");
    if (t.kind == Token::Directive) {
      if (t.text == "end" && depth == 0) break;
      if (t.text == "end") --depth;
      if (t.text == "macro" || t.text == "if" || t.text == "ifdef" || t.text == "ifndef" ||
          t.text == "while" || t.text == "for" || t.text == "switch")
        ++depth;
    }
    m.body.push_back(t);
    if (m.body.size() > kMaxMacroTokens) fail_at(at, "the macro's body is too long");
  }
  macros_[name.text] = std::move(m);
  next();
}

void Parser::expand_macro() {
  const Token name = cur_;
  const Macro& m = macros_.at(name.text);
  if (replay_.size() >= kMaxMacroNesting)
    fail_at(name.pos, "macros are nested deeper than " + std::to_string(kMaxMacroNesting) +
                          " (a macro calling itself?)");
  Token t = raw_next();
  if (!is_symbol_token(t, '(')) fail_at(t.pos, "expected '(' after the macro " + name.text);
  // Arguments: token lists split at top-level commas; (), {} and <> nest.
  std::vector<std::vector<Token>> args(1);
  int depth = 0;
  for (;;) {
    t = raw_next();
    if (t.kind == Token::End) fail_at(name.pos, "the call of " + name.text + " is never closed");
    if (depth == 0 && is_symbol_token(t, ')')) break;
    if (depth == 0 && is_symbol_token(t, ',')) {
      args.emplace_back();
      continue;
    }
    if (is_symbol_token(t, '(') || is_symbol_token(t, '{') || is_symbol_token(t, '<')) ++depth;
    if (is_symbol_token(t, ')') || is_symbol_token(t, '}') || is_symbol_token(t, '>')) --depth;
    args.back().push_back(t);
    if (args.back().size() > kMaxMacroTokens) fail_at(name.pos, "a macro argument is too long");
  }
  if (args.size() == 1 && args[0].empty()) args.clear();
  if (args.size() != m.params.size())
    fail_at(name.pos, name.text + " takes " + std::to_string(m.params.size()) +
                          " argument(s), got " + std::to_string(args.size()));
  Replay r;
  for (const Token& b : m.body) {
    const auto p = std::find(m.params.begin(), m.params.end(), b.text);
    if (b.kind != Token::Word || p == m.params.end()) {
      r.tokens.push_back(b);
      continue;
    }
    const auto& a = args[static_cast<std::size_t>(p - m.params.begin())];
    // An expression argument keeps its meaning inside the body's expressions: parenthesised
    // (not when it holds a block, such as an object or a texture).
    bool block = false;
    for (const Token& x : a) block = block || is_symbol_token(x, '{');
    const bool wrap = a.size() > 1 && !block;
    Token paren = b;
    paren.kind = Token::Symbol;
    if (wrap) paren.text = "(", r.tokens.push_back(paren);
    r.tokens.insert(r.tokens.end(), a.begin(), a.end());
    if (wrap) paren.text = ")", r.tokens.push_back(paren);
  }
  expanded_ += r.tokens.size();
  if (expanded_ > kMaxMacroTokens)
    fail_at(name.pos, "macro expansions make more than " + std::to_string(kMaxMacroTokens) +
                          " tokens in all");
  replay_.push_back(std::move(r));
  cur_ = raw_next();
}

bool Parser::accept_symbol(char c) {
  if (!is_symbol(c)) return false;
  next();
  return true;
}

void Parser::expect_symbol(char c, const char* where) {
  if (!is_symbol(c)) {
    const std::string want = std::string("'") + c + "' " + where;
    unexpected(want.c_str());
  }
  next();
}

void Parser::fail_here(const std::string& message) const {
  fail(scene_.sources, cur_.pos, message);
}
void Parser::fail_at(const Pos& p, const std::string& message) const {
  fail(scene_.sources, p, message);
}

std::string Parser::describe(const Token& t) const {
  switch (t.kind) {
    case Token::End:
      return "the end of the file";
    case Token::Number:
      return "the number " + t.text;
    case Token::Word:
      return "'" + t.text + "'";
    case Token::String:
      return "a string";
    case Token::Directive:
      return "'#" + t.text + "'";
    case Token::Symbol:
      return "'" + t.text + "'";
  }
  return "?";
}

void Parser::unexpected(const char* expected) const {
  std::ostringstream s;
  s << "expected " << expected << ", got " << describe(cur_);
  // An unknown keyword where the subset expects something is reported as unsupported.
  if (cur_.kind == Token::Word && !symbols_.count(cur_.text))
    s.str(unsupported(cur_.text) + " (expected " + expected + ")");
  if (cur_.kind == Token::Directive) s.str(unsupported("#" + cur_.text));
  fail_here(s.str());
}

bool Parser::boolean_option() {
  // `open`, `hollow`, `fresnel` ... may be followed by a boolean (on, off, true, 1 ...).
  if (cur_.kind == Token::Number || is_word("on") || is_word("off") || is_word("true") ||
      is_word("false") || is_word("yes") || is_word("no"))
    return number("a boolean") != 0;
  return true;
}

// ---- expressions ----------------------------------------------------------------------------

double Parser::number(const char* what) {
  const Pos at = cur_.pos;
  const Val v = expression();
  if (v.dims != 1) fail_at(at, std::string("expected a float for ") + what + ", got a vector");
  return v.v[0];
}

Vec3 Parser::vector(const char* what) {
  const Pos at = cur_.pos;
  const Val v = expression();
  if (v.dims == 2) fail_at(at, std::string("expected a 3-vector for ") + what + ", got a 2-vector");
  return to_vec3(v);
}

Val Parser::expression(int depth) {
  if (depth > kMaxPovNesting)
    fail_here("expressions are nested deeper than " + std::to_string(kMaxPovNesting));
  // Precedence climbing over + - (lowest), * /, unary, primary.
  auto primary = [&](auto& self_unary) -> Val {
    const Token t = cur_;
    if (t.kind == Token::Number) {
      next();
      return scalar(t.number);
    }
    if (is_symbol('(')) {
      next();
      const Val v = expression(depth + 1);
      expect_symbol(')', "to close '('");
      return v;
    }
    if (is_symbol('<')) {
      next();
      Val r;
      r.dims = 0;
      for (;;) {
        const Pos at = cur_.pos;
        const Val c = expression(depth + 1);
        if (c.dims != 1) fail_at(at, "a vector's components must be floats");
        if (r.dims == 5) fail_at(at, "a vector has at most 5 components");
        r.v[static_cast<std::size_t>(r.dims++)] = c.v[0];
        if (accept_symbol(',')) continue;
        expect_symbol('>', "to close the vector '<'");
        break;
      }
      if (r.dims < 2) fail_at(t.pos, "a vector needs at least 2 components");
      return r;
    }
    if (t.kind != Token::Word) unexpected("a number, a vector or a name");
    const std::string& w = t.text;
    if (const auto it = symbols_.find(w); it != symbols_.end()) {
      if (it->second.kind != Declared::Value)
        fail_here("'" + w + "' is not a number or a vector here");
      next();
      return it->second.val;
    }
    next();
    if (w == "x") return vec({1, 0, 0});
    if (w == "y") return vec({0, 1, 0});
    if (w == "z") return vec({0, 0, 1});
    if (w == "pi") return scalar(std::numbers::pi);
    if (w == "true" || w == "yes" || w == "on") return scalar(1);
    if (w == "false" || w == "no" || w == "off") return scalar(0);
    if (w == "image_width") return scalar(kPovImageWidth);
    if (w == "image_height") return scalar(kPovImageHeight);
    if (w == "clock") return scalar(0);
    // Functions of floats and vectors.
    static const std::map<std::string, int> arity = {
        {"sin", 1},     {"cos", 1},     {"tan", 1},        {"asin", 1}, {"acos", 1},
        {"atan", 1},    {"atan2", 2},   {"sqrt", 1},       {"pow", 2},  {"exp", 1},
        {"log", 1},     {"ln", 1},      {"abs", 1},        {"min", -1}, {"max", -1},
        {"floor", 1},   {"ceil", 1},    {"int", 1},        {"mod", 2},  {"radians", 1},
        {"degrees", 1}, {"vlength", 1}, {"vnormalize", 1}, {"vdot", 2}, {"vcross", 2}};
    const auto fn = arity.find(w);
    if (fn == arity.end()) {
      if (w == "function") fail_at(t.pos, unsupported("function outside an isosurface"));
      if (w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" || w == "color" || w == "colour")
        fail_at(t.pos, "a colour is not allowed in an arithmetic expression here");
      fail_at(t.pos,
              "unknown name '" + w + "' (not #declared, and not a function the import knows)");
    }
    expect_symbol('(', ("after " + w).c_str());
    std::vector<Val> args;
    std::vector<Pos> at;
    if (!is_symbol(')')) {
      for (;;) {
        at.push_back(cur_.pos);
        args.push_back(expression(depth + 1));
        if (!accept_symbol(',')) break;
      }
    }
    expect_symbol(')', ("to close " + w + "(").c_str());
    const int n = static_cast<int>(args.size());
    if (fn->second >= 0 && n != fn->second)
      fail_at(t.pos, w + " takes " + std::to_string(fn->second) + " argument(s), got " +
                         std::to_string(n));
    if (fn->second < 0 && n < 2) fail_at(t.pos, w + " takes at least 2 arguments");
    const bool vector_fn = w == "vlength" || w == "vnormalize" || w == "vdot" || w == "vcross";
    for (int i = 0; i < n; ++i) {
      const bool is_vec = args[static_cast<std::size_t>(i)].dims > 1;
      if (is_vec != vector_fn)
        fail_at(at[static_cast<std::size_t>(i)],
                w + (vector_fn ? " takes vectors" : " takes floats"));
    }
    auto a = [&](int i) { return args[static_cast<std::size_t>(i)].v[0]; };
    double r = 0;
    if (w == "sin")
      r = std::sin(a(0));
    else if (w == "cos")
      r = std::cos(a(0));
    else if (w == "tan")
      r = std::tan(a(0));
    else if (w == "asin")
      r = std::asin(a(0));
    else if (w == "acos")
      r = std::acos(a(0));
    else if (w == "atan")
      r = std::atan(a(0));
    else if (w == "atan2")
      r = std::atan2(a(0), a(1));
    else if (w == "sqrt")
      r = std::sqrt(a(0));
    else if (w == "pow")
      r = std::pow(a(0), a(1));
    else if (w == "exp")
      r = std::exp(a(0));
    else if (w == "log")
      r = std::log10(a(0));
    else if (w == "ln")
      r = std::log(a(0));
    else if (w == "abs")
      r = std::abs(a(0));
    else if (w == "floor")
      r = std::floor(a(0));
    else if (w == "ceil")
      r = std::ceil(a(0));
    else if (w == "int")
      r = std::trunc(a(0));
    else if (w == "mod")
      r = std::fmod(a(0), a(1));
    else if (w == "radians")
      r = a(0) / kDegrees;
    else if (w == "degrees")
      r = a(0) * kDegrees;
    else if (w == "min" || w == "max") {
      r = a(0);
      for (int i = 1; i < n; ++i) r = w == "min" ? std::min(r, a(i)) : std::max(r, a(i));
    } else {
      const Vec3 p = to_vec3(args[0]);
      const Vec3 q = n > 1 ? to_vec3(args[1]) : Vec3{};
      if (w == "vlength")
        r = length(p);
      else if (w == "vdot")
        r = dot(p, q);
      else {
        const Vec3 v = w == "vcross" ? cross(p, q) : p / length(p);
        r = 0;
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
          fail_at(t.pos, w + " of a zero vector");
        return vec({v.x, v.y, v.z});
      }
    }
    if (!std::isfinite(r)) fail_at(t.pos, w + "(...) is not a finite number");
    (void)self_unary;
    return scalar(r);
  };
  std::function<Val(int)> unary = [&](int d) -> Val {
    if (d > kMaxPovNesting)
      fail_here("expressions are nested deeper than " + std::to_string(kMaxPovNesting));
    if (accept_symbol('-')) {
      Val v = unary(d + 1);
      for (auto& c : v.v) c = -c;
      return v;
    }
    if (accept_symbol('+')) return unary(d + 1);
    return primary(unary);
  };
  auto term = [&]() -> Val {
    Val v = unary(depth);
    for (;;) {
      if (is_symbol('*')) {
        next();
        v = combine(v, unary(depth), [](double a, double b) { return a * b; });
      } else if (is_symbol('/')) {
        const Pos at = cur_.pos;
        next();
        const Val d = unary(depth);
        for (int i = 0; i < d.dims; ++i)
          if (d.v[static_cast<std::size_t>(i)] == 0) fail_at(at, "division by zero");
        v = combine(v, d, [](double a, double b) { return a / b; });
      } else {
        return v;
      }
    }
  };
  const Pos start = cur_.pos;
  Val v = term();
  for (;;) {
    if (is_symbol('+')) {
      next();
      v = combine(v, term(), [](double a, double b) { return a + b; });
    } else if (is_symbol('-')) {
      next();
      v = combine(v, term(), [](double a, double b) { return a - b; });
    } else {
      break;
    }
  }
  for (int i = 0; i < v.dims; ++i)
    if (!std::isfinite(v.v[static_cast<std::size_t>(i)]))
      fail_at(start, "the expression is not a finite number (overflow)");
  return v;
}

bool Parser::starts_colour() const {
  if (cur_.kind != Token::Word) return false;
  const std::string& w = cur_.text;
  if (w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft")
    return true;
  const auto it = symbols_.find(w);
  return it != symbols_.end() && it->second.kind == Declared::Value && it->second.colour;
}

Colour Parser::colour(const char* what) {
  if (is_word("color") || is_word("colour")) next();
  const Pos at = cur_.pos;
  Val v;
  int want = 0;  // components the keyword reads: 3 rgb, 4 rgbf/rgbt, 5 rgbft
  bool transmit_only = false;
  if (is_word("rgb"))
    want = 3;
  else if (is_word("rgbf"))
    want = 4;
  else if (is_word("rgbt"))
    want = 4, transmit_only = true;
  else if (is_word("rgbft"))
    want = 5;
  else if (cur_.kind == Token::Word &&
           (cur_.text == "srgb" || cur_.text == "srgbf" || cur_.text == "srgbt" ||
            cur_.text == "red" || cur_.text == "green" || cur_.text == "blue"))
    fail_here(unsupported(cur_.text));
  if (want) next();
  const Pos value_at = cur_.pos;
  v = expression();
  Colour c;
  if (want == 0) {                     // a declared colour or a bare vector
    if (v.dims == 1) v = widen(v, 3);  // a grey: no filter, no transmit
    if (v.dims < 3) fail_at(at, std::string("expected a colour for ") + what);
    c = {v.v[0], v.v[1], v.v[2], v.dims > 3 ? v.v[3] : 0, v.dims > 4 ? v.v[4] : 0};
  } else {
    if (v.dims == 1) v = widen(v, want);
    if (v.dims != want)
      fail_at(value_at,
              "expected " + std::to_string(want) + " components, got " + std::to_string(v.dims));
    c = {v.v[0], v.v[1], v.v[2], 0, 0};
    if (want == 4) (transmit_only ? c.transmit : c.filter) = v.v[3];
    if (want == 5) c.filter = v.v[3], c.transmit = v.v[4];
  }
  for (double x : {c.r, c.g, c.b, c.filter, c.transmit})
    if (x < 0) fail_at(at, std::string("a colour for ") + what + " must not be negative");
  return c;
}

// ---- directives -----------------------------------------------------------------------------

bool Parser::directive() {
  if (cur_.kind != Token::Directive) return false;
  const Token d = cur_;
  if (d.text == "declare" || d.text == "local") {
    next();
    declare(d.text == "local");
  } else if (d.text == "include") {
    next();
    include_file(d.pos);
  } else if (d.text == "version") {
    next();
    number("#version");
    accept_symbol(';');
  } else if (d.text == "default") {
    next();
    default_block();
  } else if (d.text == "macro") {
    define_macro(d.pos);
  } else {
    fail_at(d.pos, unsupported("#" + d.text));
  }
  return true;
}

void Parser::include_file(const Pos& at) {
  if (cur_.kind != Token::String) unexpected("a file name in quotes after #include");
  const std::string name = cur_.text;
  if (!replay_.empty()) fail_at(at, unsupported("#include inside a macro"));
  if (static_cast<int>(files_.size()) > kMaxIncludeDepth)
    fail_at(at, "#include files are nested deeper than " + std::to_string(kMaxIncludeDepth));
  namespace fs = std::filesystem;
  const fs::path path = fs::path(files_.back()->dir) / name;
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  if (!in || fs::is_directory(path, ec))
    fail_at(cur_.pos, "cannot open #include file '" + name + "' (looked in " + files_.back()->dir +
                          "; only local include files are read: POV-Ray's "
                          "standard includes such as colors.inc are not supported)");
  std::stringstream ss;
  ss << in.rdbuf();
  // The token after the file name is read when the include ends: open the file first, so the
  // lexer of the including file is not advanced until then.
  const std::string dir = path.parent_path().string();
  open(ss.str(), path.string(), path.string(), dir.empty() ? "." : dir);
  next();
}

void Parser::declare(bool) {
  if (cur_.kind != Token::Word) unexpected("a name after #declare");
  const std::string name = cur_.text;
  static const std::vector<std::string> reserved = {
      "x",       "y",       "z",      "pi",    "rgb",    "sphere",      "box",         "camera",
      "texture", "pigment", "finish", "color", "colour", "image_width", "image_height"};
  if (std::find(reserved.begin(), reserved.end(), name) != reserved.end())
    fail_here("'" + name + "' is a keyword and cannot be declared");
  next();
  expect_symbol('=', ("after #declare " + name).c_str());
  Declared d;
  if (is_object_keyword()) {
    d.kind = Declared::Object;
    d.node = std::make_shared<const Node>(object(0));
  } else if (is_word("texture")) {
    next();
    d.kind = Declared::TextureKind;
    d.texture = texture_block(default_texture_, 0);
    d.texture.name = name;
  } else if (is_word("material")) {
    next();
    d.kind = Declared::TextureKind;
    d.texture = material_block(default_texture_, 0);
    d.texture.name = name;
  } else if (is_word("pigment")) {
    next();
    d.kind = Declared::PigmentKind;
    d.pigment = pigment_block(default_texture_.pigment);
  } else if (is_word("finish")) {
    next();
    d.kind = Declared::FinishKind;
    d.finish = finish_block(default_texture_.finish);
  } else if (is_word("interior")) {
    next();
    d.kind = Declared::InteriorKind;
    d.ior = interior_block();
  } else if (starts_colour() && !(cur_.kind == Token::Word && symbols_.count(cur_.text))) {
    const Colour c = colour("#declare");
    d.colour = true;
    d.val = vec({c.r, c.g, c.b, c.filter, c.transmit});
  } else if (cur_.kind == Token::Word && symbols_.count(cur_.text) &&
             symbols_.at(cur_.text).kind != Declared::Value) {
    d = symbols_.at(cur_.text);
    next();
  } else {
    const bool was_colour = starts_colour();
    d.val = expression();
    d.colour = was_colour && d.val.dims == 5;
  }
  accept_symbol(';');
  symbols_[name] = std::move(d);
}

void Parser::default_block() {
  expect_symbol('{', "after #default");
  while (!accept_symbol('}')) {
    if (is_word("texture")) {
      next();
      default_texture_ = texture_block(default_texture_, 0);
    } else if (is_word("pigment")) {
      next();
      default_texture_.pigment = pigment_block(default_texture_.pigment);
    } else if (is_word("finish")) {
      next();
      default_texture_.finish = finish_block(default_texture_.finish);
    } else {
      unexpected("texture, pigment or finish in #default");
    }
  }
  default_texture_.name.clear();
}

// ---- textures -------------------------------------------------------------------------------

Pigment Parser::pigment_block(const Pigment& base) {
  expect_symbol('{', "after pigment");
  Pigment p = base;
  if (cur_.kind == Token::Word) {
    const auto it = symbols_.find(cur_.text);
    if (it != symbols_.end() && it->second.kind == Declared::PigmentKind) {
      p = it->second.pigment;
      next();
    }
  }
  while (!accept_symbol('}')) {
    if (is_word("checker")) {
      next();
      p.checker = true;
      p.c0 = {0, 0, 1, 0, 0};  // POV-Ray's defaults: blue and green
      p.c1 = {0, 1, 0, 0, 0};
      if (starts_colour()) {
        p.c0 = colour("checker");
        skip_comma();
        if (starts_colour()) p.c1 = colour("checker");
      }
    } else if (starts_colour()) {
      p.checker = false;
      p.c0 = colour("pigment");
    } else if (is_word("scale")) {
      const Pos at = cur_.pos;
      next();
      const Vec3 s = vector("scale");
      if (s.x != s.y || s.y != s.z || s.x <= 0)
        fail_at(at,
                "a pigment's scale must be one positive factor (raycast's checker has one "
                "uniform scale): " +
                    unsupported("non-uniform pigment scale"));
      p.scale *= s.x;
    } else if (cur_.kind == Token::Word &&
               (cur_.text == "translate" || cur_.text == "rotate" || cur_.text == "matrix")) {
      fail_here(unsupported("pigment " + cur_.text) + " (only a uniform scale)");
    } else {
      unexpected("a colour, checker or scale in pigment");
    }
  }
  return p;
}

void Parser::reflection_block(Finish& f) {
  // reflection { [min,] max [fresnel on] [conserve_energy-like modifiers are outside] }
  std::vector<double> values;
  std::vector<Pos> at;
  while (!accept_symbol('}')) {
    if (is_word("fresnel")) {
      next();
      f.fresnel = boolean_option();
    } else if (starts_colour() || cur_.kind == Token::Number || is_symbol('<') || is_symbol('-')) {
      at.push_back(cur_.pos);
      const Colour c = colour("reflection");
      if (c.r != c.g || c.g != c.b)
        fail_at(at.back(), unsupported("coloured reflection") + " (use a grey value)");
      values.push_back(c.r);
      skip_comma();
    } else {
      unexpected("a reflection value or fresnel");
    }
  }
  if (values.empty() || values.size() > 2) fail_here("reflection { } takes one or two values");
  const double lo = values.front(), hi = values.back();
  if (f.fresnel) {
    if (lo != 0 || hi != 1)
      fail_at(at.front(),
              unsupported("reflection { min, max fresnel } other than { 0, 1 fresnel on }"));
    f.reflection = 0;
  } else {
    if (lo != hi)
      fail_at(at.front(), unsupported("variable reflection { min, max }") + " (give one value)");
    f.reflection = hi;
  }
}

Finish Parser::finish_block(const Finish& base) {
  expect_symbol('{', "after finish");
  Finish f = base;
  if (cur_.kind == Token::Word) {
    const auto it = symbols_.find(cur_.text);
    if (it != symbols_.end() && it->second.kind == Declared::FinishKind) {
      f = it->second.finish;
      next();
    }
  }
  auto grey = [&](const char* what) {
    const Pos at = cur_.pos;
    const Colour c = colour(what);
    if (c.r != c.g || c.g != c.b)
      fail_at(at, unsupported(std::string("coloured ") + what) + " (use a float)");
    return c.r;
  };
  while (!accept_symbol('}')) {
    const Pos at = cur_.pos;
    if (is_word("ambient"))
      next(), f.ambient = grey("ambient");
    else if (is_word("diffuse"))
      next(), f.diffuse = number("diffuse");
    else if (is_word("phong"))
      next(), f.phong = number("phong");
    else if (is_word("phong_size"))
      next(), f.phong_size = number("phong_size");
    else if (is_word("specular"))
      next(), f.specular = number("specular");
    else if (is_word("roughness")) {
      next();
      f.roughness = number("roughness");
      if (f.roughness <= 0) fail_at(at, "roughness must be > 0");
    } else if (is_word("reflection")) {
      next();
      if (accept_symbol('{'))
        reflection_block(f);
      else {
        f.fresnel = false;
        f.reflection = grey("reflection");
      }
    } else if (is_word("conserve_energy")) {
      next();
      f.conserve_energy = boolean_option();
    } else if (is_word("brilliance")) {
      next();
      if (number("brilliance") != 1) fail_at(at, unsupported("brilliance") + " (other than 1)");
    } else {
      unexpected(
          "a finish item (ambient, diffuse, phong, phong_size, specular, roughness, "
          "reflection, conserve_energy)");
    }
    for (double v : {f.ambient, f.diffuse, f.phong, f.phong_size, f.specular, f.reflection})
      if (v < 0) fail_at(at, "finish values must not be negative");
  }
  return f;
}

std::optional<double> Parser::interior_block() {
  expect_symbol('{', "after interior");
  std::optional<double> ior;
  if (cur_.kind == Token::Word) {
    const auto it = symbols_.find(cur_.text);
    if (it != symbols_.end() && it->second.kind == Declared::InteriorKind) {
      ior = it->second.ior;
      next();
    }
  }
  while (!accept_symbol('}')) {
    if (is_word("ior")) {
      const Pos at = cur_.pos;
      next();
      ior = number("ior");
      if (*ior <= 0) fail_at(at, "ior must be > 0");
    } else {
      unexpected("ior in interior");
    }
  }
  return ior;
}

Texture Parser::texture_block(const Texture& base, int depth) {
  if (depth > kMaxPovNesting) fail_here("textures are nested too deeply");
  expect_symbol('{', "after texture");
  Texture t = base;
  t.name.clear();
  if (cur_.kind == Token::Word) {
    const auto it = symbols_.find(cur_.text);
    if (it != symbols_.end() && it->second.kind == Declared::TextureKind) {
      const std::optional<double> ior = t.ior;
      t = it->second.texture;
      if (!t.ior) t.ior = ior;
      next();
    }
  }
  while (!accept_symbol('}')) {
    if (is_word("pigment")) {
      next();
      t.pigment = pigment_block(t.pigment);
      t.name.clear();
    } else if (is_word("finish")) {
      next();
      t.finish = finish_block(t.finish);
      t.name.clear();
    } else if (is_word("scale")) {
      const Pos at = cur_.pos;
      next();
      const Vec3 s = vector("scale");
      if (s.x != s.y || s.y != s.z || s.x <= 0)
        fail_at(at, unsupported("non-uniform texture scale"));
      t.pigment.scale *= s.x;
      t.name.clear();
    } else {
      unexpected("pigment, finish or scale in texture");
    }
  }
  return t;
}

Texture Parser::material_block(const Texture& base, int depth) {
  expect_symbol('{', "after material");
  Texture t = base;
  if (cur_.kind == Token::Word) {
    const auto it = symbols_.find(cur_.text);
    if (it != symbols_.end() && it->second.kind == Declared::TextureKind) {
      t = it->second.texture;
      next();
    }
  }
  while (!accept_symbol('}')) {
    if (is_word("texture")) {
      next();
      const std::optional<double> ior = t.ior;
      t = texture_block(t, depth + 1);
      t.ior = ior;
    } else if (is_word("interior")) {
      next();
      t.ior = interior_block();
      t.name.clear();
    } else {
      unexpected("texture or interior in material");
    }
  }
  return t;
}

// ---- camera, lights, settings ---------------------------------------------------------------

void Parser::camera_block() {
  Camera& c = scene_.camera;
  c.pos = cur_.pos;
  c.given = true;
  next();
  expect_symbol('{', "after camera");
  double angle = 0;
  while (!accept_symbol('}')) {
    const Pos at = cur_.pos;
    if (is_word("perspective"))
      next(), c.orthographic = false;
    else if (is_word("orthographic"))
      next(), c.orthographic = true;
    else if (is_word("location"))
      next(), c.location = vector("location");
    else if (is_word("direction"))
      next(), c.direction = vector("direction");
    else if (is_word("up"))
      next(), c.up = vector("up");
    else if (is_word("right"))
      next(), c.right = vector("right");
    else if (is_word("sky"))
      next(), c.sky = vector("sky");
    else if (is_word("angle")) {
      next();
      angle = number("angle");
      if (!(angle > 0 && angle < 180)) fail_at(at, "angle must be in (0, 180) degrees");
    } else if (is_word("look_at")) {
      next();
      const Vec3 target = vector("look_at");
      // POV-Ray's look_at: turn direction towards the target, right = sky x direction, keeping
      // every vector's length and the frame's handedness.
      const double dl = length(c.direction), ul = length(c.up), rl = length(c.right);
      const double handed = dot(cross(c.up, c.direction), c.right);
      const Vec3 d = target - c.location;
      const Vec3 r = cross(c.sky, d);
      if (length(d) == 0) fail_at(at, "look_at is the camera's location");
      if (length(r) == 0) fail_at(at, "look_at is straight along the sky vector");
      c.direction = d / length(d);
      c.right = r / length(r);
      c.up = cross(c.direction, c.right);
      c.direction = c.direction * dl;
      c.right = c.right * (handed > 0 ? rl : -rl);
      c.up = c.up * ul;
    } else if (is_word("translate")) {
      next();
      c.location = c.location + vector("translate");
    } else {
      unexpected(
          "a camera item (perspective, orthographic, location, look_at, angle, up, "
          "right, direction, sky, translate)");
    }
  }
  for (const Vec3& v : {c.direction, c.up, c.right})
    if (!(length(v) > 0)) fail_at(c.pos, "the camera's direction, up and right must be non-zero");
  if (angle > 0 && !c.orthographic)
    c.direction = c.direction / length(c.direction) *
                  (0.5 * length(c.right) / std::tan(angle / kDegrees / 2));
  for (const Vec3& v : {c.direction, c.up, c.right})
    if (length(v) == 0) fail_at(c.pos, "the camera's direction, up and right must be non-zero");
}

void Parser::light_block() {
  Light l;
  l.pos = cur_.pos;
  next();
  expect_symbol('{', "after light_source");
  l.position = vector("the light's position");
  skip_comma();
  l.colour = colour("the light");
  while (!accept_symbol('}')) {
    const Pos at = cur_.pos;
    if (is_word("spotlight"))
      next(), l.kind = Light::Spot;
    else if (is_word("point_at"))
      next(), l.point_at = vector("point_at");
    else if (is_word("radius"))
      next(), l.radius = number("radius");
    else if (is_word("falloff"))
      next(), l.falloff = number("falloff");
    else if (is_word("tightness")) {
      next();
      if (number("tightness") != 0) fail_at(at, unsupported("tightness") + " (other than 0)");
    } else if (is_word("area_light")) {
      next();
      l.area = true;
      l.axis1 = vector("area_light");
      skip_comma();
      l.axis2 = vector("area_light");
      skip_comma();
      const double n1 = number("area_light"), n2 = (skip_comma(), number("area_light"));
      if (!(n1 >= 1 && n2 >= 1 && n1 * n2 <= 4096))
        fail_at(at, "area_light sizes must be >= 1 with at most 4096 samples in all");
      l.size1 = static_cast<int>(n1);
      l.size2 = static_cast<int>(n2);
    } else if (is_word("adaptive")) {
      next();
      number("adaptive");
    } else if (is_word("jitter") || is_word("circular") || is_word("orient")) {
      next();
    } else if (is_word("translate")) {
      next();
      const Vec3 v = vector("translate");
      l.position = l.position + v;
      l.point_at = l.point_at + v;
    } else {
      unexpected(
          "a light_source item (spotlight, point_at, radius, falloff, area_light, "
          "adaptive, jitter, circular, orient, translate)");
    }
  }
  if (l.kind == Light::Spot &&
      !(l.radius >= 0 && l.falloff > 0 && l.falloff < 180 && l.radius <= l.falloff))
    fail_at(l.pos, "a spotlight needs 0 <= radius <= falloff < 180 degrees");
  scene_.lights.push_back(l);
}

void Parser::global_settings_block() {
  next();
  expect_symbol('{', "after global_settings");
  while (!accept_symbol('}')) {
    const Pos at = cur_.pos;
    if (is_word("max_trace_level")) {
      next();
      const double n = number("max_trace_level");
      if (!(n >= 1 && n <= 256)) fail_at(at, "max_trace_level must be in [1, 256]");
      scene_.max_trace_level = static_cast<int>(n);
    } else if (is_word("assumed_gamma")) {
      next();
      if (number("assumed_gamma") != 1)
        fail_at(at, unsupported("assumed_gamma") + " other than 1 (colours are linear)");
    } else if (is_word("ambient_light")) {
      next();
      scene_.ambient_light = colour("ambient_light");
    } else if (is_word("adc_bailout")) {
      next();
      scene_.adc_bailout = number("adc_bailout");
      if (*scene_.adc_bailout < 0 || *scene_.adc_bailout > 1)
        fail_at(at, "adc_bailout must be in [0, 1]");
    } else {
      unexpected("max_trace_level, assumed_gamma, ambient_light or adc_bailout");
    }
  }
}

PovScene Parser::run() {
  default_texture_.pigment.c0 = {0, 0, 0, 0, 0};  // POV-Ray's default: black
  while (cur_.kind != Token::End) {
    if (directive()) continue;
    if (is_word("camera"))
      camera_block();
    else if (is_word("light_source"))
      light_block();
    else if (is_word("global_settings"))
      global_settings_block();
    else if (is_word("background")) {
      next();
      expect_symbol('{', "after background");
      scene_.background = colour("background");
      expect_symbol('}', "to close background");
    } else if (is_object_keyword()) {
      scene_.objects.push_back(object(0));
      if (!scene_.objects.back().texture) scene_.objects.back().texture = default_texture_;
    } else if (accept_symbol(';')) {
      continue;
    } else {
      unexpected(
          "a scene item (camera, light_source, an object, global_settings, background "
          "or a directive)");
    }
  }
  return std::move(scene_);
}

PovScene parse_pov(const std::string& text, const std::string& name, const std::string& dir) {
  Parser p(text, name, dir);
  return p.run();
}

}  // namespace raycast::pov
