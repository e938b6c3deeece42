#include "volume/particle_file.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <vector>

#include "io/ply.h"
#include "volume/text_cursor.h"

namespace raycast {

using volume_detail::parse_double;
using volume_detail::read_all;
using volume_detail::split;
using volume_detail::Token;

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Iterates the lines of a text with their 1-based numbers.
struct Lines {
  std::string_view text;
  std::size_t pos = 0;
  int number = 0;
  bool next(std::string_view& line) {
    if (pos >= text.size()) return false;
    std::size_t e = text.find('\n', pos);
    if (e == std::string_view::npos) e = text.size();
    line = text.substr(pos, e - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = e + 1;
    ++number;
    return true;
  }
};

double finite_value(const std::string& path, int line, const Token& t, const char* what) {
  double v;
  if (!parse_double(t.text, v))
    throw VolumeFileError(
        path, line, t.column,
        std::string(what) + " must be a number, got '" + std::string(t.text) + "'");
  if (!std::isfinite(v))
    throw VolumeFileError(path, line, t.column,
                          std::string(what) + " must be finite, got '" + std::string(t.text) + "'");
  return v;
}

// CSV (delim ',') and .xyz (delim 0).
std::vector<Vec3> read_text(const std::string& path, const std::string& text, char delim) {
  std::vector<Vec3> out;
  Lines lines{text};
  std::string_view line;
  int col[3] = {0, 1, 2};
  bool first = true;
  std::vector<Token> tokens;
  static const char* kAxis[3] = {"x", "y", "z"};
  while (lines.next(line)) {
    tokens.clear();
    split(line, delim, tokens);
    if (tokens.empty() || (tokens.size() == 1 && tokens[0].text.empty())) continue;
    if (tokens[0].text.size() > 0 && tokens[0].text[0] == '#') continue;
    double probe;
    if (first && !parse_double(tokens[0].text, probe)) {  // a header
      first = false;
      int found = 0;
      for (int a = 0; a < 3; ++a)
        for (std::size_t i = 0; i < tokens.size(); ++i) {
          std::string name = lower(std::string(tokens[i].text));
          name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
          if (name == kAxis[a]) {
            col[a] = int(i);
            ++found;
            break;
          }
        }
      if (found != 3) col[0] = 0, col[1] = 1, col[2] = 2;
      continue;
    }
    first = false;
    const int need = std::max({col[0], col[1], col[2]}) + 1;
    if (int(tokens.size()) < need) {
      const int end = int(line.size()) + 1;
      throw VolumeFileError(path, lines.number, end,
                            "expected " + std::to_string(need) + " values (x y z), found " +
                                std::to_string(tokens.size()));
    }
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = finite_value(path, lines.number, tokens[col[a]], kAxis[a]);
    out.push_back(p);
  }
  if (out.empty())
    throw VolumeFileError(path, std::max(lines.number, 1), 1, "no particles in the file");
  return out;
}

const char* const kPlyAxis[3] = {"x", "y", "z"};

// Where the particles are in a PLY file: the vertex element and its x, y, z properties.
struct PlyVertices {
  int element = -1;
  int xyz[3] = {-1, -1, -1};
};

PlyVertices find_vertices(const std::string& path, const ply::Header& header) {
  PlyVertices v;
  const std::vector<ply::Element>& elements = header.elements;
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].name == "vertex") v.element = int(e);
  if (v.element < 0) throw VolumeFileError(path, 2, 1, "the PLY file has no vertex element");
  const ply::Element& ve = elements[std::size_t(v.element)];
  for (std::size_t i = 0; i < ve.props.size(); ++i)
    for (int a = 0; a < 3; ++a)
      if (!ve.props[i].is_list() && ve.props[i].name == std::string(1, char('x' + a)))
        v.xyz[a] = int(i);
  if (v.xyz[0] < 0 || v.xyz[1] < 0 || v.xyz[2] < 0)
    throw VolumeFileError(path, ve.line, 1, "the PLY vertex element has no x, y and z properties");
  if (ve.count == 0)
    throw VolumeFileError(path, ve.line, 1, "no particles in the file (0 vertices)");
  return v;
}

