#pragma once
// Line and word bookkeeping for the text file readers (OBJ, ASCII STL and PLY): 1-based line
// numbers and columns for positioned errors, numbers parsed with from_chars (no locale, no copy).
#include <charconv>
#include <cstdint>
#include <string_view>
#include <system_error>
#include <vector>

namespace raycast::text {

/// One blank-separated word of a line with its 1-based column.
struct Word {
  std::string_view text;
  int column = 0;
};

/// The lines of a text, each without its "\n" or "\r\n", with their 1-based numbers.
class Lines {
 public:
  explicit Lines(std::string_view text, std::size_t start = 0, int first_number = 1)
      : text_(text), pos_(start), number_(first_number - 1) {}
  /// The next line; false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t e = text_.find('\n', pos_);
    if (e == std::string_view::npos) e = text_.size();
    line = text_.substr(pos_, e - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = e + 1;
    ++number_;
    return true;
  }
  /// The number of the line last returned by next().
  int number() const { return number_; }
  /// Bytes not yet read.
  std::size_t remaining() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }

 private:
  std::string_view text_;
  std::size_t pos_;
  int number_;
};

/// Splits a line at runs of blanks (spaces, tabs) into `out` (cleared first).
inline void split_words(std::string_view line, std::vector<Word>& out) {
  out.clear();
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    if (i >= line.size()) break;
    const std::size_t b = i;
    while (i < line.size() && !blank(line[i])) ++i;
    out.push_back({line.substr(b, i - b), static_cast<int>(b) + 1});
  }
}

/// The whole word as a number (a leading '+' allowed, "nan" and "inf" accepted as from_chars
/// reads them); false when it is not one.
inline bool parse_number(std::string_view s, double& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

/// The whole word as a finite number; false for anything else (NaN and infinities included).
inline bool parse_finite(std::string_view s, double& v) {
  return parse_number(s, v) && v - v == 0;  // v - v is NaN for NaN and the infinities
}

/// The whole word as a signed integer; false when it is not one (or out of range).
inline bool parse_integer(std::string_view s, std::int64_t& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace raycast::text
