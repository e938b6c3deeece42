#pragma once
// The PLY format's header and value encodings, shared by the mesh reader (io/ply_file.cpp) and
// the particle reader (volume/particle_file.cpp). The header is read line by line as the format
// defines it: "ply", then format, comment, obj_info, element and property lines, up to a line
// "end_header".
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raycast::ply {

/// A malformed header, with the 1-based line and column of the mistake.
class HeaderError : public std::runtime_error {
 public:
  HeaderError(int line, int column, const std::string& message)
      : std::runtime_error(message), line_(line), column_(column) {}
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  int line_, column_;
};

enum class Type { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64, kNone };
enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

/// The type a header names ("float", "float32", "uchar", ...); kNone for anything else.
Type type_named(std::string_view name);
/// Bytes of one value in the binary formats (0 for kNone).
int type_size(Type t);

/// One value of type `t` stored at `p` in the given byte order, as a double.
inline double read_value(const unsigned char* p, Type t, bool big_endian) {
  unsigned char b[8] = {};
  const int n = type_size(t);
  for (int i = 0; i < n; ++i) b[i] = big_endian ? p[n - 1 - i] : p[i];
  switch (t) {
    case Type::kI8:
      return static_cast<std::int8_t>(b[0]);
    case Type::kU8:
      return b[0];
    case Type::kI16: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Type::kU16: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Type::kI32: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Type::kU32: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Type::kF32: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Type::kF64: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
    default:
      return 0;
  }
}

struct Property {
  std::string name;
  Type type = Type::kNone;        // the value's type (a list's items)
  Type count_type = Type::kNone;  // a list's count; kNone for a plain property
  bool is_list() const { return count_type != Type::kNone; }
};

struct Element {
  std::string name;
  std::uint64_t count = 0;  // as written (up to 2^64 - 1): readers check it against the bytes left
  int line = 0;             // where the element was declared
  std::vector<Property> props;
};

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;
  std::size_t bytes = 0;  // the header's length, through the newline after end_header
  int lines = 0;          // its number of lines (the body starts on line `lines + 1`)
};

/// Reads the header at the start of `file`. Throws HeaderError for anything malformed: no "ply"
/// line, no end_header line (or a header over 1 MiB), no format line, an unknown keyword, format
/// or type, a property before any element, a count that is not a whole number, stray tokens.
Header parse_header(std::string_view file);

}  // namespace raycast::ply
