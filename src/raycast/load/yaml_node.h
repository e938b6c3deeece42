#pragma once
// A parsed YAML document as a compact tree of positioned nodes (docs/performance.md "Loading large
// scenes"). Nodes live in one arena owned by their YamlDocument; scalars are views of the scene
// text where it spells them literally, else of a copy in the arena. A YamlNode is a pointer-sized
// handle, valid while its document lives.
//
// The members the readers use keep yaml-cpp's names and meanings (IsMap, Scalar, Mark, ...), so
// that code written against either reads the same.
#include <cstdint>
#include <memory>
#include <memory_resource>
#include <string>
#include <string_view>

namespace raycast {

/// A position in the text, 0-based (yaml-cpp's convention); -1 when unknown.
struct YamlMark {
  int line = -1;
  int column = -1;
};

/// Undefined: what a lookup of a missing key or index answers. Null: `~`, `null`, `Null`,
/// `NULL` or nothing, when written plain and without a tag (as yaml-cpp reads them).
enum class YamlType : std::uint8_t { kUndefined, kNull, kScalar, kSequence, kMap };

/// One node's storage, 24 bytes: a scene of 100,000 objects has over a million nodes.
struct YamlNodeData {
  // A scalar's text (const char*, not NUL-terminated), a sequence's entries
  // (const YamlNodeData* const*) or a mapping's pairs (const YamlPair*), by `type`.
  const void* items = nullptr;
  std::uint32_t size = 0;               // scalar length, or number of entries or pairs
  std::int32_t line = -1, column = -1;  // 0-based
  YamlType type = YamlType::kNull;
  bool quoted = false;  // a quoted or block scalar (never null, never plain)
};

class YamlNode;

/// A key and its value in a mapping.
struct YamlPair {
  const YamlNodeData* key_data;
  const YamlNodeData* value_data;
  YamlNode key() const;
  YamlNode value() const;
};

class YamlNode {
 public:
  YamlNode() = default;  // undefined
  explicit YamlNode(const YamlNodeData* data) : data_(data) {}

  YamlType Type() const { return data_ ? data_->type : YamlType::kUndefined; }
  bool IsDefined() const { return data_ != nullptr; }
  bool IsNull() const { return Type() == YamlType::kNull; }
  bool IsScalar() const { return Type() == YamlType::kScalar; }
  bool IsSequence() const { return Type() == YamlType::kSequence; }
  bool IsMap() const { return Type() == YamlType::kMap; }
  explicit operator bool() const { return IsDefined(); }
  /// Written in quotes or as a block scalar (so its first character is not at Mark()).
  bool IsQuoted() const { return data_ && data_->quoted; }

  /// A scalar's text ("" for any other node).
  std::string_view Scalar() const {
    return IsScalar() ? std::string_view(static_cast<const char*>(data_->items), data_->size)
                      : std::string_view();
  }
  YamlMark Mark() const { return data_ ? YamlMark{data_->line, data_->column} : YamlMark{}; }

  /// Entries of a sequence, pairs of a mapping; 0 for other nodes.
  std::size_t size() const;
  /// A sequence's entry `i`; undefined when out of range or not a sequence.
  YamlNode operator[](std::size_t i) const;
  YamlNode operator[](int i) const { return (*this)[static_cast<std::size_t>(i)]; }
  /// The value of the first key equal to `key` in a mapping; undefined when absent.
  YamlNode operator[](std::string_view key) const;
  YamlNode operator[](const char* key) const { return (*this)[std::string_view(key)]; }
  YamlNode operator[](const std::string& key) const { return (*this)[std::string_view(key)]; }

  /// A sequence's entries (nothing for other nodes).
  class SequenceIterator;
  SequenceIterator begin() const;
  SequenceIterator end() const;
  /// A mapping's pairs, in the order written (nothing for other nodes).
  const YamlPair* pairs_begin() const;
  const YamlPair* pairs_end() const;

  const YamlNodeData* data() const { return data_; }

 private:
  const YamlNodeData* const* entries() const;  // of a sequence
  const YamlNodeData* data_ = nullptr;
};

inline YamlNode YamlPair::key() const { return YamlNode(key_data); }
inline YamlNode YamlPair::value() const { return YamlNode(value_data); }

class YamlNode::SequenceIterator {
 public:
  explicit SequenceIterator(const YamlNodeData* const* at) : at_(at) {}
  YamlNode operator*() const { return YamlNode(*at_); }
  SequenceIterator& operator++() {
    ++at_;
    return *this;
  }
  bool operator!=(const SequenceIterator& o) const { return at_ != o.at_; }

 private:
  const YamlNodeData* const* at_;
};

/// A mapping's pairs as a range: `for (const YamlPair& kv : pairs_of(node))`.
struct YamlPairs {
  const YamlPair* b;
  const YamlPair* e;
  const YamlPair* begin() const { return b; }
  const YamlPair* end() const { return e; }
};
inline YamlPairs pairs_of(const YamlNode& node) { return {node.pairs_begin(), node.pairs_end()}; }

/// Owns the text and the arena of a parsed document; move-only, its nodes stay where they are.
class YamlDocument {
 public:
  YamlDocument();
  YamlDocument(YamlDocument&&) noexcept;
  YamlDocument& operator=(YamlDocument&&) noexcept;
  ~YamlDocument();

  YamlNode root() const { return YamlNode(root_); }

 private:
  friend YamlDocument build_yaml_document(std::string text, const std::string& name);
  std::unique_ptr<std::string> text_;
  std::unique_ptr<std::pmr::monotonic_buffer_resource> arena_;
  const YamlNodeData* root_ = nullptr;
};

}  // namespace raycast
