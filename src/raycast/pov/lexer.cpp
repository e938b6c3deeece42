#include "pov/lexer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace raycast::pov {

namespace {
bool is_word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
constexpr int kMaxCommentNesting = 256;
}  // namespace

void Lexer::advance() {
  if (pos_ >= text_.size()) return;
  if (text_[pos_] == '\n') {
    ++line_;
    column_ = 1;
  } else {
    ++column_;
  }
  ++pos_;
}

void Lexer::skip_space_and_comments() {
  for (;;) {
    const char c = peek();
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
      advance();
    } else if (c == '/' && peek(1) == '/') {
      while (pos_ < text_.size() && peek() != '\n') advance();
    } else if (c == '/' && peek(1) == '*') {
      const Pos start = here();
      int depth = 0;
      do {
        if (pos_ >= text_.size())
          fail(sources_, start, "unterminated comment: '/*' is never closed");
        if (peek() == '/' && peek(1) == '*') {
          if (++depth > kMaxCommentNesting)
            fail(sources_, here(), "comments are nested deeper than 256");
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
    } else {
      return;
    }
  }
}

Token Lexer::number(Pos start) {
  const std::size_t begin = pos_;
  while (is_digit(peek())) advance();
  if (peek() == '.') {
    advance();
    while (is_digit(peek())) advance();
  }
  if (peek() == 'e' || peek() == 'E') {
    advance();
    if (peek() == '+' || peek() == '-') advance();
    if (!is_digit(peek()))
      fail(sources_, start,
           "malformed number '" + std::string(text_.substr(begin, pos_ - begin)) +
               "': the exponent has no digits");
    while (is_digit(peek())) advance();
  }
  if (is_word_char(peek()) || peek() == '.')
    fail(sources_, start,
         "malformed number '" + std::string(text_.substr(begin, pos_ - begin + 1)) + "'");
  Token t;
  t.kind = Token::Number;
  t.pos = start;
  t.text = std::string(text_.substr(begin, pos_ - begin));
  if (t.text == ".") fail(sources_, start, "malformed number '.'");
  t.number = std::strtod(t.text.c_str(), nullptr);
  if (!std::isfinite(t.number))
    fail(sources_, start, "number '" + t.text + "' is out of range (not a finite double)");
  return t;
}

Token Lexer::next() {
  skip_space_and_comments();
  Token t;
  t.pos = here();
  if (pos_ >= text_.size()) return t;
  const char c = peek();
  if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return number(t.pos);
  if (is_word_start(c)) {
    const std::size_t begin = pos_;
    while (is_word_char(peek())) advance();
    t.kind = Token::Word;
    t.text = std::string(text_.substr(begin, pos_ - begin));
    return t;
  }
  if (c == '#') {
    advance();
    while (peek() == ' ' || peek() == '\t') advance();  // POV-Ray allows "# declare"
    const std::size_t begin = pos_;
    while (is_word_char(peek())) advance();
    if (begin == pos_) fail(sources_, t.pos, "'#' must be followed by a directive name");
    t.kind = Token::Directive;
    t.text = std::string(text_.substr(begin, pos_ - begin));
    return t;
  }
  if (c == '"') {
    advance();
    t.kind = Token::String;
    while (peek() != '"') {
      if (pos_ >= text_.size() || peek() == '\n')
        fail(sources_, t.pos, "unterminated string: '\"' is never closed on its line");
      if (peek() == '\\') {
        advance();
        if (pos_ >= text_.size()) break;
      }
      t.text += peek();
      advance();
    }
    advance();
    return t;
  }
  static const std::string_view symbols = "{}<>()[],;:+-*/=?!&|.";
  if (symbols.find(c) != std::string_view::npos) {
    advance();
    t.kind = Token::Symbol;
    t.text = std::string(1, c);
    return t;
  }
  std::string shown = std::isprint(static_cast<unsigned char>(c))
                          ? std::string(1, c)
                          : "\\x" + std::string(1, "0123456789abcdef"[(c >> 4) & 15]) +
                                std::string(1, "0123456789abcdef"[c & 15]);
  fail(sources_, t.pos, "unexpected character '" + shown + "'");
}

}  // namespace raycast::pov
