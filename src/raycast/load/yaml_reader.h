#pragma once
// Typed, positioned reading of YAML nodes: every failure is a SceneError at the node's position.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "io/scene_error.h"
#include "load/yaml_node.h"
#include "math/transform.h"
#include "math/vec3.h"

namespace raycast {

/// Where the scene came from, for error positions and resolving relative paths.
struct SourceContext {
  std::string file;  // as given by the user, used in messages
  std::string dir;   // folder that relative paths resolve against
  int frame = -1;    // the frame `{frame}` patterns in data paths expand to (-1: none given)
  std::vector<std::string>* files = nullptr;  // when set, every data file read is appended
};

/// Throws SceneError at node's position (1-based line and column).
[[noreturn]] void fail_at(const SourceContext& ctx, const YamlNode& node,
                          const std::string& message);
[[noreturn]] void fail_at(const SourceContext& ctx, const YamlMark& mark,
                          const std::string& message);

/// A mapping key read as text: a scalar's own, "null" for a null key (yaml-cpp's reading, which
/// scenes were first written against); a collection is an error at it.
std::string key_text(const SourceContext& ctx, const YamlNode& key);

/// A short rendering of a node's value for messages ("-1", "[1, 2]", "a mapping").
std::string describe(const YamlNode& node);

/// Reads a mapping's fields by name and, on finish(), rejects any key that was not read, naming
/// the nearest key that was asked for ("did you mean"). A key given twice is an error naming both
/// positions. `what` prefixes messages: "sphere" gives "sphere.radius must be > 0, got -1".
class Fields {
 public:
  Fields(const SourceContext& ctx, const YamlNode& map, std::string what);

  bool has(const std::string& key) const;
  /// The node of a key, marking it read; throws when it is required and missing.
  YamlNode required(const std::string& key);
  YamlNode optional(const std::string& key);  // an undefined node when absent

  double number(const std::string& key);                   // required
  double number(const std::string& key, double fallback);  // optional
  double positive(const std::string& key);                 // required, > 0
  double positive(const std::string& key, double fallback);
  double non_negative(const std::string& key, double fallback);
  int integer(const std::string& key, int fallback, int lo, int hi);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  Vec3 vec3(const std::string& key);
  Vec3 vec3(const std::string& key, const Vec3& fallback);
  /// A non-zero finite vector (directions, normals, axes).
  Vec3 direction(const std::string& key);
  Vec3 direction(const std::string& key, const Vec3& fallback);

  /// Throws for the first key not read; call once all fields have been taken.
  void finish() const;
  const YamlNode& node() const { return map_; }
  const SourceContext& ctx() const { return ctx_; }
  std::string name(const std::string& key) const { return what_ + "." + key; }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const SourceContext& ctx_;
  YamlNode map_;
  std::string what_;
  void ask(const std::string& key) const;
  bool was_asked(std::string_view key) const;
  bool was_read(std::string_view key) const;
  YamlNode take(const std::string& key);  // the key's value, marked read when present

  bool pair_read(std::size_t pair) const;
  void mark_read(std::size_t pair);

  // Which pairs were read (keys are unique: the constructor checks): the first 64 by bit, so
  // that a shape's mapping needs no allocation, the rest in read_more_.
  std::uint64_t read_first_ = 0;
  std::vector<bool> read_more_;
  // Every key looked up, present or not (the valid keys), each followed by '\0': one string
  // rather than a set, since a shape's mapping asks for a handful of keys.
  mutable std::string asked_;
};

/// A finite number; `what` names it in the error.
double read_number(const SourceContext& ctx, const YamlNode& node, const std::string& what);
/// A sequence of exactly 3 finite numbers.
Vec3 read_vec3(const SourceContext& ctx, const YamlNode& node, const std::string& what);
/// A sequence of numbers (any length, each finite).
std::vector<double> read_numbers(const SourceContext& ctx, const YamlNode& node,
                                 const std::string& what);
/// A sequence of [x, y, z] points.
std::vector<Vec3> read_points(const SourceContext& ctx, const YamlNode& node,
                              const std::string& what);

/// A `transform:` list (translate, scale, rotate, matrix), composed first to last.
Transform read_transform(const SourceContext& ctx, const YamlNode& node);

}  // namespace raycast
