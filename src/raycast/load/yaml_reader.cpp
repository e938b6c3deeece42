#include "load/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "load/did_you_mean.h"

namespace raycast {

void fail_at(const SourceContext& ctx, const YamlMark& mark, const std::string& message) {
  // Marks are 0-based; a null mark (-1) means "position unknown".
  const int line = mark.line >= 0 ? mark.line + 1 : 0;
  const int column = mark.column >= 0 ? mark.column + 1 : 0;
  throw SceneError(ctx.file, line, column, message);
}

void fail_at(const SourceContext& ctx, const YamlNode& node, const std::string& message) {
  fail_at(ctx, node.Mark(), message);
}

std::string key_text(const SourceContext& ctx, const YamlNode& key) {
  if (key.IsNull()) return "null";
  if (!key.IsScalar()) fail_at(ctx, key, "bad conversion");
  return std::string(key.Scalar());
}

std::string describe(const YamlNode& node) {
  switch (node.Type()) {
    case YamlType::kNull:
    case YamlType::kUndefined:
      return "nothing";
    case YamlType::kScalar: {
      std::string s(node.Scalar());
      if (s.size() > 40) s = s.substr(0, 37) + "...";
      return s;
    }
    case YamlType::kSequence:
      return "a list of " + std::to_string(node.size());
    case YamlType::kMap:
      return "a mapping";
  }
  return "?";
}

namespace {

// Parses a YAML scalar as a double, accepting the spellings users write for non-finite values
// only so that they can be rejected with a precise message. What strtod accepts is a number:
// from_chars answers the common decimal spellings alike without a terminated copy, and strtod the
// rest (a leading '+' or blank, hexadecimal, out of range).
bool parse_double(std::string_view text, double& out) {
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (ec == std::errc() && end == text.data() + text.size()) return true;
  const std::string copy(text);
  const char* s = copy.c_str();
  char* stop = nullptr;
  out = std::strtod(s, &stop);
  if (stop != s + copy.size()) {
    if (text == ".nan" || text == ".NaN" || text == ".NAN") {
      out = std::nan("");
      return true;
    }
    if (text == ".inf" || text == ".Inf" || text == "+.inf") {
      out = INFINITY;
      return true;
    }
    if (text == "-.inf" || text == "-.Inf") {
      out = -INFINITY;
      return true;
    }
    return false;
  }
  return true;
}

// The first pair of `map` whose text key repeats an earlier one, and that earlier one; nullptr when
// no key repeats. Mappings of fields hold a handful of keys: comparing pairs beats building an
// index, which only larger mappings get.
std::pair<const YamlPair*, const YamlPair*> repeated_key(const YamlNode& map) {
  constexpr std::size_t kScanned = 16;
  std::map<std::string_view, const YamlPair*> seen;
  for (const YamlPair& kv : pairs_of(map)) {
    if (!kv.key().IsScalar()) continue;
    const std::string_view key = kv.key().Scalar();
    if (map.size() > kScanned) {
      const auto [it, fresh] = seen.emplace(key, &kv);
      if (!fresh) return {&kv, it->second};
      continue;
    }
    for (const YamlPair* other = map.pairs_begin(); other != &kv; ++other)
      if (other->key().IsScalar() && other->key().Scalar() == key) return {&kv, other};
  }
  return {nullptr, nullptr};
}

}  // namespace

double read_number(const SourceContext& ctx, const YamlNode& node, const std::string& what) {
  double v;
  if (!node.IsScalar() || !parse_double(node.Scalar(), v))
    fail_at(ctx, node, what + " must be a number, got " + describe(node));
  if (!std::isfinite(v))
    fail_at(ctx, node, what + " must be finite, got " + std::string(node.Scalar()));
  return v;
}

namespace {

// Entry i of a list of numbers; its name, `what[i]`, is spelled only for a failure's message.
double read_entry(const SourceContext& ctx, const YamlNode& node, const std::string& what,
                  std::size_t i) {
  double v;
  if (node.IsScalar() && parse_double(node.Scalar(), v) && std::isfinite(v)) return v;
  return read_number(ctx, node, what + "[" + std::to_string(i) + "]");  // throws
}

}  // namespace

std::vector<double> read_numbers(const SourceContext& ctx, const YamlNode& node,
                                 const std::string& what) {
  if (!node.IsSequence())
    fail_at(ctx, node, what + " must be a list of numbers, got " + describe(node));
  std::vector<double> v;
  v.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i) v.push_back(read_entry(ctx, node[i], what, i));
  return v;
}

Vec3 read_vec3(const SourceContext& ctx, const YamlNode& node, const std::string& what) {
  if (!node.IsSequence() || node.size() != 3)
    fail_at(ctx, node, what + " must be a list of 3 numbers, got " + describe(node));
  return {read_entry(ctx, node[0], what, 0), read_entry(ctx, node[1], what, 1),
          read_entry(ctx, node[2], what, 2)};
}

