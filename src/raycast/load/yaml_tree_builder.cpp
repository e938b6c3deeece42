#include "load/yaml_tree_builder.h"

#include <yaml.h>

#include <algorithm>
#include <cstring>
#include <new>
#include <unordered_map>
#include <vector>

#include "io/scene_error.h"

namespace raycast {

namespace {

// Owns one libyaml event until the next replaces it.
class Event {
 public:
  Event() = default;
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;
  ~Event() { clear(); }
  yaml_event_t* get() { return &event_; }
  const yaml_event_t& operator*() const { return event_; }
  void clear() {
    if (held_) yaml_event_delete(&event_);
    held_ = false;
  }
  void hold() { held_ = true; }

 private:
  yaml_event_t event_{};
  bool held_ = false;
};

// The parser's state, freed on every exit.
struct Parser {
  yaml_parser_t parser;
  Parser() { yaml_parser_initialize(&parser); }
  ~Parser() { yaml_parser_delete(&parser); }
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;
};

bool is_null_spelling(const char* text, std::size_t size) {
  const std::string_view s(text, size);
  return s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL";
}

// The 0-based line and column of byte `offset` (libyaml's reader errors give only an offset).
YamlMark mark_at_offset(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  YamlMark m{0, 0};
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++m.line;
      m.column = 0;
    } else {
      ++m.column;
    }
  }
  return m;
}

// libyaml's message for a syntax error, worded for the scene author: a collection's missing
// closing bracket and a stray one get yaml-cpp's wording, which the loader's messages (and the
// scene format documentation) use.
std::string syntax_message(const yaml_parser_t& p, const std::string& text) {
  const std::string problem = p.problem ? p.problem : "syntax error";
  const std::string context = p.context ? p.context : "";
  const std::size_t at = p.problem_mark.index;
  const char c = at < text.size() ? text[at] : '\0';
  const bool in_flow = context.find("flow") != std::string::npos;
  if ((c == '}' || c == ']') && !in_flow) return "illegal flow end";
  if (context == "while parsing a flow mapping") return "end of map flow not found";
  if (context == "while parsing a flow sequence") return "end of sequence flow not found";
  return context.empty() ? problem : problem + " (" + context + ")";
}

}  // namespace

// Turns the event stream into nodes: a stack of open collections, whose children wait in one
// shared list until the collection ends and they are copied into the arena.
class YamlTreeBuilder {
 public:
  YamlTreeBuilder(std::string text, const std::string& name) : name_(name) {
    doc_.text_ = std::make_unique<std::string>(std::move(text));
    // Sized to the text: a scene needs about five times its text in nodes.
    doc_.arena_ = std::make_unique<std::pmr::monotonic_buffer_resource>(
        std::max<std::size_t>(4096, doc_.text_->size()));
  }

  YamlDocument build() {
    Parser p;
    const std::string& text = *doc_.text_;
    yaml_parser_set_input_string(&p.parser, reinterpret_cast<const unsigned char*>(text.data()),
                                 text.size());
    Event event;
    for (;;) {
      event.clear();
      if (!yaml_parser_parse(&p.parser, event.get())) fail_syntax(p.parser);
      event.hold();
      const yaml_event_type_t type = (*event).type;
      if (type == YAML_STREAM_END_EVENT || type == YAML_DOCUMENT_END_EVENT) break;
      on_event(*event);
    }
    if (!root_) {  // no document at all: a null root, as yaml-cpp answers
      void* at = doc_.arena_->allocate(sizeof(YamlNodeData), alignof(YamlNodeData));
      root_ = new (at) YamlNodeData;
    }
    doc_.root_ = root_;
    return std::move(doc_);
  }

 private:
  [[noreturn]] void fail(YamlMark m, const std::string& message) const {
    throw SceneError(name_, m.line + 1, m.column + 1, message);
  }

  [[noreturn]] void fail_syntax(const yaml_parser_t& p) const {
    const std::string& text = *doc_.text_;
    if (p.error == YAML_READER_ERROR)  // bad encoding: libyaml gives a byte offset only
      fail(mark_at_offset(text, p.problem_offset), p.problem ? p.problem : "unreadable text");
    if (p.error == YAML_MEMORY_ERROR) throw std::bad_alloc();
    fail({static_cast<int>(p.problem_mark.line), static_cast<int>(p.problem_mark.column)},
         syntax_message(p, text));
  }

