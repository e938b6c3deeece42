#include "load/yaml_tree_builder.h"

#include <yaml.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>
#include <unordered_map>
#include <vector>

#include "io/huge_pages.h"
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

// The length of the UTF-8 sequence at text[i] when it is valid and a character libyaml accepts
// (YAML's printable set: tab, line breaks, no other control characters, no U+FEFF, U+FFFE or
// U+FFFF), else 0.
std::size_t accepted_sequence(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
  };
  const unsigned c = byte(i);
  if (c < 0x80) return c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c != 0x7f) ? 1 : 0;
  const std::size_t n = c >= 0xc2 && c <= 0xdf   ? 2
                        : c >= 0xe0 && c <= 0xef ? 3
                        : c >= 0xf0 && c <= 0xf4 ? 4
                                                 : 0;
  if (n == 0) return 0;
  unsigned code = c & (0x7f >> n);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3f);
  }
  const bool shortest = code >= (n == 2 ? 0x80u : n == 3 ? 0x800u : 0x10000u);
  const bool printable = code == 0x85 || (code >= 0xa0 && code <= 0xd7ff) ||
                         (code >= 0xe000 && code <= 0xfffd && code != 0xfeff) ||
                         (code >= 0x10000 && code <= 0x10ffff);
  const bool leading_bom = code == 0xfeff && i == 0;
  return shortest && (printable || leading_bom) ? n : 0;
}

// libyaml refuses text that is not UTF-8 or holds control characters; yaml-cpp, which scenes were
// first read with, took each such byte as U+FFFD (the replacement character), and so does this.
// Whether the 8 bytes at `p` are all printable ASCII (0x20 to 0x7e), tested at once.
bool printable_ascii_word(const char* p) {
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
  constexpr std::uint64_t kOnes = 0x0101010101010101, kHigh = 0x8080808080808080;
  const std::uint64_t below_space = (w - 0x20 * kOnes) & ~w;  // high bit where a byte < 0x20
  const std::uint64_t del = ((w ^ (0x7f * kOnes)) - kOnes) & ~(w ^ (0x7f * kOnes));  // == 0x7f
  return ((w | below_space | del) & kHigh) == 0;
}

