#include "pov/lexer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace raycast::pov {

namespace {

bool is_word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr int kMaxCommentNesting = 256;

class Reader {
 public:
  Reader(std::string_view text, int file, const Sources& sources, Cursor& c)
      : t_(text), file_(file), sources_(sources), c_(c) {}

  char peek(std::size_t ahead = 0) const {
    return c_.offset + ahead < t_.size() ? t_[c_.offset + ahead] : '\0';
  }
  bool at_end() const { return c_.offset >= t_.size(); }
  void advance() {
    if (at_end()) return;
    if (t_[c_.offset] == '\n') {
      ++c_.line;
      c_.column = 1;
    } else {
      ++c_.column;
    }
    ++c_.offset;
  }
  Pos here() const { return {file_, c_.line, c_.column}; }
  [[noreturn]] void error(const Pos& p, const std::string& m) const { fail(sources_, p, m); }

  void skip_space_and_comments() {
    for (;;) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '/' && peek(1) == '/') {
        while (!at_end() && peek() != '\n') advance();
      } else if (c == '/' && peek(1) == '*') {
        block_comment();
      } else {
        return;
      }
    }
  }

  Token number(Pos start) {
    const std::size_t begin = c_.offset;
    while (is_digit(peek())) advance();
    if (peek() == '.') {
      advance();
      while (is_digit(peek())) advance();
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      advance();
      if (peek() == '+' || peek() == '-') advance();
      while (is_digit(peek())) advance();
    }
    Token t;
    t.kind = Token::Number;
    t.pos = start;
    const std::string_view s = t_.substr(begin, c_.offset - begin);
    t.text = std::string(s);
    t.number = std::strtod(t.text.c_str(), nullptr);
    if (!std::isfinite(t.number))
      error(start, "number '" + t.text + "' is out of range (not a finite double)");
    return t;
  }

  Token string(Pos start) {
    advance();
    Token t;
    t.kind = Token::String;
    t.pos = start;
    while (peek() != '"') {
      if (at_end()) error(start, "unterminated string: '\"' is never closed");
      if (peek() == '\\') {
        advance();
        if (at_end()) break;
        const char e = peek();
        switch (e) {
          case 'n':
            t.text += '\n';
            break;
          case 't':
            t.text += '\t';
            break;
          case 'r':
            t.text += '\r';
            break;
          case 'a':
            t.text += '\a';
            break;
          case '\\':
          case '"':
          case '\'':
            t.text += e;
            break;
          default:
            t.text += '\\';
            t.text += e;  // kept as written (Windows paths)
        }
        advance();
        continue;
      }
      t.text += peek();
      advance();
    }
    advance();
    return t;
  }

 private:
  void block_comment() {
    const Pos start = here();
    int depth = 0;
    do {
      if (at_end()) error(start, "unterminated comment: '/*' is never closed");
      if (peek() == '/' && peek(1) == '*') {
        if (++depth > kMaxCommentNesting) error(here(), "comments are nested deeper than 256");
        advance();
        advance();
      } else if (peek() == '*' && peek(1) == '/') {
        --depth;
        advance();
        advance();
      } else {
        advance();
      }
    } while (depth > 0);
  }

  std::string_view t_;
  int file_;
  const Sources& sources_;
  Cursor& c_;
};

}  // namespace

Token read_token(std::string_view text, int file, const Sources& sources, Cursor& cursor) {
  Reader r(text, file, sources, cursor);
  r.skip_space_and_comments();
  // A '#' with no directive name after it is skipped, as POV-Ray does.
  while (r.peek() == '#') {
    Cursor after = cursor;
    Reader look(text, file, sources, after);
    look.advance();
    look.skip_space_and_comments();
    const char c = look.peek();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') break;
    cursor = after;
  }
  Token t;
  t.pos = r.here();
  if (r.at_end()) return t;
  const char c = r.peek();
  if (is_digit(c) || (c == '.' && is_digit(r.peek(1)))) return r.number(t.pos);
  if (is_word_start(c)) {
    const std::size_t begin = cursor.offset;
    while (is_word_char(r.peek())) r.advance();
    t.kind = Token::Word;
    t.text = std::string(text.substr(begin, cursor.offset - begin));
    return t;
  }
  if (c == '#') {
    r.advance();
    r.skip_space_and_comments();  // POV-Ray allows "# declare", even across lines
    const std::size_t begin = cursor.offset;
    while (is_word_char(r.peek())) r.advance();
    if (begin == cursor.offset) r.error(t.pos, "'#' must be followed by a directive name");
    t.kind = Token::Directive;
    t.text = std::string(text.substr(begin, cursor.offset - begin));
    return t;
  }
  if (c == '"') return r.string(t.pos);
  static constexpr std::string_view kSymbols = "{}<>()[],;:+-*/=?!&|.";
  if (kSymbols.find(c) != std::string_view::npos) {
    r.advance();
    t.kind = Token::Symbol;
    t.text = std::string(1, c);
    if ((c == '<' || c == '>' || c == '!') && r.peek() == '=') {
      r.advance();
      t.text += '=';
    }
    return t;
  }
  const std::string shown =
      std::isprint(static_cast<unsigned char>(c))
          ? std::string(1, c)
          : std::string("\\x") + "0123456789abcdef"[(c >> 4) & 15] + "0123456789abcdef"[c & 15];
  r.error(t.pos, "unexpected character '" + shown + "'");
}

}  // namespace raycast::pov
