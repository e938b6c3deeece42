#include "io/ply.h"

#include <algorithm>
#include <charconv>

#include "io/text_lines.h"

namespace raycast::ply {

namespace {

Type checked_type(const text::Word& w, int line) {
  const Type t = type_named(w.text);
  if (t == Type::kNone)
    throw HeaderError(line, w.column, "unknown PLY type '" + std::string(w.text) + "'");
  return t;
}

}  // namespace

Type type_named(std::string_view s) {
  if (s == "char" || s == "int8") return Type::kI8;
  if (s == "uchar" || s == "uint8") return Type::kU8;
  if (s == "short" || s == "int16") return Type::kI16;
  if (s == "ushort" || s == "uint16") return Type::kU16;
  if (s == "int" || s == "int32") return Type::kI32;
  if (s == "uint" || s == "uint32") return Type::kU32;
  if (s == "float" || s == "float32") return Type::kF32;
  if (s == "double" || s == "float64") return Type::kF64;
  return Type::kNone;
}

int type_size(Type t) {
  switch (t) {
    case Type::kI8:
    case Type::kU8:
      return 1;
    case Type::kI16:
    case Type::kU16:
      return 2;
    case Type::kI32:
    case Type::kU32:
    case Type::kF32:
      return 4;
    case Type::kF64:
      return 8;
    default:
      return 0;
  }
}

Header parse_header(std::string_view file) {
  constexpr std::size_t kMaxHeader = std::size_t{1} << 20;  // far beyond any real header
  const std::string_view head = file.substr(0, std::min(file.size(), kMaxHeader));
  Header h;
  bool have_format = false;
  std::vector<text::Word> w;
  std::size_t pos = 0;
  for (int n = 1;; ++n) {
    const std::size_t eol = head.find('\n', pos);
    if (eol == std::string_view::npos) {
      if (n == 1 && head.substr(0, 3) != "ply")
        throw HeaderError(1, 1, "not a PLY file (the first line must be 'ply')");
      throw HeaderError(std::max(n - 1, 1), 1,
                        file.size() > kMaxHeader ? "PLY header longer than 1 MiB"
                                                 : "truncated PLY header (no end_header line)");
    }
    std::string_view line = head.substr(pos, eol - pos);
    pos = eol + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (n == 1) {
      if (line != "ply") throw HeaderError(1, 1, "not a PLY file (the first line must be 'ply')");
      continue;
    }
    text::split_words(line, w);
    if (w.empty()) continue;
    const std::string_view key = w[0].text;
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      if (w.size() > 1) throw HeaderError(n, w[1].column, "text after end_header");
      if (!have_format) throw HeaderError(2, 1, "the PLY header has no format line");
      h.bytes = pos;
      h.lines = n;
      return h;
    }
    if (key == "format") {
      if (w.size() != 3)
        throw HeaderError(n, 1,
                          "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      const std::string_view k = w[1].text;
      if (k == "ascii")
        h.format = Format::kAscii;
      else if (k == "binary_little_endian")
        h.format = Format::kBinaryLittleEndian;
      else if (k == "binary_big_endian")
        h.format = Format::kBinaryBigEndian;
      else
        throw HeaderError(n, w[1].column,
                          "unknown PLY format '" + std::string(k) +
                              "' (expected ascii, binary_little_endian or binary_big_endian)");
      have_format = true;
    } else if (key == "element") {
      if (w.size() != 3) throw HeaderError(n, 1, "expected 'element NAME COUNT'");
      Element e;
      e.name = std::string(w[1].text);
      e.line = n;
      const std::string_view c = w[2].text;
      const auto r = std::from_chars(c.data(), c.data() + c.size(), e.count);
      if (r.ec != std::errc() || r.ptr != c.data() + c.size())
        throw HeaderError(
            n, w[2].column,
            "element count must be a whole number >= 0 below 2^64, got '" + std::string(c) + "'");
      h.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (h.elements.empty()) throw HeaderError(n, 1, "a property before any element");
      Property p;
      if (w.size() >= 2 && w[1].text == "list") {
        if (w.size() != 5) throw HeaderError(n, 1, "expected 'property list COUNT_TYPE TYPE NAME'");
        p.count_type = checked_type(w[2], n);
        p.type = checked_type(w[3], n);
        p.name = std::string(w[4].text);
      } else {
        if (w.size() != 3) throw HeaderError(n, 1, "expected 'property TYPE NAME'");
        p.type = checked_type(w[1], n);
        p.name = std::string(w[2].text);
      }
      h.elements.back().props.push_back(std::move(p));
    } else {
      throw HeaderError(n, w[0].column,
                        "unexpected PLY header line starting with '" + std::string(key) + "'");
    }
  }
}

}  // namespace raycast::ply
