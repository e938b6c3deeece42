#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pov/interpreter.h"

namespace raycast::pov {

namespace {
// POV-Ray still reads these directives without their '#' (with a warning).
bool is_bare_directive(std::string_view w) {
  return w == "declare" || w == "local" || w == "default" || w == "include";
}

bool opens_block(std::string_view d) {
  return d == "if" || d == "ifdef" || d == "ifndef" || d == "while" || d == "for" ||
         d == "switch" || d == "macro";
}
}  // namespace

Interpreter::Interpreter(const std::string& text, const std::string& name, const std::string& dir,
                         const Options& options)
    : options_(options) {
  scopes_.emplace_back();
  scene_.settings.width = options.width;
  scene_.settings.height = options.height;
  if (options.antialias) {
    scene_.settings.antialias_depth = options.antialias_depth;
    scene_.settings.antialias_threshold = options.antialias_threshold;
  }
  open_file(text, name, name, dir);
  apply_declares();
}

void Interpreter::open_file(const std::string& text, const std::string& name,
                            const std::string& path, const std::string& dir) {
  const int index = static_cast<int>(scene_.sources.names.size());
  scene_.sources.names.push_back(name);
  scene_.sources.paths.push_back(path);
  texts_.push_back(std::make_shared<const std::string>(text));
  dirs_.push_back(dir.empty() ? "." : dir);
  inputs_.push_back({index, {}});
}

bool Interpreter::rereading() const {
  for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
    if (f->kind == FrameKind::While || f->kind == FrameKind::For || f->kind == FrameKind::Macro)
      return true;
  return false;
}

Token Interpreter::raw() {
  Input& in = inputs_.back();
  cur_input_ = inputs_.size() - 1;
  cur_before_ = in.cursor;
  const std::string& text = *texts_[static_cast<std::size_t>(in.file)];
  if (!rereading() || in.cursor.offset >= (std::uint64_t{1} << 40))
    return read_token(text, in.file, scene_.sources, in.cursor);
  const std::uint64_t key = (static_cast<std::uint64_t>(in.file) << 40) | in.cursor.offset;
  if (const auto it = token_cache_.find(key); it != token_cache_.end()) {
    in.cursor = it->second.after;
    return it->second.token;
  }
  Token t = read_token(text, in.file, scene_.sources, in.cursor);
  if (token_cache_.size() >= kTokenCacheSize) token_cache_.clear();
  token_cache_.emplace(key, CachedToken{t, in.cursor});
  return t;
}

Token Interpreter::raw_name() {
  if (have_ && !pending_) {
    have_ = false;
    return cur_;
  }
  if (pending_) {
    pending_ = have_ = false;
    return cur_;
  }
  return raw();
}

void Interpreter::unread() {
  if (!have_) return;
  if (cur_input_ < inputs_.size()) inputs_[cur_input_].cursor = cur_before_;
  have_ = pending_ = false;
}

void Interpreter::fetch() {
  for (;;) {
    if (have_ && !pending_) return;  // a directive's handler left the token after it
    Token t;
    if (pending_) {
      t = std::move(cur_);
      pending_ = have_ = false;
    } else {
      t = raw();
    }
    if (t.kind == Token::Directive) {
      directive(t);
      continue;
    }
    if (t.kind == Token::Word) {
      const Symbol* s = find_symbol(t.text);
      if (s && s->value.kind == Value::Macro) {
        call_macro(t, *s->value.macro);
        continue;
      }
      if (!s && is_bare_directive(t.text)) {
        t.kind = Token::Directive;
        directive(t);
        continue;
      }
    }
    if (t.kind == Token::End && !frames_.empty()) {
      const Frame& f = frames_.back();
      if (f.kind == FrameKind::Include && f.inputs == inputs_.size()) {
        close_file();
        continue;
      }
      if (f.inputs == inputs_.size())
        fail_at(f.pos, "this directive is never closed by #end (the file ends first)");
    }
    cur_ = std::move(t);
    have_ = true;
    return;
  }
}

const Token& Interpreter::tok() {
  if (!have_ || pending_) fetch();
  return cur_;
}

const Token& Interpreter::peek_operator() {
  if (have_) return cur_;
  for (;;) {
    Token t = raw();
    // A macro's #end inside an expression returns to the caller's tokens (POV-Ray's
    // `Add(1, 2) * 3`): it runs here; any other directive waits for the statement level.
    if (t.kind == Token::Directive && opaque_ == 0 && std::string_view(t.text) == "end" &&
        !frames_.empty() && frames_.back().kind == FrameKind::Macro) {
      end_macro();
      continue;
    }
    // So does the end of an #if's branch (a macro's `#if (C) A[I] #else B #end`, then `* 2` in
    // the caller): it only skips tokens and closes the frame.
    if (t.kind == Token::Directive && opaque_ == 0 && !frames_.empty() &&
        frames_.back().kind == FrameKind::If && frames_.back().inputs == inputs_.size()) {
      const std::string_view d = t.text;
      if (d == "else" || d == "elseif") skip_to(false, false);
      if (d == "else" || d == "elseif" || d == "end") {
        frames_.pop_back();
        continue;
      }
    }
    cur_ = std::move(t);
    have_ = true;
    pending_ = cur_.kind == Token::Directive || cur_.kind == Token::End;
    if (cur_.kind == Token::Word) {
      const Symbol* s = find_symbol(cur_.text);
      pending_ = s ? s->value.kind == Value::Macro : is_bare_directive(cur_.text);
    }
    return cur_;
  }
}

bool Interpreter::accept_symbol(std::string_view s) {
  if (!is_symbol(s)) return false;
  next();
  return true;
}

void Interpreter::expect_symbol(const char* s, const char* where) {
  if (!is_symbol(s)) unexpected(std::string("'") + s + "' " + where);
  next();
}

void Interpreter::fail_here(const std::string& message) { fail_at(tok().pos, message); }

void Interpreter::fail_at(const Pos& p, const std::string& message) const {
  fail(scene_.sources, p, message);
}

std::string Interpreter::describe(const Token& t) const {
  switch (t.kind) {
    case Token::End:
      return "the end of the file";
    case Token::Number:
      return "the number " + t.text;
    case Token::Word:
      return "'" + t.text + "'";
    case Token::String:
      return "the string \"" + t.text + "\"";
    case Token::Directive:
      return "'#" + t.text + "'";
    case Token::Symbol:
      return "'" + t.text + "'";
  }
  return "?";
}

void Interpreter::unexpected(const std::string& expected) {
  const Token& t = tok();
  if (t.kind == Token::Word && !find_symbol(t.text) && !is_builtin(t.text))
    fail_at(t.pos, "unknown word '" + t.text + "' (expected " + expected + ")");
  fail_at(t.pos, "expected " + expected + ", got " + describe(t));
}

void Interpreter::unsupported_warning(const Pos& at, const std::string& kind,
                                      const std::string& detail) {
  if (quiet_ > 0) {
    quiet_missed_ = true;
    return;
  }
  const std::string text = "raycast does not render " + kind + " yet" +
                           (detail.empty() ? std::string() : " (" + detail + ")");
  if (options_.strict) fail_at(at, text + "; without --strict it is a warning and is left out");
  if (!warned_.insert(kind).second) return;
  const std::string& name = at.file >= 0 && at.file < static_cast<int>(scene_.sources.names.size())
                                ? scene_.sources.names[static_cast<std::size_t>(at.file)]
                                : std::string("<pov>");
  scene_.warnings.push_back(name + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                            ": warning: " + text + "; left out (--strict makes this an error)");
}

void Interpreter::skip_block(const std::string& what) {
  expect_symbol("{", ("after " + what).c_str());
  skip_block_rest(what);
}

void Interpreter::skip_block_rest(const std::string& what) {
  int depth = 1;
  while (depth > 0) {
    const Token& t = tok();
    if (t.kind == Token::End) fail_at(t.pos, what + " { is never closed by '}'");
    if (pov::is_symbol(t, "{")) ++depth;
    if (pov::is_symbol(t, "}")) --depth;
    next();
  }
}

// ---- files ----------------------------------------------------------------------------------

std::vector<std::string> Interpreter::library_dirs() const {
  std::vector<std::string> dirs;
  dirs.push_back(dirs_[static_cast<std::size_t>(inputs_.back().file)]);
  dirs.push_back(dirs_[0]);
  for (const std::string& d : options_.library_paths) dirs.push_back(d);
  if (options_.system_library_path)
    for (const std::string& d : configured_library_paths()) dirs.push_back(d);
  return dirs;
}

std::optional<std::string> Interpreter::find_on_library_path(const std::string& name) const {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::path(name).is_absolute())
    return fs::is_regular_file(name, ec) ? std::optional<std::string>(name) : std::nullopt;
  for (const std::string& d : library_dirs()) {
    const fs::path p = fs::path(d) / name;
    if (fs::is_regular_file(p, ec)) return p.string();
  }
  return std::nullopt;
}

