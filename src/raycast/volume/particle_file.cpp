#include "volume/particle_file.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <vector>

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

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64, kBad };

PlyType ply_type(std::string_view s) {
  if (s == "char" || s == "int8") return PlyType::kInt8;
  if (s == "uchar" || s == "uint8") return PlyType::kUint8;
  if (s == "short" || s == "int16") return PlyType::kInt16;
  if (s == "ushort" || s == "uint16") return PlyType::kUint16;
  if (s == "int" || s == "int32") return PlyType::kInt32;
  if (s == "uint" || s == "uint32") return PlyType::kUint32;
  if (s == "float" || s == "float32") return PlyType::kFloat32;
  if (s == "double" || s == "float64") return PlyType::kFloat64;
  return PlyType::kBad;
}

int ply_size(PlyType t) {
  switch (t) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    default:
      return 8;
  }
}

double ply_value(const unsigned char* p, PlyType t, bool big) {
  unsigned char b[8];
  const int n = ply_size(t);
  for (int i = 0; i < n; ++i) b[i] = big ? p[n - 1 - i] : p[i];
  switch (t) {
    case PlyType::kInt8:
      return double(static_cast<std::int8_t>(b[0]));
    case PlyType::kUint8:
      return double(b[0]);
    case PlyType::kInt16: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::kUint16: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::kInt32: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::kUint32: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::kFloat32: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
  }
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kBad;
  PlyType count_type = PlyType::kBad;  // lists only
  bool list = false;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  int line = 0;
  std::vector<PlyProperty> props;
};