std::vector<Vec3> read_points(const SourceContext& ctx, const YamlNode& node,
                              const std::string& what) {
  if (!node.IsSequence())
    fail_at(ctx, node, what + " must be a list of [x, y, z] points, got " + describe(node));
  std::vector<Vec3> pts;
  pts.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i)
    pts.push_back(read_vec3(ctx, node[i], what + "[" + std::to_string(i) + "]"));
  return pts;
}

Fields::Fields(const SourceContext& ctx, const YamlNode& map, std::string what)
    : ctx_(ctx), map_(map), what_(std::move(what)) {
  asked_.reserve(64);
  if (map.IsNull()) return;  // an empty mapping: every lookup is absent
  if (!map.IsMap()) fail_at(ctx, map, what_ + " must be a mapping, got " + describe(map));
  // Lookups answer the first of a repeated key, so the user's second value would be lost
  // without a word.
  if (const auto [again, first] = repeated_key(map_); again) {
    const YamlMark m = first->key().Mark();
    fail_at(ctx, again->key(),
            "key '" + std::string(again->key().Scalar()) + "' is given twice in " + what_ +
                " (first at " + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1) +
                ")");
  }
  if (map_.size() > 64) read_more_.assign(map_.size() - 64, false);
}

bool Fields::pair_read(std::size_t pair) const {
  return pair < 64 ? (read_first_ >> pair) & 1 : read_more_[pair - 64];
}

void Fields::mark_read(std::size_t pair) {
  if (pair < 64)
    read_first_ |= std::uint64_t{1} << pair;
  else
    read_more_[pair - 64] = true;
}

void Fields::ask(const std::string& key) const {
  if (was_asked(key)) return;
  asked_ += key;
  asked_ += '\0';
}

bool Fields::was_asked(std::string_view key) const {
  for (std::size_t at = 0; at < asked_.size();) {
    const std::size_t end = asked_.find('\0', at);
    if (std::string_view(asked_).substr(at, end - at) == key) return true;
    at = end + 1;
  }
  return false;
}

bool Fields::was_read(std::string_view key) const {
  for (const YamlPair& kv : pairs_of(map_))
    if (kv.key().IsScalar() && kv.key().Scalar() == key)
      return pair_read(static_cast<std::size_t>(&kv - map_.pairs_begin()));
  return false;
}

YamlNode Fields::take(const std::string& key) {
  for (const YamlPair& kv : pairs_of(map_)) {
    if (kv.key().IsScalar() && kv.key().Scalar() == key) {
      mark_read(static_cast<std::size_t>(&kv - map_.pairs_begin()));
      return kv.value();
    }
  }
  return YamlNode();
}

bool Fields::has(const std::string& key) const {
  ask(key);
  return map_[key].IsDefined();
}

void Fields::fail(const std::string& key, const std::string& message) const {
  const YamlNode n = map_[key];
  fail_at(ctx_, n.IsDefined() ? n : map_, message);
}

YamlNode Fields::required(const std::string& key) {
  ask(key);
  const YamlNode n = take(key);
  if (!n.IsDefined()) {
    // A misspelling of the missing key is the likelier mistake: name it.
    for (const YamlPair& kv : pairs_of(map_)) {
      if (!kv.key().IsScalar()) continue;
      const std::string other(kv.key().Scalar());
      if (was_read(other) || was_asked(other)) continue;
      if (nearest_name(other, {key}) == key)
        fail_at(ctx_, kv.key(),
                "unknown key '" + other + "' in " + what_ + " (did you mean '" + key + "'?); " +
                    name(key) + " is required");
    }
    fail_at(ctx_, map_, name(key) + " is required");
  }
  return n;
}

YamlNode Fields::optional(const std::string& key) {
  ask(key);
  return take(key);
}

double Fields::number(const std::string& key) {
  return read_number(ctx_, required(key), name(key));
}
double Fields::number(const std::string& key, double fallback) {
  const YamlNode n = optional(key);
  return n.IsDefined() ? read_number(ctx_, n, name(key)) : fallback;
}

double Fields::positive(const std::string& key) {
  const YamlNode n = required(key);
  const double v = read_number(ctx_, n, name(key));
  if (!(v > 0)) fail_at(ctx_, n, name(key) + " must be > 0, got " + std::string(n.Scalar()));
  return v;
}
double Fields::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : fallback;
}
double Fields::non_negative(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const YamlNode n = required(key);
  const double v = read_number(ctx_, n, name(key));
  if (v < 0) fail_at(ctx_, n, name(key) + " must be >= 0, got " + std::string(n.Scalar()));
  return v;
}

int Fields::integer(const std::string& key, int fallback, int lo, int hi) {
  if (!has(key)) return fallback;
  const YamlNode n = required(key);
  const double v = read_number(ctx_, n, name(key));
  if (v != std::floor(v) || v < lo || v > hi)
    fail_at(ctx_, n,
            name(key) + " must be a whole number in [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "], got " + std::string(n.Scalar()));
  return static_cast<int>(v);
}

