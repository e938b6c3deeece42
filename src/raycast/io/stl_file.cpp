#include "io/stl_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "io/mapped_file.h"
#include "io/text_lines.h"

namespace raycast {

namespace {

// Joins corners at the same position (bit for bit) into one vertex.
class VertexWelder {
 public:
  std::uint32_t add(const Vec3f& p) {
    std::array<std::uint32_t, 3> key;
    std::memcpy(key.data(), &p, sizeof key);
    const auto [it, fresh] = index_.try_emplace(key, static_cast<std::uint32_t>(positions_.size()));
    if (fresh) positions_.push_back(p);
    return it->second;
  }
  std::vector<Vec3f> take() { return std::move(positions_); }

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::uint32_t, 3>& k) const {
      std::uint64_t h = 0x9E3779B97F4A7C15ull;
      for (const std::uint32_t v : k) h = (h ^ v) * 0xBF58476D1CE4E5B9ull;
      return static_cast<std::size_t>(h ^ (h >> 31));
    }
  };
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, KeyHash> index_;
  std::vector<Vec3f> positions_;
};

MeshFileData read_binary_stl(std::string_view file, std::uint64_t count) {
  MeshFileData out;
  VertexWelder weld;
  out.soup.triangles.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const char* facet = file.data() + 84 + 50 * i;
    std::array<std::uint32_t, 3> t;
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 + 12 * k, 12);  // after the facet normal
      t[k] = weld.add(Vec3f{xyz[0], xyz[1], xyz[2]});
    }
    out.soup.triangles.push_back(t);
  }
  out.soup.positions = weld.take();
  return out;
}

class AsciiStlReader {
 public:
  explicit AsciiStlReader(const std::string& path) : path_(path) {}

  MeshFileData read(std::string_view file) {
    text::Lines lines(file);
    MeshFileData out;
    VertexWelder weld;
    std::array<std::uint32_t, 3> t{};
    int corners = -1;  // -1 outside a facet's loop, else the corners read so far
    bool ended = false;
    std::string_view line;
    while (lines.next(line)) {
      text::split_words(line, words_);
      if (words_.empty()) continue;
      const std::string_view key = words_[0].text;
      if (lines.number() == 1 && key != "solid")
        fail(lines, 1, "an ASCII STL file starts with 'solid'");
      if (ended) fail(lines, words_[0].column, "text after endsolid");
      if (key == "solid" && lines.number() == 1) continue;
      if (key == "facet" || key == "endfacet") {
        if (corners >= 0) fail(lines, words_[0].column, "'" + std::string(key) + "' inside a loop");
      } else if (key == "outer") {
        if (corners >= 0) fail(lines, words_[0].column, "a loop inside a loop");
        corners = 0;
      } else if (key == "vertex") {
        if (corners < 0) fail(lines, words_[0].column, "a vertex outside 'outer loop'");
        if (corners == 3) fail(lines, words_[0].column, "a facet with more than 3 vertices");
        if (words_.size() != 4) fail(lines, words_[0].column, "expected 'vertex x y z'");
        t[static_cast<std::size_t>(corners++)] =
            weld.add(Vec3f(Vec3{number(lines, 1), number(lines, 2), number(lines, 3)}));
      } else if (key == "endloop") {
        if (corners != 3)
          fail(lines, words_[0].column,
               "a facet needs 3 vertices, got " + std::to_string(std::max(corners, 0)));
        out.soup.triangles.push_back(t);
        corners = -1;
      } else if (key == "endsolid") {
        if (corners >= 0) fail(lines, words_[0].column, "endsolid inside a loop");
        ended = true;
      } else {
        fail(lines, words_[0].column, "unexpected '" + std::string(key) + "' in an ASCII STL file");
      }
    }
    if (!ended) fail(lines, 1, "truncated STL file (no endsolid line)");
    out.soup.positions = weld.take();
    return out;
  }

 private:
  [[noreturn]] void fail(const text::Lines& lines, int column, const std::string& why) const {
    throw MeshFileError(path_, std::max(lines.number(), 1), column, why);
  }
  double number(const text::Lines& lines, std::size_t w) const {
    double v;
    if (!text::parse_finite(words_[w].text, v))
      fail(lines, words_[w].column,
           "expected a finite number, got '" + std::string(words_[w].text) + "'");
    return v;
  }

  const std::string& path_;
  std::vector<text::Word> words_;
};

}  // namespace

MeshFileData read_stl_mesh(const std::string& path) {
  const MappedFile file(path);
  const std::string_view bytes = file.view();
  if (bytes.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * std::uint64_t{count}) return read_binary_stl(bytes, count);
  }
  if (bytes.substr(0, 5) != "solid")
    throw MeshFileError(
        path + ": neither a binary STL (" + std::to_string(bytes.size()) +
        " bytes is not 84 + 50 per facet) nor an ASCII one (no 'solid' at the start)");
  return AsciiStlReader(path).read(bytes);
}

}  // namespace raycast