// The particles of an ASCII PLY body (`lines` just after the header); elements before the
// vertices are skipped line by line.
std::vector<Vec3> read_ply_ascii(const std::string& path, const std::string& text,
                                 const ply::Header& header, const PlyVertices& v, Lines& lines) {
  const int body_line = lines.number + 1;
  const ply::Element& ve = header.elements[std::size_t(v.element)];
  std::string_view line;
  std::uint64_t skip = 0;
  for (int e = 0; e < v.element; ++e) skip += header.elements[std::size_t(e)].count;
  for (std::uint64_t i = 0; i < skip; ++i)
    if (!lines.next(line))
      throw VolumeFileError(path, lines.number + 1, 1, "truncated PLY file (data ends early)");
  if (ve.count > text.size() - std::min(lines.pos, text.size()))
    throw VolumeFileError(path, body_line, 1,
                          "truncated PLY file: " + std::to_string(ve.count) +
                              " vertices cannot fit in the bytes left");
  std::vector<Vec3> out;
  out.reserve(ve.count);
  std::vector<Token> tok;
  for (std::uint64_t i = 0; i < ve.count; ++i) {
    if (!lines.next(line))
      throw VolumeFileError(path, lines.number + 1, 1,
                            "truncated PLY file: vertex " + std::to_string(i) + " of " +
                                std::to_string(ve.count) + " is missing");
    tok.clear();
    split(line, 0, tok);
    if (tok.size() < ve.props.size())
      throw VolumeFileError(path, lines.number, int(line.size()) + 1,
                            "expected " + std::to_string(ve.props.size()) +
                                " vertex values, found " + std::to_string(tok.size()));
    Vec3 p;
    for (int a = 0; a < 3; ++a)
      p[a] = finite_value(path, lines.number, tok[std::size_t(v.xyz[a])], kPlyAxis[a]);
    out.push_back(p);
  }
  return out;
}

// A binary PLY body, read from byte `at` (just after the header) with bounds checks on every
// read; errors name `body_line`, the first line after the header.
class PlyBinaryBody {
 public:
  PlyBinaryBody(const std::string& path, const std::string& text, std::uint64_t at, bool big,
                int body_line)
      : path_(path),
        data_(reinterpret_cast<const unsigned char*>(text.data())),
        size_(text.size()),
        at_(std::min<std::uint64_t>(at, text.size())),
        big_(big),
        body_line_(body_line) {}

  // The vertices of element `ve`, whose properties all have fixed sizes (`stride` bytes).
  std::vector<Vec3> fixed_vertices(const ply::Element& ve, const PlyVertices& v,
                                   std::uint64_t stride) {
    if (stride != 0 && ve.count > (size_ - at_) / stride)
      throw truncated(std::to_string(ve.count) + " vertices of " + std::to_string(stride) +
                      " bytes need " + std::to_string(ve.count * stride) + " bytes after byte " +
                      std::to_string(at_));
    std::uint64_t off[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < v.xyz[a]; ++i)
        off[a] += std::uint64_t(ply::type_size(ve.props[std::size_t(i)].type));
    std::vector<Vec3> out(ve.count);
    for (std::uint64_t i = 0; i < ve.count; ++i, at_ += stride)
      for (int a = 0; a < 3; ++a) {
        out[i][a] =
            ply::read_value(data_ + at_ + off[a], ve.props[std::size_t(v.xyz[a])].type, big_);
        if (!std::isfinite(out[i][a]))
          throw VolumeFileError(path_, body_line_, 1,
                                "vertex " + std::to_string(i) + " has a " + kPlyAxis[a] +
                                    " that is not finite (at byte " + std::to_string(at_ + off[a]) +
                                    ")");
      }
    return out;
  }