std::string Interpreter::find_include(const std::string& name, const Pos& at) {
  namespace fs = std::filesystem;
  if (const auto found = find_on_library_path(name)) return *found;
  std::vector<std::string> dirs;
  if (!fs::path(name).is_absolute()) dirs = library_dirs();
  std::string looked;
  for (const std::string& d : dirs) looked += (looked.empty() ? "" : ", ") + d;
  fail_at(at, "cannot open #include file '" + name + "' (looked in " + looked +
                  "; add folders with --library-path DIR or RAYCAST_POV_LIBRARY_PATH)");
}

void Interpreter::include(const Pos& at) {
  ++opaque_;
  const std::string name = string_value("#include");
  --opaque_;
  unread();
  const int depth = static_cast<int>(std::count_if(
      frames_.begin(), frames_.end(), [](const Frame& f) { return f.kind == FrameKind::Include; }));
  if (depth >= options_.limits.include_depth)
    fail_at(at, "#include files are nested deeper than " +
                    std::to_string(options_.limits.include_depth) +
                    " (an include including itself?)");
  const std::string path = find_include(name, at);
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in) fail_at(at, "cannot read #include file '" + path + "'");
  Frame f;
  f.kind = FrameKind::Include;
  f.pos = at;
  f.scopes = scopes_.size();
  scopes_.emplace_back();  // the include file's #local identifiers
  const std::string dir = std::filesystem::path(path).parent_path().string();
  open_file(ss.str(), path, path, dir);
  f.inputs = inputs_.size();
  frames_.push_back(f);
}