std::vector<Vec3> read_ply(const std::string& path, const std::string& text) {
  Lines lines{text};
  std::string_view line;
  std::vector<Token> tok;
  if (!lines.next(line) || line != "ply")
    throw VolumeFileError(path, 1, 1, "not a PLY file (the first line must be 'ply')");
  int format = -1;  // 0 ascii, 1 binary little endian, 2 binary big endian
  std::vector<PlyElement> elements;
  bool ended = false;
  while (lines.next(line)) {
    tok.clear();
    split(line, 0, tok);
    if (tok.empty()) continue;
    const std::string_view key = tok[0].text;
    const int ln = lines.number;
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      ended = true;
      break;
    }
    if (key == "format") {
      if (tok.size() < 2)
        throw VolumeFileError(path, ln, int(line.size()) + 1, "format needs a kind and a version");
      const std::string_view k = tok[1].text;
      format = k == "ascii"                  ? 0
               : k == "binary_little_endian" ? 1
               : k == "binary_big_endian"    ? 2
                                             : -1;
      if (format < 0)
        throw VolumeFileError(path, ln, tok[1].column,
                              "unknown PLY format '" + std::string(k) +
                                  "' (expected ascii, binary_little_endian or binary_big_endian)");
    } else if (key == "element") {
      if (tok.size() != 3) throw VolumeFileError(path, ln, 1, "expected 'element NAME COUNT'");
      double c;
      if (!parse_double(tok[2].text, c) || !(c >= 0) || c != std::floor(c) || c > 1e15)
        throw VolumeFileError(
            path, ln, tok[2].column,
            "element count must be a whole number >= 0, got '" + std::string(tok[2].text) + "'");
      elements.push_back({std::string(tok[1].text), std::uint64_t(c), ln, {}});
    } else if (key == "property") {
      if (elements.empty()) throw VolumeFileError(path, ln, 1, "a property before any element");
      PlyProperty p;
      if (tok.size() >= 2 && tok[1].text == "list") {
        if (tok.size() != 5)
          throw VolumeFileError(path, ln, 1, "expected 'property list COUNT_TYPE TYPE NAME'");
        p.list = true;
        p.count_type = ply_type(tok[2].text);
        p.type = ply_type(tok[3].text);
        p.name = std::string(tok[4].text);
        if (p.count_type == PlyType::kBad)
          throw VolumeFileError(path, ln, tok[2].column,
                                "unknown PLY type '" + std::string(tok[2].text) + "'");
        if (p.type == PlyType::kBad)
          throw VolumeFileError(path, ln, tok[3].column,
                                "unknown PLY type '" + std::string(tok[3].text) + "'");
      } else {
        if (tok.size() != 3) throw VolumeFileError(path, ln, 1, "expected 'property TYPE NAME'");
        p.type = ply_type(tok[1].text);
        p.name = std::string(tok[2].text);
        if (p.type == PlyType::kBad)
          throw VolumeFileError(path, ln, tok[1].column,
                                "unknown PLY type '" + std::string(tok[1].text) + "'");
      }
      elements.back().props.push_back(p);
    } else {
      throw VolumeFileError(path, ln, tok[0].column,
                            "unexpected PLY header line starting with '" + std::string(key) + "'");
    }
  }
  if (!ended)
    throw VolumeFileError(path, std::max(lines.number, 1), 1,
                          "truncated PLY header (no end_header)");
  if (format < 0) throw VolumeFileError(path, 2, 1, "the PLY header has no format line");
  const int body_line = lines.number + 1;
  int vertex = -1;
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].name == "vertex") vertex = int(e);
  if (vertex < 0) throw VolumeFileError(path, 2, 1, "the PLY file has no vertex element");
  int xyz[3] = {-1, -1, -1};
  const PlyElement& ve = elements[std::size_t(vertex)];
  for (std::size_t i = 0; i < ve.props.size(); ++i)
    for (int a = 0; a < 3; ++a)
      if (!ve.props[i].list && ve.props[i].name == std::string(1, char('x' + a))) xyz[a] = int(i);
  if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)
    throw VolumeFileError(path, ve.line, 1, "the PLY vertex element has no x, y and z properties");
  if (ve.count == 0)
    throw VolumeFileError(path, ve.line, 1, "no particles in the file (0 vertices)");

  std::vector<Vec3> out;
  static const char* kAxis[3] = {"x", "y", "z"};
  if (format == 0) {
    // Elements before the vertices are skipped line by line.
    std::uint64_t skip = 0;
    for (int e = 0; e < vertex; ++e) skip += elements[std::size_t(e)].count;
    for (std::uint64_t i = 0; i < skip; ++i)
      if (!lines.next(line))
        throw VolumeFileError(path, lines.number + 1, 1, "truncated PLY file (data ends early)");
    if (ve.count > text.size() - std::min(lines.pos, text.size()))
      throw VolumeFileError(path, body_line, 1,
                            "truncated PLY file: " + std::to_string(ve.count) +
                                " vertices cannot fit in the bytes left");
    out.reserve(ve.count);
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
        p[a] = finite_value(path, lines.number, tok[std::size_t(xyz[a])], kAxis[a]);
      out.push_back(p);
    }
    return out;
  }
  const bool big = format == 2;
  const auto* data = reinterpret_cast<const unsigned char*>(text.data());
  const std::uint64_t size = text.size();
  std::uint64_t at = std::min<std::uint64_t>(lines.pos, size);
  auto truncated = [&](const std::string& what) {
    return VolumeFileError(
        path, body_line, 1,
        "truncated PLY file: " + what + " (the file has " + std::to_string(size) + " bytes)");
  };
  for (int e = 0; e <= vertex; ++e) {
    const PlyElement& el = elements[std::size_t(e)];
    bool fixed = true;
    std::uint64_t stride = 0;
    for (const PlyProperty& q : el.props) {
      if (q.list) fixed = false;
      stride += std::uint64_t(ply_size(q.type));
    }
    if (e == vertex && fixed) {
      if (stride != 0 && ve.count > (size - at) / stride)
        throw truncated(std::to_string(ve.count) + " vertices of " + std::to_string(stride) +
                        " bytes need " + std::to_string(ve.count * stride) + " bytes after byte " +
                        std::to_string(at));
      std::uint64_t off[3] = {0, 0, 0};
      for (int a = 0; a < 3; ++a)
        for (int i = 0; i < xyz[a]; ++i)
          off[a] += std::uint64_t(ply_size(el.props[std::size_t(i)].type));
      out.resize(ve.count);
      for (std::uint64_t i = 0; i < ve.count; ++i, at += stride) {
        for (int a = 0; a < 3; ++a) {
          out[i][a] = ply_value(data + at + off[a], el.props[std::size_t(xyz[a])].type, big);
          if (!std::isfinite(out[i][a]))
            throw VolumeFileError(path, body_line, 1,
                                  "vertex " + std::to_string(i) + " has a " + kAxis[a] +
                                      " that is not finite (at byte " +
                                      std::to_string(at + off[a]) + ")");
        }
      }
      return out;
    }
    for (std::uint64_t i = 0; i < el.count; ++i) {
      Vec3 p;
      for (std::size_t k = 0; k < el.props.size(); ++k) {
        const PlyProperty& q = el.props[k];
        std::uint64_t n = 1;
        if (q.list) {
          const int cs = ply_size(q.count_type);
          if (size - at < std::uint64_t(cs)) throw truncated("element " + el.name + " ends early");
          const double c = ply_value(data + at, q.count_type, big);
          if (!(c >= 0))
            throw VolumeFileError(path, body_line, 1,
                                  "a negative PLY list count at byte " + std::to_string(at));
          at += std::uint64_t(cs);
          n = std::uint64_t(c);
        }
        const std::uint64_t bytes = n * std::uint64_t(ply_size(q.type));
        if (size - at < bytes) throw truncated("element " + el.name + " ends early");
        if (e == vertex && !q.list)
          for (int a = 0; a < 3; ++a)
            if (xyz[a] == int(k)) p[a] = ply_value(data + at, q.type, big);
        at += bytes;
      }
      if (e == vertex) {
        if (!is_finite(p))
          throw VolumeFileError(path, body_line, 1,
                                "vertex " + std::to_string(i) + " is not finite");
        out.push_back(p);
      }
    }
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
