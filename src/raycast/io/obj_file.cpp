#include "io/obj_file.h"

#include <cmath>
#include <cstdint>
#include <string_view>

#include "io/mapped_file.h"
#include "io/text_lines.h"

namespace raycast {

namespace {

class ObjReader {
 public:
  explicit ObjReader(const std::string& path) : path_(path) {}

  MeshFileData read(std::string_view file) {
    text::Lines lines(file);
    std::string_view line;
    while (lines.next(line)) {
      text::split_words(line, words_);
      if (words_.empty() || words_[0].text[0] == '#') continue;
      const std::string_view key = words_[0].text;
      if (key == "v") {
        if (words_.size() < 4) fail(lines, line.size() + 1, "a vertex needs x y z");
        positions_.push_back(Vec3f(Vec3{number(lines, 1), number(lines, 2), number(lines, 3)}));
      } else if (key == "vn") {
        if (words_.size() < 4) fail(lines, line.size() + 1, "a normal needs x y z");
        normals_.push_back(Vec3{number(lines, 1), number(lines, 2), number(lines, 3)});
      } else if (key == "f") {
        read_face(lines, line);
      }
    }
    MeshFileData out;
    out.soup.positions = std::move(positions_);
    out.soup.triangles = std::move(triangles_);
    if (every_corner_has_normal_ && corners_ > 0) {
      out.normals.assign(out.soup.positions.size(), Vec3f{0, 0, 0});
      corner_normal_sums_.resize(out.normals.size());
      for (std::size_t i = 0; i < corner_normal_sums_.size(); ++i) {
        const Vec3& n = corner_normal_sums_[i];
        const double len = length(n);
        if (!(len > 0 && std::isfinite(len))) {  // unused, or its normals cancel: computed instead
          out.normals.clear();
          break;
        }
        out.normals[i] = Vec3f(n / len);
      }
    }
    return out;
  }

 private:
  [[noreturn]] void fail(const text::Lines& lines, std::size_t column,
                         const std::string& why) const {
    throw MeshFileError(path_, lines.number(), static_cast<int>(column), why);
  }

  double number(const text::Lines& lines, std::size_t w) const {
    double v;
    if (!text::parse_finite(words_[w].text, v))
      fail(lines, words_[w].column,
           "expected a finite number, got '" + std::string(words_[w].text) + "'");
    return v;
  }

  // An OBJ index (1-based, or negative from the end of the `count` defined so far) as 0-based.
  std::uint32_t resolve(const text::Lines& lines, std::string_view s, int column, std::size_t count,
                        const char* what) const {
    std::int64_t i;
    if (!text::parse_integer(s, i) || i == 0)
      fail(lines, column,
           std::string("expected a ") + what + " index (1-based, or negative), got '" +
               std::string(s) + "'");
    const std::int64_t n = static_cast<std::int64_t>(count);
    const std::int64_t k = i > 0 ? i - 1 : n + i;
    if (k < 0 || k >= n)
      fail(lines, column,
           std::string(what) + " index " + std::string(s) + " names no " + what + " (" +
               std::to_string(count) + " defined so far)");
    return static_cast<std::uint32_t>(k);
  }

  void read_face(const text::Lines& lines, std::string_view line) {
    if (words_.size() < 4) fail(lines, line.size() + 1, "a face needs at least 3 corners");
    std::uint32_t first = 0, prev = 0;
    for (std::size_t w = 1; w < words_.size(); ++w) {
      const std::string_view corner = words_[w].text;
      const std::size_t slash = corner.find('/');
      const std::uint32_t v =
          resolve(lines, corner.substr(0, slash), words_[w].column, positions_.size(), "vertex");
      // v/t/n: the normal is the third part; v and v/t have none.
      std::string_view normal;
      if (slash != std::string_view::npos) {
        const std::size_t second = corner.find('/', slash + 1);
        if (second != std::string_view::npos) normal = corner.substr(second + 1);
      }
      ++corners_;
      if (normal.empty()) {
        every_corner_has_normal_ = false;
      } else if (every_corner_has_normal_) {
        const std::uint32_t n = resolve(lines, normal, words_[w].column, normals_.size(), "normal");
        if (corner_normal_sums_.size() <= v) corner_normal_sums_.resize(v + 1);
        const double len = length(normals_[n]);
        if (len > 0 && std::isfinite(len)) corner_normal_sums_[v] += normals_[n] / len;
      }
      if (w == 1)
        first = v;
      else if (w >= 3)
        triangles_.push_back({first, prev, v});
      prev = v;
    }
  }

  const std::string& path_;
  std::vector<text::Word> words_;
  std::vector<Vec3f> positions_;
  std::vector<Vec3> normals_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<Vec3> corner_normal_sums_;  // per vertex: the unit normals its corners name, summed
  bool every_corner_has_normal_ = true;
  std::size_t corners_ = 0;
};

}  // namespace

MeshFileData read_obj_mesh(const std::string& path) {
  const MappedFile file(path);
  return ObjReader(path).read(file.view());
}

}  // namespace raycast