void Interpreter::close_file() {
  const Frame f = frames_.back();
  frames_.pop_back();
  scopes_.resize(f.scopes);
  inputs_.pop_back();
}

// ---- directives -----------------------------------------------------------------------------

void Interpreter::directive(const Token& d) {
  // A directive can start inside another's value (`#declare A = #declare B = ...`): each is a
  // level of the C++ stack, bounded with the expressions'.
  const NestingLevel level(*this);
  // A directive starts a statement, outside the parentheses of any value it interrupts.
  const ParenDepth statement(*this, 0);
  directive_body(d);
}

void Interpreter::directive_body(const Token& d) {
  const std::string& w = d.text;
  const std::string_view word = w;  // compared with literals inline
  if (word == "declare" || word == "local") {
    declare(d, word == "local");
  } else if (word == "if") {
    ++opaque_;
    const bool v = std::fabs(paren_number("#if")) > 1e-10;
    --opaque_;
    unread();
    begin_if(d, v);
  } else if (word == "ifdef" || word == "ifndef") {
    ++opaque_;
    const bool defined = is_defined_test();
    --opaque_;
    unread();
    begin_if(d, word == "ifdef" ? defined : !defined);
  } else if (word == "else" || word == "elseif") {
    if (frames_.empty() || frames_.back().inputs != inputs_.size())
      fail_at(d.pos, "#" + w + " without #if");
    if (frames_.back().kind == FrameKind::Switch && word == "else") return;  // falls through
    if (frames_.back().kind != FrameKind::If) fail_at(d.pos, "#" + w + " without #if");
    skip_to(false, false);
    frames_.pop_back();
  } else if (word == "end") {
    end_directive(d);
  } else if (word == "while") {
    begin_while(d);
  } else if (word == "for") {
    begin_for(d);
  } else if (word == "switch") {
    begin_switch(d);
  } else if (word == "case" || word == "range") {
    if (frames_.empty() || frames_.back().kind != FrameKind::Switch)
      fail_at(d.pos, "#" + w + " outside #switch");
    ++opaque_;
    condition();  // a later label while a case runs: POV-Ray falls through it
    --opaque_;
    unread();
  } else if (word == "break") {
    break_directive(d);
  } else if (word == "macro") {
    define_macro(d);
  } else if (word == "include") {
    include(d.pos);
  } else if (word == "undef") {
    undef();
  } else if (word == "version") {
    ++opaque_;
    scene_.settings.version = number("#version");
    --opaque_;
    if (pov::is_symbol(peek_operator(), ";")) next();
  } else if (word == "default") {
    default_block();
  } else if (word == "debug" || word == "warning" || word == "error" || word == "render" ||
             word == "statistics") {
    message_directive(d);
  } else if (word == "fopen") {
    fopen_directive();
  } else if (word == "read") {
    read_directive();
  } else if (word == "write") {
    write_directive();
  } else if (word == "fclose") {
    fclose_directive();
  } else {
    fail_at(d.pos, "unknown directive '#" + w + "'");
  }
}

