#include "load/yaml_reader.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "load/did_you_mean.h"

namespace raycast {

void fail_at(const SourceContext& ctx, const YAML::Mark& mark, const std::string& message) {
  // yaml-cpp marks are 0-based; a null mark (-1) means "position unknown".
  const int line = mark.line >= 0 ? mark.line + 1 : 0;
  const int column = mark.column >= 0 ? mark.column + 1 : 0;
  throw SceneError(ctx.file, line, column, message);
}

void fail_at(const SourceContext& ctx, const YAML::Node& node, const std::string& message) {
  fail_at(ctx, node.Mark(), message);
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return "nothing";
    case YAML::NodeType::Scalar: {
      std::string s = node.Scalar();
      if (s.size() > 40) s = s.substr(0, 37) + "...";
      return s;
    }
    case YAML::NodeType::Sequence:
      return "a list of " + std::to_string(node.size());
    case YAML::NodeType::Map:
      return "a mapping";
  }
  return "?";
}

namespace {

// Parses a YAML scalar as a double, accepting the spellings users write for non-finite values
// only so that they can be rejected with a precise message.
bool parse_double(const std::string& text, double& out) {
  if (text.empty()) return false;
  const char* s = text.c_str();
  char* end = nullptr;
  out = std::strtod(s, &end);
  if (end != s + text.size()) {
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

}  // namespace

double read_number(const SourceContext& ctx, const YAML::Node& node, const std::string& what) {
  double v;
  if (!node.IsScalar() || !parse_double(node.Scalar(), v))
    fail_at(ctx, node, what + " must be a number, got " + describe(node));
  if (!std::isfinite(v)) fail_at(ctx, node, what + " must be finite, got " + node.Scalar());
  return v;
}

std::vector<double> read_numbers(const SourceContext& ctx, const YAML::Node& node,
                                 const std::string& what) {
  if (!node.IsSequence())
    fail_at(ctx, node, what + " must be a list of numbers, got " + describe(node));
  std::vector<double> v;
  v.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i)
    v.push_back(read_number(ctx, node[i], what + "[" + std::to_string(i) + "]"));
  return v;
}

Vec3 read_vec3(const SourceContext& ctx, const YAML::Node& node, const std::string& what) {
  if (!node.IsSequence() || node.size() != 3)
    fail_at(ctx, node, what + " must be a list of 3 numbers, got " + describe(node));
  const auto v = read_numbers(ctx, node, what);
  return {v[0], v[1], v[2]};
}

std::vector<Vec3> read_points(const SourceContext& ctx, const YAML::Node& node,
                              const std::string& what) {
  if (!node.IsSequence())
    fail_at(ctx, node, what + " must be a list of [x, y, z] points, got " + describe(node));
  std::vector<Vec3> pts;
  pts.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i)
    pts.push_back(read_vec3(ctx, node[i], what + "[" + std::to_string(i) + "]"));
  return pts;
}

Fields::Fields(const SourceContext& ctx, const YAML::Node& map, std::string what)
    : ctx_(ctx), map_(map), what_(std::move(what)) {
  if (map.IsNull()) {
    map_ = YAML::Node(YAML::NodeType::Map);
    return;
  }
  if (!map.IsMap()) fail_at(ctx, map, what_ + " must be a mapping, got " + describe(map));
  // yaml-cpp keeps both entries of a repeated key and answers lookups with the first, so the
  // user's second value would be lost without a word.
  std::map<std::string, YAML::Mark> seen;
  for (const auto& kv : map_) {
    if (!kv.first.IsScalar()) continue;
    const auto [it, fresh] = seen.emplace(kv.first.Scalar(), kv.first.Mark());
    if (!fresh)
      fail_at(ctx, kv.first,
              "key '" + kv.first.Scalar() + "' is given twice in " + what_ + " (first at " +
                  std::to_string(it->second.line + 1) + ":" +
                  std::to_string(it->second.column + 1) + ")");
  }
}

bool Fields::has(const std::string& key) const {
  asked_.insert(key);
  return map_[key].IsDefined();
}

void Fields::fail(const std::string& key, const std::string& message) const {
  const YAML::Node n = map_[key];
  fail_at(ctx_, n.IsDefined() ? n : map_, message);
}

YAML::Node Fields::required(const std::string& key) {
  asked_.insert(key);
  const YAML::Node n = map_[key];
  if (!n.IsDefined()) {
    // A misspelling of the missing key is the likelier mistake: name it.
    for (const auto& kv : map_) {
      if (!kv.first.IsScalar() || read_.count(kv.first.Scalar()) || asked_.count(kv.first.Scalar()))
        continue;
      if (nearest_name(kv.first.Scalar(), {key}) == key)
        fail_at(ctx_, kv.first,
                "unknown key '" + kv.first.Scalar() + "' in " + what_ + " (did you mean '" + key +
                    "'?); " + name(key) + " is required");
    }
    fail_at(ctx_, map_, name(key) + " is required");
  }
  read_.insert(key);
  return n;
}

YAML::Node Fields::optional(const std::string& key) {
  asked_.insert(key);
  const YAML::Node n = map_[key];
  if (n.IsDefined()) read_.insert(key);
  return n;
}

double Fields::number(const std::string& key) {
  return read_number(ctx_, required(key), name(key));
}
double Fields::number(const std::string& key, double fallback) {
  const YAML::Node n = optional(key);
  return n.IsDefined() ? read_number(ctx_, n, name(key)) : fallback;
}

