#pragma once
// Line and column bookkeeping for the text readers of the volume layer.
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include "volume/volume_error.h"

namespace raycast::volume_detail {

/// The whole file as bytes; throws VolumeFileError (line 0) when it cannot be read.
inline std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw VolumeFileError(path, 1, 1, "cannot open the file");
  std::string s((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) throw VolumeFileError(path, 1, 1, "cannot read the file");
  return s;
}

/// One token of a line with its 1-based column.
struct Token {
  std::string_view text;
  int column = 0;
};

/// Splits a line at the delimiter (',' for CSV) or at runs of blanks (delim == 0).
template <class Out>
void split(std::string_view line, char delim, Out& out) {
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  if (delim == 0) {
    while (i < line.size()) {
      while (i < line.size() && blank(line[i])) ++i;
      if (i >= line.size()) break;
      const std::size_t b = i;
      while (i < line.size() && !blank(line[i])) ++i;
      out.push_back({line.substr(b, i - b), int(b) + 1});
    }
    return;
  }
  for (;;) {
    std::size_t e = line.find(delim, i);
    if (e == std::string_view::npos) e = line.size();
    std::size_t b = i, end = e;
    while (b < end && blank(line[b])) ++b;
    while (end > b && blank(line[end - 1])) --end;
    out.push_back({line.substr(b, end - b), int(b) + 1});
    if (e == line.size()) break;
    i = e + 1;
  }
}

/// Parses a whole token as a double; false when it is not a number.
inline bool parse_double(std::string_view s, double& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && !s.empty();
}

}  // namespace raycast::volume_detail
