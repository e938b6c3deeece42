#pragma once
// The POV-Ray scene language's tokens with their positions: numbers, words (keywords and
// identifiers), strings, `#` directives and one-character symbols. Comments (`//` to the end of
// the line, `/* */`, nested) are skipped.
#include <string>
#include <string_view>

#include "pov/source.h"

namespace raycast::pov {

struct Token {
  enum Kind { End, Number, Word, String, Directive, Symbol };
  Kind kind = End;
  std::string text;  // the word, the string's contents, the directive's name, or the symbol
  double number = 0;
  Pos pos;
};

class Lexer {
 public:
  /// `text` must outlive the lexer; `file` is its index in `sources`.
  Lexer(std::string_view text, int file, const Sources& sources)
      : text_(text), file_(file), sources_(sources) {}
  /// The next token; End at the end of the text (and ever after). Throws SceneError on an
  /// unterminated comment or string, a malformed or out-of-range number, or a stray character.
  Token next();

 private:
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  void advance();
  void skip_space_and_comments();
  Pos here() const { return {file_, line_, column_}; }
  Token number(Pos start);

  std::string_view text_;
  int file_;
  const Sources& sources_;
  std::size_t pos_ = 0;
  int line_ = 1, column_ = 1;
};

}  // namespace raycast::pov