double Fields::positive(const std::string& key) {
  const YAML::Node n = required(key);
  const double v = read_number(ctx_, n, name(key));
  if (!(v > 0)) fail_at(ctx_, n, name(key) + " must be > 0, got " + n.Scalar());
  return v;
}
double Fields::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : fallback;
}
double Fields::non_negative(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const YAML::Node n = required(key);
  const double v = read_number(ctx_, n, name(key));
  if (v < 0) fail_at(ctx_, n, name(key) + " must be >= 0, got " + n.Scalar());
  return v;
}

int Fields::integer(const std::string& key, int fallback, int lo, int hi) {
  if (!has(key)) return fallback;
  const YAML::Node n = required(key);
  const double v = read_number(ctx_, n, name(key));
  if (v != std::floor(v) || v < lo || v > hi)
    fail_at(ctx_, n,
            name(key) + " must be a whole number in [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "], got " + n.Scalar());
  return static_cast<int>(v);
}

bool Fields::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const YAML::Node n = required(key);
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "True" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "False" || s == "no" || s == "off") return false;
  }
  fail_at(ctx_, n, name(key) + " must be true or false, got " + describe(n));
}

std::string Fields::string(const std::string& key) {
  const YAML::Node n = required(key);
  if (!n.IsScalar()) fail_at(ctx_, n, name(key) + " must be text, got " + describe(n));
  return n.Scalar();
}
std::string Fields::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

Vec3 Fields::vec3(const std::string& key) { return read_vec3(ctx_, required(key), name(key)); }
Vec3 Fields::vec3(const std::string& key, const Vec3& fallback) {
  return has(key) ? vec3(key) : fallback;
}

Vec3 Fields::direction(const std::string& key) {
  const YAML::Node n = required(key);
  const Vec3 v = read_vec3(ctx_, n, name(key));
  if (length_squared(v) == 0) fail_at(ctx_, n, name(key) + " must be a non-zero vector");
  if (!std::isfinite(length_squared(v))) fail_at(ctx_, n, name(key) + " is too large");
  return v;
}
Vec3 Fields::direction(const std::string& key, const Vec3& fallback) {
  return has(key) ? direction(key) : fallback;
}

void Fields::finish() const {
  for (const auto& kv : map_) {
    const YAML::Node& k = kv.first;
    const std::string key = k.IsScalar() ? k.Scalar() : "";
    if (!k.IsScalar() || !read_.count(key)) {
      const std::vector<std::string> valid(asked_.begin(), asked_.end());
      fail_at(ctx_, k, "unknown key '" + describe(k) + "' in " + what_ + did_you_mean(key, valid));
    }
  }
}

Transform read_transform(const SourceContext& ctx, const YAML::Node& node) {
  if (node.IsMap()) {
    // A single step written without the list brackets.
    YAML::Node list(YAML::NodeType::Sequence);
    list.push_back(node);
    return read_transform(ctx, list);
  }
  if (!node.IsSequence())
    fail_at(ctx, node, "transform must be a list of steps, got " + describe(node));
  Transform xf;
  for (const YAML::Node& step : node) {
    if (!step.IsMap() || step.size() != 1)
      fail_at(ctx, step, "a transform step must be one of translate, scale, rotate, matrix");
    const std::string kind = step.begin()->first.as<std::string>();
    const YAML::Node v = step.begin()->second;
    Transform t;
    if (kind == "translate") {
      t = Transform::translate(read_vec3(ctx, v, "translate"));
    } else if (kind == "scale") {
      Vec3 s;
      if (v.IsScalar()) {
        const double k = read_number(ctx, v, "scale");
        s = {k, k, k};
      } else {
        s = read_vec3(ctx, v, "scale");
      }
      if (s.x == 0 || s.y == 0 || s.z == 0) fail_at(ctx, v, "scale must be non-zero on every axis");
      t = Transform::scale(s);
    } else if (kind == "rotate") {
      Fields f(ctx, v, "rotate");
      const Vec3 axis = f.direction("axis");
      const double degrees = f.number("degrees");
      f.finish();
      t = Transform::rotate(axis, degrees);
    } else if (kind == "matrix") {
      if (!v.IsSequence() || v.size() != 4) fail_at(ctx, v, "matrix must be 4 rows of 4 numbers");
      Mat4 m;
      for (int i = 0; i < 4; ++i) {
        const auto row = read_numbers(ctx, v[i], "matrix row");
        if (row.size() != 4) fail_at(ctx, v[i], "matrix must be 4 rows of 4 numbers");
        for (int j = 0; j < 4; ++j) m.m[i][j] = row[j];
      }
      const auto made = Transform::from_matrix(m);
      if (!made) fail_at(ctx, v, "matrix must be invertible with last row [0, 0, 0, 1]");
      t = *made;
    } else {
      fail_at(
          ctx, step.begin()->first,
          "unknown transform step '" + kind + "' (expected translate, scale, rotate or matrix)");
    }
    xf = t * xf;  // applied first to last
  }
  // Reject composites whose inverse over- or underflowed.
  const auto check = Transform::from_matrix(xf.matrix());
  if (!check) fail_at(ctx, node, "transform is singular or not finite");
  return xf;
}

}  // namespace raycast