bool Fields::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const YamlNode n = required(key);
  if (n.IsScalar()) {
    const std::string_view s = n.Scalar();
    if (s == "true" || s == "True" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "False" || s == "no" || s == "off") return false;
  }
  fail_at(ctx_, n, name(key) + " must be true or false, got " + describe(n));
}

std::string Fields::string(const std::string& key) {
  const YamlNode n = required(key);
  if (!n.IsScalar()) fail_at(ctx_, n, name(key) + " must be text, got " + describe(n));
  return std::string(n.Scalar());
}
std::string Fields::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

Vec3 Fields::vec3(const std::string& key) { return read_vec3(ctx_, required(key), name(key)); }
Vec3 Fields::vec3(const std::string& key, const Vec3& fallback) {
  return has(key) ? vec3(key) : fallback;
}

Vec3 Fields::direction(const std::string& key) {
  const YamlNode n = required(key);
  const Vec3 v = read_vec3(ctx_, n, name(key));
  if (length_squared(v) == 0) fail_at(ctx_, n, name(key) + " must be a non-zero vector");
  if (!std::isfinite(length_squared(v))) fail_at(ctx_, n, name(key) + " is too large");
  return v;
}
Vec3 Fields::direction(const std::string& key, const Vec3& fallback) {
  return has(key) ? direction(key) : fallback;
}

void Fields::finish() const {
  for (const YamlPair& kv : pairs_of(map_)) {
    const YamlNode k = kv.key();
    if (!k.IsScalar() || !pair_read(static_cast<std::size_t>(&kv - map_.pairs_begin()))) {
      std::vector<std::string> valid;  // sorted: the nearest name's ties go to the first
      for (std::size_t at = 0; at < asked_.size(); at = asked_.find('\0', at) + 1)
        valid.emplace_back(asked_.c_str() + at);
      std::sort(valid.begin(), valid.end());
      fail_at(ctx_, k,
              "unknown key '" + describe(k) + "' in " + what_ +
                  did_you_mean(std::string(k.Scalar()), valid));
    }
  }
}

namespace {

// One step of a transform list: {translate: v}, {scale: v}, {rotate: {axis, degrees}} or
// {matrix: rows}.
Transform read_transform_step(const SourceContext& ctx, const YamlNode& step) {
  if (!step.IsMap() || step.size() != 1)
    fail_at(ctx, step, "a transform step must be one of translate, scale, rotate, matrix");
  const YamlNode key = step.pairs_begin()->key();
  const YamlNode v = step.pairs_begin()->value();
  const std::string kind = key_text(ctx, key);
  if (kind == "translate") return Transform::translate(read_vec3(ctx, v, "translate"));
  if (kind == "scale") {
    Vec3 s;
    if (v.IsScalar()) {
      const double k = read_number(ctx, v, "scale");
      s = {k, k, k};
    } else {
      s = read_vec3(ctx, v, "scale");
    }
    if (s.x == 0 || s.y == 0 || s.z == 0) fail_at(ctx, v, "scale must be non-zero on every axis");
    return Transform::scale(s);
  }
  if (kind == "rotate") {
    Fields f(ctx, v, "rotate");
    const Vec3 axis = f.direction("axis");
    const double degrees = f.number("degrees");
    f.finish();
    return Transform::rotate(axis, degrees);
  }
  if (kind == "matrix") {
    if (!v.IsSequence() || v.size() != 4) fail_at(ctx, v, "matrix must be 4 rows of 4 numbers");
    Mat4 m;
    for (int i = 0; i < 4; ++i) {
      const auto row = read_numbers(ctx, v[i], "matrix row");
      if (row.size() != 4) fail_at(ctx, v[i], "matrix must be 4 rows of 4 numbers");
      for (int j = 0; j < 4; ++j) m.m[i][j] = row[j];
    }
    const auto made = Transform::from_matrix(m);
    if (!made) fail_at(ctx, v, "matrix must be invertible with last row [0, 0, 0, 1]");
    return *made;
  }
  fail_at(ctx, key,
          "unknown transform step '" + kind + "' (expected translate, scale, rotate or matrix)");
}

}  // namespace

Transform read_transform(const SourceContext& ctx, const YamlNode& node) {
  Transform xf;
  if (node.IsMap()) {
    xf = read_transform_step(ctx, node);  // a single step written without the list brackets
  } else {
    if (!node.IsSequence())
      fail_at(ctx, node, "transform must be a list of steps, got " + describe(node));
    for (const YamlNode step : node) xf = read_transform_step(ctx, step) * xf;  // first to last
  }
  // Reject composites whose inverse over- or underflowed.
  const auto check = Transform::from_matrix(xf.matrix());
  if (!check) fail_at(ctx, node, "transform is singular or not finite");
  return xf;
}

}  // namespace raycast
