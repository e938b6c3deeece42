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

std::vector<Vec3> read_ply(const std::string& path, const std::string& text) {
  ply::Header header;
  try {
    header = ply::parse_header(text);
  } catch (const ply::HeaderError& e) {
    throw VolumeFileError(path, e.line(), e.column(), e.what());
  }
  const int format = header.format == ply::Format::kAscii                ? 0
                     : header.format == ply::Format::kBinaryLittleEndian ? 1
                                                                         : 2;
  const std::vector<ply::Element>& elements = header.elements;
  Lines lines{text, header.bytes, header.lines};
  std::string_view line;
  std::vector<Token> tok;
  const int body_line = lines.number + 1;
  int vertex = -1;
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].name == "vertex") vertex = int(e);
  if (vertex < 0) throw VolumeFileError(path, 2, 1, "the PLY file has no vertex element");
  int xyz[3] = {-1, -1, -1};
  const ply::Element& ve = elements[std::size_t(vertex)];
  for (std::size_t i = 0; i < ve.props.size(); ++i)
    for (int a = 0; a < 3; ++a)
      if (!ve.props[i].is_list() && ve.props[i].name == std::string(1, char('x' + a)))
        xyz[a] = int(i);
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
    const ply::Element& el = elements[std::size_t(e)];
    bool fixed = true;
    std::uint64_t stride = 0;
    for (const ply::Property& q : el.props) {
      if (q.is_list()) fixed = false;
      stride += std::uint64_t(ply::type_size(q.type));
    }
    if (e == vertex && fixed) {
      if (stride != 0 && ve.count > (size - at) / stride)
        throw truncated(std::to_string(ve.count) + " vertices of " + std::to_string(stride) +
                        " bytes need " + std::to_string(ve.count * stride) + " bytes after byte " +
                        std::to_string(at));
      std::uint64_t off[3] = {0, 0, 0};
      for (int a = 0; a < 3; ++a)
        for (int i = 0; i < xyz[a]; ++i)
          off[a] += std::uint64_t(ply::type_size(el.props[std::size_t(i)].type));
      out.resize(ve.count);
      for (std::uint64_t i = 0; i < ve.count; ++i, at += stride) {
        for (int a = 0; a < 3; ++a) {
          out[i][a] = ply::read_value(data + at + off[a], el.props[std::size_t(xyz[a])].type, big);
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
        const ply::Property& q = el.props[k];
        std::uint64_t n = 1;
        if (q.is_list()) {
          const int cs = ply::type_size(q.count_type);
          if (size - at < std::uint64_t(cs)) throw truncated("element " + el.name + " ends early");
          const double c = ply::read_value(data + at, q.count_type, big);
          if (!(c >= 0))
            throw VolumeFileError(path, body_line, 1,
                                  "a negative PLY list count at byte " + std::to_string(at));
          at += std::uint64_t(cs);
          n = std::uint64_t(c);
        }
        const std::uint64_t bytes = n * std::uint64_t(ply::type_size(q.type));
        if (size - at < bytes) throw truncated("element " + el.name + " ends early");
        if (e == vertex && !q.is_list())
          for (int a = 0; a < 3; ++a)
            if (xyz[a] == int(k)) p[a] = ply::read_value(data + at, q.type, big);
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