double Interpreter::paren_number(const char* what) {
  const Pos at = tok().pos;
  const Value v = expression();
  if (v.kind != Value::Float)
    fail_at(at, std::string(what) + " needs a float, got " + kind_name(v));
  return v.v[0];
}

Value Interpreter::condition() { return expression(); }

Token Interpreter::skip_to(bool stop_at_else, bool stop_at_case) {
  const Pos start = frames_.empty() ? cur_.pos : frames_.back().pos;
  int depth = 0;
  std::optional<Token> first;
  if (have_) first = cur_;
  have_ = pending_ = false;
  for (;;) {
    Token t = first ? std::move(*first) : raw();
    first.reset();
    if (t.kind == Token::End) fail_at(start, "this directive is never closed by #end");
    if (t.kind != Token::Directive) continue;
    if (opens_block(t.text)) {
      ++depth;
    } else if (t.text == "end") {
      if (depth == 0) return t;
      --depth;
    } else if (depth == 0 && stop_at_else && (t.text == "else" || t.text == "elseif")) {
      return t;
    } else if (depth == 0 && stop_at_case &&
               (t.text == "case" || t.text == "range" || t.text == "else")) {
      return t;
    }
  }
}

void Interpreter::begin_if(const Token& d, bool value) {
  Frame f;
  f.kind = FrameKind::If;
  f.pos = d.pos;
  f.inputs = inputs_.size();
  while (!value) {
    const Token t = skip_to(true, false);
    if (t.text == "end") return;
    if (t.text == "else") break;
    ++opaque_;
    value = std::fabs(paren_number("#elseif")) > 1e-10;  // #elseif
    --opaque_;
    unread();
  }
  frames_.push_back(f);
}

bool Interpreter::is_defined_test() {
  expect_symbol("(", "after #ifdef");
  const Token nt = raw_name();
  if (nt.kind != Token::Word) fail_at(nt.pos, "expected a name in #ifdef ( ), got " + describe(nt));
  std::string name = nt.text;
  bool local_only = false, global_only = false;
  if ((name == "local" || name == "global") && is_symbol(".")) {
    local_only = name == "local";
    global_only = name == "global";
    next();
    if (tok().kind != Token::Word) unexpected("a name after '.'");
    name = tok().text;
    next();
  }
  bool defined;
  if (local_only) {
    defined = scopes_.back().count(name) > 0;
  } else if (global_only) {
    defined = scopes_.front().count(name) > 0;
  } else {
    const Symbol* s = find_symbol(name);
    defined = s != nullptr;
    if (s && s->value.kind == Value::Array && is_symbol("[")) {
      // An array element: defined when assigned.
      const ArrayValue& a = *s->value.array;
      std::size_t index = 0;
      for (std::size_t k = 0; k < a.sizes.size() && accept_symbol("["); ++k) {
        const double i = number("an array index");
        expect_symbol("]", "after the index");
        if (i < 0 || i >= a.sizes[k]) fail_here("array index out of range");
        index = index * static_cast<std::size_t>(a.sizes[k]) + static_cast<std::size_t>(i);
      }
      defined = index < a.elements.size() && a.elements[index].has_value();
    }
  }
  expect_symbol(")", "to close #ifdef (");
  return defined;
}

