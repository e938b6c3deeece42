#pragma once
// The POV-Ray scene language's tokens with their positions: numbers, words (keywords and
// identifiers), strings, `#` directives and symbols. Comments (`//` to the end of the line,
// `/* */`, nested) are skipped. The lexer reads one file's text from a cursor that can be saved
// and restored: #while loops and macros re-read their text from a saved cursor, as POV-Ray does.
#include <cstddef>
#include <string>
#include <string_view>

#include "pov/source.h"

namespace raycast::pov {

struct Token {
  enum Kind : unsigned char { End, Number, Word, String, Directive, Symbol };
  Kind kind = End;
  std::string text;  // the word, the string's contents, the directive's name, or the symbol
  double number = 0;
  Pos pos;
};

/// A place in one file's text: the byte offset and its 1-based line and column.
struct Cursor {
  std::size_t offset = 0;
  int line = 1, column = 1;
};

/// Reads the token at `c` in `text` (file index `file` in `sources`) and moves `c` past it;
/// an End token at the end of the text. Throws SceneError on an unterminated comment or string,
/// an out-of-range number or a stray character.
Token read_token(std::string_view text, int file, const Sources& sources, Cursor& c);

/// True when `t` is the one- or two-character symbol `s`. Compared here, inline: the expression
/// parser asks this of every operator at every precedence level.
inline bool is_symbol(const Token& t, std::string_view s) {
  if (t.kind != Token::Symbol || t.text.size() != s.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i)  // a byte or two: no call to memcmp
    if (t.text[i] != s[i]) return false;
  return true;
}

}  // namespace raycast::pov