std::string with_replacement_characters(std::string text) {
  std::size_t i = 0;
  while (i < text.size()) {  // most texts are accepted whole, without a copy
    if (i + 8 <= text.size() && printable_ascii_word(text.data() + i)) {
      i += 8;
      continue;
    }
    const auto c = static_cast<unsigned char>(text[i]);
    if ((c >= 0x20 && c < 0x7f) || c == '\n') {  // the usual characters, at once
      ++i;
      continue;
    }
    const std::size_t n = accepted_sequence(text, i);
    if (n == 0) break;
    i += n;
  }
  if (i == text.size()) return text;
  std::string out = text.substr(0, i);
  while (i < text.size()) {
    const std::size_t n = accepted_sequence(text, i);
    if (n == 0) {
      out += "\xEF\xBF\xBD";
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

// Turns libyaml's positions (lines, and columns counted in characters) into byte offsets in the
// text, walking forward from the last one asked for: events come in text order, so one pass
// answers them all. Columns are reported in bytes, as yaml-cpp reported them.
class ByteCursor {
 public:
  explicit ByteCursor(const std::string& text) : text_(text) {
    enter_line(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0);  // libyaml skips a BOM
  }

  // The byte offset of (line, column in characters); npos when the text's lines disagree with
  // libyaml's (a lone carriage return or a Unicode line separator also breaks lines there).
  std::size_t offset(std::size_t line, std::size_t column) {
    if (lost_ || line < line_) return std::string::npos;  // never, for events in text order
    while (line_ < line) {
      if (line_end_ == text_.size()) {
        lost_ = true;  // for good: searching again would make the walk quadratic
        return std::string::npos;
      }
      ++line_;
      enter_line(line_end_ + 1);
    }
    if (ascii_) return column <= line_end_ - line_start_ ? line_start_ + column : std::string::npos;
    if (column < column_) {
      at_ = line_start_;
      column_ = 0;
    }
    while (column_ < column) {
      if (at_ >= line_end_) return std::string::npos;
      at_ += sequence_length(static_cast<unsigned char>(text_[at_]));
      ++column_;
    }
    return at_;
  }
  std::size_t line_start() const { return line_start_; }

 private:
  // Lines of ASCII text, most of them, have a byte per character: no walk.
  void enter_line(std::size_t start) {
    line_start_ = at_ = start;
    column_ = 0;
    const std::size_t nl = text_.find('\n', start);
    line_end_ = nl == std::string::npos ? text_.size() : nl;
    unsigned char bits = 0;  // no early exit: the loop vectorises
    for (std::size_t k = start; k < line_end_; ++k) bits |= static_cast<unsigned char>(text_[k]);
    ascii_ = bits < 0x80;
  }
  static std::size_t sequence_length(unsigned char lead) {
    return lead < 0x80 ? 1 : lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : 2;
  }
  const std::string& text_;
  std::size_t line_ = 0, column_ = 0;                   // where at_ is, in libyaml's terms
  std::size_t at_ = 0, line_start_ = 0, line_end_ = 0;  // bytes; line_end_ at its '\n'
  bool ascii_ = true;
  bool lost_ = false;  // lines disagree: columns stay libyaml's
};

// libyaml's message for a syntax error, worded for the scene author: a collection's missing
// closing bracket and a stray one get yaml-cpp's wording, which the loader's messages (and the
// scene format documentation) use.
// `at` is the byte offset of the problem (npos when unknown).
std::string syntax_message(const yaml_parser_t& p, const std::string& text, std::size_t at) {
  const std::string problem = p.problem ? p.problem : "syntax error";
  const std::string context = p.context ? p.context : "";
  const char c = at < text.size() ? text[at] : '\0';
  const bool in_flow = context.find("flow") != std::string::npos;
  if ((c == '}' || c == ']') && !in_flow) return "illegal flow end";
  if (context == "while parsing a flow mapping") return "end of map flow not found";
  if (context == "while parsing a flow sequence") return "end of sequence flow not found";
  return context.empty() ? problem : problem + " (" + context + ")";
}

// Turns the event stream into nodes: a stack of open collections, whose children wait in one
// shared list until the collection ends and they are copied into the arena.
class YamlTreeBuilder {
 public:
  YamlTreeBuilder(const std::string& text, std::pmr::monotonic_buffer_resource& arena,
                  const std::string& name)
      : text_(text), arena_(arena), name_(name), cursor_(text) {}

  // The root node (a null node for a text without any).
  const YamlNodeData* build() {
    Parser p;
    const std::string& text = text_;
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
      void* at = arena_.allocate(sizeof(YamlNodeData), alignof(YamlNodeData));
      root_ = new (at) YamlNodeData;
    }
    return root_;
  }

 private:
  [[noreturn]] void fail(YamlMark m, const std::string& message) const {
    throw SceneError(name_, m.line + 1, m.column + 1, message);
  }

  [[noreturn]] void fail_syntax(const yaml_parser_t& p) const {
    const std::string& text = text_;
    if (p.error == YAML_MEMORY_ERROR) throw std::bad_alloc();
    if (p.error == YAML_READER_ERROR)  // the text was made valid UTF-8: not expected
      throw SceneError(name_, 0, 0, p.problem ? p.problem : "unreadable text");
    ByteCursor cursor(text);
    const YamlMark m = byte_mark(cursor, p.problem_mark);
    fail(m, syntax_message(p, text, cursor.offset(p.problem_mark.line, p.problem_mark.column)));
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

  // The 0-based line and byte column of a libyaml mark.
  static YamlMark byte_mark(ByteCursor& cursor, const yaml_mark_t& m) {
    const std::size_t at = cursor.offset(m.line, m.column);
    const std::size_t column = at == std::string::npos ? m.column : at - cursor.line_start();
    return {static_cast<int>(m.line), static_cast<int>(column)};
  }

  YamlNodeData* new_node(const yaml_event_t& e, YamlType type) {
    void* at = arena_.allocate(sizeof(YamlNodeData), alignof(YamlNodeData));
    auto* node = new (at) YamlNodeData;
    node->type = type;
    const YamlMark m = byte_mark(cursor_, e.start_mark);
    node->line = m.line;
    node->column = m.column;
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
    const std::string& text = text_;
    const std::size_t at = cursor_.offset(e.start_mark.line, e.start_mark.column);
    // A plain scalar on one line is its own text: viewed, not copied. When as many characters
    // separate its ends as it has bytes, it is one line of ASCII: no comparison needed.
    const bool one_ascii_line =
        e.end_mark.line == e.start_mark.line && e.end_mark.column - e.start_mark.column == s.length;
    if (plain && at != std::string::npos && s.length <= text.size() - at &&
        (one_ascii_line || std::memcmp(text.data() + at, value, s.length) == 0)) {
      node->items = text.data() + at;
    } else {
      char* copy = static_cast<char*>(arena_.allocate(s.length + 1, 1));
      std::memcpy(copy, value, s.length);
      copy[s.length] = '\0';
      node->items = copy;
    }
    return node;
  }

  const YamlNodeData* alias(const yaml_event_t& e) {
    const auto it = anchors_.find(reinterpret_cast<const char*>(e.data.alias.anchor));
    if (it == anchors_.end())
      fail(byte_mark(cursor_, e.start_mark), "the referenced anchor is not defined");
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
      void* at = arena_.allocate(count * sizeof(YamlNodeData*), alignof(YamlNodeData*));
      auto* entries = static_cast<const YamlNodeData**>(at);
      std::copy(children, children + count, entries);
      c.node->items = entries;
      c.node->size = static_cast<std::uint32_t>(count);
    } else {
      const std::size_t pairs = count / 2;
      void* at = arena_.allocate(pairs * sizeof(YamlPair), alignof(YamlPair));
      auto* out = static_cast<YamlPair*>(at);
      for (std::size_t i = 0; i < pairs; ++i)
        new (out + i) YamlPair{children[2 * i], children[2 * i + 1]};
      c.node->items = out;
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

  const std::string& text_;
  std::pmr::monotonic_buffer_resource& arena_;
  const std::string& name_;
  ByteCursor cursor_;
  const YamlNodeData* root_ = nullptr;
  std::vector<OpenCollection> open_;
  std::vector<const YamlNodeData*> pending_;
  std::unordered_map<std::string, const YamlNodeData*> anchors_;
};

// The arena's memory: large blocks aligned to huge pages and advised to use them
// (io/huge_pages.h), small ones from the heap.
class HugePageBlocks : public std::pmr::memory_resource {
  static bool large(std::size_t bytes, std::size_t alignment) {
    return bytes >= 2 * kHugePageBytes && alignment <= kHugePageBytes;
  }
  static std::size_t rounded(std::size_t bytes) {
    return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  }

  void* do_allocate(std::size_t bytes, std::size_t alignment) override {
    if (!large(bytes, alignment))
      return std::pmr::new_delete_resource()->allocate(bytes, alignment);
    void* p = std::aligned_alloc(kHugePageBytes, rounded(bytes));
    if (!p) throw std::bad_alloc();
    advise_huge_pages(p, rounded(bytes));
    return p;
  }
  void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    if (!large(bytes, alignment))
      return std::pmr::new_delete_resource()->deallocate(p, bytes, alignment);
    std::free(p);
  }
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }
};

std::pmr::memory_resource* huge_page_blocks() {
  static HugePageBlocks blocks;
  return &blocks;
}

}  // namespace

YamlDocument build_yaml_document(std::string text, const std::string& name) {
  YamlDocument doc;
  doc.text_ = std::make_unique<std::string>(with_replacement_characters(std::move(text)));
  // Sized to the text: a scene needs about five times its text in nodes.
  doc.arena_ = std::make_unique<std::pmr::monotonic_buffer_resource>(
      std::max<std::size_t>(4096, doc.text_->size()), huge_page_blocks());
  doc.root_ = YamlTreeBuilder(*doc.text_, *doc.arena_, name).build();
  return doc;
}

}  // namespace raycast