  void on_event(const yaml_event_t& e) {
    switch (e.type) {
      case YAML_SCALAR_EVENT:
        return add(scalar(e), e.data.scalar.anchor);
      case YAML_ALIAS_EVENT:
        return add(alias(e), nullptr);
      case YAML_SEQUENCE_START_EVENT:
        return open(e, YamlType::kSequence, e.data.sequence_start.anchor);
      case YAML_MAPPING_START_EVENT:
        return open(e, YamlType::kMap, e.data.mapping_start.anchor);
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT:
        return close();
      default:
        return;  // stream and document starts
    }
  }

  YamlNodeData* new_node(const yaml_event_t& e, YamlType type) {
    void* at = doc_.arena_->allocate(sizeof(YamlNodeData), alignof(YamlNodeData));
    auto* node = new (at) YamlNodeData;
    node->type = type;
    node->line = static_cast<std::int32_t>(e.start_mark.line);
    node->column = static_cast<std::int32_t>(e.start_mark.column);
    return node;
  }

  const YamlNodeData* scalar(const yaml_event_t& e) {
    const auto& s = e.data.scalar;
    const char* value = reinterpret_cast<const char*>(s.value);
    const bool plain = s.style == YAML_PLAIN_SCALAR_STYLE;
    YamlNodeData* node =
        new_node(e, plain && !s.tag && is_null_spelling(value, s.length) ? YamlType::kNull
                                                                         : YamlType::kScalar);
    node->quoted = !plain;
    node->size = static_cast<std::uint32_t>(s.length);
    // A plain scalar on one line is its own text: viewed, not copied.
    const std::string& text = *doc_.text_;
    const std::size_t at = e.start_mark.index;
    if (plain && at <= text.size() && s.length <= text.size() - at &&
        std::memcmp(text.data() + at, value, s.length) == 0) {
      node->text = text.data() + at;
    } else {
      char* copy = static_cast<char*>(doc_.arena_->allocate(s.length + 1, 1));
      std::memcpy(copy, value, s.length);
      copy[s.length] = '\0';
      node->text = copy;
    }
    return node;
  }

  const YamlNodeData* alias(const yaml_event_t& e) {
    const auto it = anchors_.find(reinterpret_cast<const char*>(e.data.alias.anchor));
    if (it == anchors_.end())
      fail({static_cast<int>(e.start_mark.line), static_cast<int>(e.start_mark.column)},
           "the referenced anchor is not defined");
    return it->second;
  }

  void open(const yaml_event_t& e, YamlType type, const yaml_char_t* anchor) {
    open_.push_back({new_node(e, type), pending_.size(),
                     anchor ? std::string(reinterpret_cast<const char*>(anchor)) : std::string()});
  }

  // Ends the innermost collection; its anchor is defined only now, so that no alias inside it
  // can make the tree cyclic.
  void close() {
    OpenCollection c = std::move(open_.back());
    open_.pop_back();
    const std::size_t count = pending_.size() - c.first;
    const YamlNodeData* const* children = pending_.data() + c.first;
    if (c.node->type == YamlType::kSequence) {
      void* at = doc_.arena_->allocate(count * sizeof(YamlNodeData*), alignof(YamlNodeData*));
      auto* entries = static_cast<const YamlNodeData**>(at);
      std::copy(children, children + count, entries);
      c.node->entries = entries;
      c.node->size = static_cast<std::uint32_t>(count);
    } else {
      const std::size_t pairs = count / 2;
      void* at = doc_.arena_->allocate(pairs * sizeof(YamlPair), alignof(YamlPair));
      auto* out = static_cast<YamlPair*>(at);
      for (std::size_t i = 0; i < pairs; ++i)
        new (out + i) YamlPair{children[2 * i], children[2 * i + 1]};
      c.node->pairs = out;
      c.node->size = static_cast<std::uint32_t>(pairs);
    }
    pending_.resize(c.first);
    if (!c.anchor.empty()) anchors_[c.anchor] = c.node;
    add(c.node, nullptr);
  }

  void add(const YamlNodeData* node, const yaml_char_t* anchor) {
    if (anchor) anchors_[reinterpret_cast<const char*>(anchor)] = node;
    if (open_.empty()) {
      if (!root_) root_ = node;
    } else {
      pending_.push_back(node);
    }
  }

  struct OpenCollection {
    YamlNodeData* node;
    std::size_t first;   // its first child in pending_
    std::string anchor;  // "" when it has none
  };

  const std::string& name_;
  YamlDocument doc_;
  const YamlNodeData* root_ = nullptr;
  std::vector<OpenCollection> open_;
  std::vector<const YamlNodeData*> pending_;
  std::unordered_map<std::string, const YamlNodeData*> anchors_;
};

YamlDocument build_yaml_document(std::string text, const std::string& name) {
  return YamlTreeBuilder(std::move(text), name).build();
}

}  // namespace raycast
