#include "load/yaml_prescan.h"

#include <vector>

#include "io/scene_error.h"
#include "load/yaml_tree_builder.h"

namespace raycast {
namespace {

// The readers of the nodes recurse per level, so text nested deeper than max_nesting is rejected
// before parsing, at the position of the first level too deep. Flow collections
// ([, {) count one level each; block collections one level per indentation step and per inline
// `- ` item. Quoted scalars, block scalars (| and >) and comments are skipped.
struct FlowOpen {
  int line, column;
  char bracket;
};

// Characters that never start or end anything the scan follows (quotes, brackets, comments,
// block indicators, `- ` items and `:`): letters, digits, '.' and '_'.
bool is_word_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_';
}

// Returns the first `[` or `{` left open at the end of the text (bracket 0 when all closed).
FlowOpen check_nesting(const std::string& text, const std::string& name, int max_nesting) {
  const std::string too_deep =
      "the YAML is nested deeper than " + std::to_string(max_nesting) + " levels";
  std::vector<std::size_t> indents;               // block indentation levels open at this line
  std::vector<FlowOpen> open;                     // open [ and { around the current character
  char quote = 0;                                 // the open quote character, or 0
  std::size_t scalar_indent = std::string::npos;  // inside a block scalar: its parent's indent
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const std::size_t line_start = i;
    std::size_t block = indents.size(), indent = 0;
    if (open.empty() && quote == 0) {
      // A block line: its indentation and leading `- ` items.
      std::size_t j = i;
      while (j < n && text[j] == ' ') ++j;
      indent = j - i;
      const bool blank = j == n || text[j] == '\n' || text[j] == '\r';
      if (scalar_indent != std::string::npos && (blank || indent > scalar_indent)) {
        while (i < n && text[i] != '\n') ++i;  // block scalar content: plain text
        if (i < n) ++i;
        ++line;
        continue;
      }
      scalar_indent = std::string::npos;
      if (!blank && text[j] != '#') {
        while (!indents.empty() && indents.back() > indent) indents.pop_back();
        if (indents.empty() || indents.back() < indent) indents.push_back(indent);
        block = indents.size();
        while (j + 1 < n && text[j] == '-' && (text[j + 1] == ' ' || text[j + 1] == '\n')) {
          ++block;
          if (block > static_cast<std::size_t>(max_nesting))
            throw SceneError(name, line, static_cast<int>(j - line_start) + 1, too_deep);
          j += 2;
          while (j < n && text[j] == ' ') ++j;
        }
        if (block > static_cast<std::size_t>(max_nesting))
          throw SceneError(name, line, static_cast<int>(indent) + 1, too_deep);
      }
    }
    char prev = '\n';     // previous non-blank character on this line ('\n' at its start)
    char last_token = 0;  // first character of the line's last token
    bool after_blank = true;
    for (; i < n && text[i] != '\n'; ++i) {
      const char c = text[i];
      if (!quote && is_word_character(c)) {
        // A run of letters and digits opens and closes nothing: only its last character counts
        // (as `prev`), and its first as a token's start.
        if (after_blank) last_token = c;
        after_blank = false;
        while (i + 1 < n && is_word_character(text[i + 1])) ++i;
        prev = text[i];
        continue;
      }
      if (quote) {
        if (c == '\\' && quote == '"')
          ++i;
        else if (c == quote)
          quote = 0;
        continue;
      }
      if (c == '#' && after_blank) {
        while (i < n && text[i] != '\n') ++i;
        break;
      }
      const bool token_start = !open.empty() || prev == '\n' ||
                               (after_blank && (prev == ':' || prev == '-' || prev == '?'));
      if ((c == '"' || c == '\'') && token_start) {
        quote = c;
      } else if ((c == '[' || c == '{') && token_start) {
        open.push_back({line, static_cast<int>(i - line_start) + 1, c});
        if (block + open.size() > static_cast<std::size_t>(max_nesting))
          throw SceneError(name, line, static_cast<int>(i - line_start) + 1, too_deep);
      } else if ((c == ']' || c == '}') && !open.empty()) {
        open.pop_back();
      }
      if (after_blank && c != ' ' && c != '\t') last_token = c;
      after_blank = c == ' ' || c == '\t';
      if (!after_blank) prev = c;
    }
    if (open.empty() && quote == 0 && (last_token == '|' || last_token == '>'))
      scalar_indent = indent;
    if (i < n) ++i;  // the newline
    ++line;
  }
  return open.empty() ? FlowOpen{0, 0, 0} : open.front();
}

}  // namespace

YamlDocument parse_yaml(std::string text, const std::string& name, int max_nesting) {
  const FlowOpen unclosed = check_nesting(text, name, max_nesting);
  try {
    return build_yaml_document(std::move(text), name);
  } catch (const SceneError& e) {
    // The parser notices a missing `}` or `]` only where the next token does not fit, often lines
    // later; the place the user must fix is where the collection opened.
    if (unclosed.bracket != 0)
      throw SceneError(name, unclosed.line, unclosed.column,
                       std::string("this '") + unclosed.bracket + "' is never closed (" +
                           e.message() + " at " + std::to_string(e.line()) + ":" +
                           std::to_string(e.column()) + ")");
    throw;
  }
}

}  // namespace raycast