  // Element `el` read value by value (lists included); its points appended to `out` when
  // `xyz` is given (the vertex element), skipped otherwise.
  void element(const ply::Element& el, const int* xyz, std::vector<Vec3>& out) {
    for (std::uint64_t i = 0; i < el.count; ++i) {
      Vec3 p;
      for (std::size_t k = 0; k < el.props.size(); ++k) {
        const ply::Property& q = el.props[k];
        const std::uint64_t bytes = values(el, q) * std::uint64_t(ply::type_size(q.type));
        if (size_ - at_ < bytes) throw truncated("element " + el.name + " ends early");
        if (xyz && !q.is_list())
          for (int a = 0; a < 3; ++a)
            if (xyz[a] == int(k)) p[a] = ply::read_value(data_ + at_, q.type, big_);
        at_ += bytes;
      }
      if (!xyz) continue;
      if (!is_finite(p))
        throw VolumeFileError(path_, body_line_, 1,
                              "vertex " + std::to_string(i) + " is not finite");
      out.push_back(p);
    }
  }

 private:
  // How many values property q holds here: 1, or a list's count (read and stepped over).
  std::uint64_t values(const ply::Element& el, const ply::Property& q) {
    if (!q.is_list()) return 1;
    const int cs = ply::type_size(q.count_type);
    if (size_ - at_ < std::uint64_t(cs)) throw truncated("element " + el.name + " ends early");
    const double c = ply::read_value(data_ + at_, q.count_type, big_);
    if (!(c >= 0))
      throw VolumeFileError(path_, body_line_, 1,
                            "a negative PLY list count at byte " + std::to_string(at_));
    at_ += std::uint64_t(cs);
    return std::uint64_t(c);
  }
  VolumeFileError truncated(const std::string& what) const {
    return VolumeFileError(
        path_, body_line_, 1,
        "truncated PLY file: " + what + " (the file has " + std::to_string(size_) + " bytes)");
  }

  const std::string& path_;
  const unsigned char* data_;
  std::uint64_t size_, at_;
  bool big_;
  int body_line_;
};

std::vector<Vec3> read_ply(const std::string& path, const std::string& text) {
  ply::Header header;
  try {
    header = ply::parse_header(text);
  } catch (const ply::HeaderError& e) {
    throw VolumeFileError(path, e.line(), e.column(), e.what());
  }
  const PlyVertices v = find_vertices(path, header);
  Lines lines{text, header.bytes, header.lines};
  if (header.format == ply::Format::kAscii) return read_ply_ascii(path, text, header, v, lines);
  PlyBinaryBody body(path, text, lines.pos, header.format != ply::Format::kBinaryLittleEndian,
                     lines.number + 1);
  std::vector<Vec3> out;
  for (int e = 0; e <= v.element; ++e) {
    const ply::Element& el = header.elements[std::size_t(e)];
    bool fixed = true;
    std::uint64_t stride = 0;
    for (const ply::Property& q : el.props) {
      if (q.is_list()) fixed = false;
      stride += std::uint64_t(ply::type_size(q.type));
    }
    if (e == v.element && fixed) return body.fixed_vertices(el, v, stride);
    body.element(el, e == v.element ? v.xyz : nullptr, out);
  }
  return out;
}

}  // namespace

bool particle_format_supported(const std::string& extension) {
  const std::string e = lower(extension);
  return e == ".ply" || e == ".csv" || e == ".xyz";
}

std::vector<Vec3> read_particles(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (!particle_format_supported(ext))
    throw VolumeFileError(path, 1, 1,
                          "unknown particle format '" + ext + "' (expected .ply, .csv or .xyz)");
  const std::string text = read_all(path);
  if (ext == ".ply") return read_ply(path, text);
  return read_text(path, text, ext == ".csv" ? ',' : 0);
}

}  // namespace raycast