void Interpreter::begin_switch(const Token& d) {
  ++opaque_;
  const double v = paren_number("#switch");
  --opaque_;
  unread();
  for (;;) {
    const Token t = skip_to(false, true);
    if (t.text == "end") return;
    bool match = t.text == "else";
    if (!match) {
      ++opaque_;
      expect_symbol("(", ("after #" + t.text).c_str());
      const double a = number("#case");
      if (t.text == "range") {
        expect_symbol(",", "between #range's bounds");
        const double b = number("#range");
        match = v >= a && v <= b;
      } else {
        match = std::fabs(v - a) < 1e-10;
      }
      expect_symbol(")", ("to close #" + t.text).c_str());
      --opaque_;
    }
    if (match) {
      Frame f;
      f.kind = FrameKind::Switch;
      f.pos = d.pos;
      f.inputs = inputs_.size();
      frames_.push_back(f);
      return;
    }
  }
}

void Interpreter::count_iteration(const Frame& f) {
  if (++iterations_ > options_.limits.loop_iterations)
    fail_at(f.pos, "loops ran more than " + std::to_string(options_.limits.loop_iterations) +
                       " iterations in all (an endless #while?); raise the bound with "
                       "--pov-max-iterations N");
}

void Interpreter::begin_while(const Token& d) {
  Frame f;
  f.kind = FrameKind::While;
  f.pos = d.pos;
  f.inputs = inputs_.size();
  f.loop = inputs_.back().cursor;
  ++opaque_;
  const bool go = std::fabs(paren_number("#while")) > 1e-10;
  --opaque_;
  unread();
  if (!go) {
    skip_to(false, false);
    return;
  }
  frames_.push_back(f);
}

void Interpreter::begin_for(const Token& d) {
  Frame f;
  f.kind = FrameKind::For;
  f.pos = d.pos;
  f.inputs = inputs_.size();
  ++opaque_;
  expect_symbol("(", "after #for");
  if (tok().kind != Token::Word) unexpected("the loop variable's name");
  f.variable = tok().text;
  next();
  expect_symbol(",", "after the loop variable");
  const double start = number("#for's start");
  expect_symbol(",", "after #for's start");
  f.end = number("#for's end");
  if (accept_symbol(",")) f.step = number("#for's step");
  if (!is_symbol(")")) unexpected("')' to close #for (");
  next();
  --opaque_;
  if (f.step == 0) fail_at(d.pos, "#for's step must not be 0");
  f.loop = inputs_.back().cursor;
  assign(f.variable, Value::number(start), true, d.pos);
  if (f.step > 0 ? start > f.end : start < f.end) {
    skip_to(false, false);
    return;
  }
  frames_.push_back(f);
}

void Interpreter::end_directive(const Token& d) {
  if (frames_.empty() || frames_.back().inputs != inputs_.size() ||
      frames_.back().kind == FrameKind::Include)
    fail_at(d.pos, "#end without an open #if, #while, #for, #switch or #macro");
  Frame& f = frames_.back();
  switch (f.kind) {
    case FrameKind::If:
    case FrameKind::Switch:
      frames_.pop_back();
      return;
    case FrameKind::Macro:
      end_macro();
      return;
    case FrameKind::While: {
      count_iteration(f);
      const Cursor after = inputs_.back().cursor;
      inputs_.back().cursor = f.loop;
      have_ = pending_ = false;
      ++opaque_;
      const bool go = std::fabs(paren_number("#while")) > 1e-10;
      --opaque_;
      unread();
      if (!go) {
        inputs_.back().cursor = after;
        frames_.pop_back();
      }
      return;
    }
    case FrameKind::For: {
      count_iteration(f);
      const Symbol* s = find_symbol(f.variable);
      if (!s || s->value.kind != Value::Float)
        fail_at(d.pos, "#for's variable " + f.variable + " is no longer a float");
      const double v = s->value.v[0] + f.step;
      assign(f.variable, Value::number(v), true, d.pos);
      if (f.step > 0 ? v <= f.end : v >= f.end)
        inputs_.back().cursor = f.loop;
      else
        frames_.pop_back();
      return;
    }
    case FrameKind::Include:
      break;
  }
}

void Interpreter::break_directive(const Token& d) {
  std::size_t target = frames_.size();
  while (target > 0) {
    const FrameKind k = frames_[target - 1].kind;
    if (k == FrameKind::Switch || k == FrameKind::While || k == FrameKind::For) break;
    if (k != FrameKind::If) {
      target = 0;
      break;
    }
    --target;
  }
  if (target == 0) fail_at(d.pos, "#break outside #switch, #while or #for");
  while (frames_.size() >= target) {
    skip_to(false, false);
    frames_.pop_back();
  }
}

}  // namespace raycast::pov
