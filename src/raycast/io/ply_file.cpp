#include "io/ply_file.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "io/mapped_file.h"
#include "io/ply.h"
#include "io/progress.h"
#include "io/text_lines.h"

namespace raycast {

namespace {

using ply::Type;

constexpr std::uint32_t kBadIndex = 0xFFFFFFFFu;  // out of range for any mesh: make_mesh reports it

bool is_index_list(const ply::Property& q) {
  return q.is_list() && (q.name == "vertex_indices" || q.name == "vertex_index");
}

// A stored index as a vertex number: negative or huge values become an out-of-range index.
std::uint32_t to_index(double v) {
  return v >= 0 && v < 4294967295.0 ? static_cast<std::uint32_t>(v) : kBadIndex;
}

// Where x, y, z, nx, ny, nz sit in a vertex row (-1: absent).
struct VertexLayout {
  int prop[6] = {-1, -1, -1, -1, -1, -1};
  bool normals() const { return prop[3] >= 0 && prop[4] >= 0 && prop[5] >= 0; }
};

VertexLayout vertex_layout(const ply::Element& e) {
  static const char* const kNames[6] = {"x", "y", "z", "nx", "ny", "nz"};
  VertexLayout l;
  for (std::size_t i = 0; i < e.props.size(); ++i)
    for (int k = 0; k < 6; ++k)
      if (!e.props[i].is_list() && e.props[i].name == kNames[k]) l.prop[k] = static_cast<int>(i);
  return l;
}

// ---- Binary bodies ------------------------------------------------------------------------------

// Rows decoded between two progress updates (and between two releases of decoded pages).
constexpr std::uint64_t kSlab = 1u << 20;

// Decodes rows [0, count) with `row(i)` in parallel, slab by slab, advancing the progress bar by
// each slab's bytes and releasing the decoded pages of the map.
template <class Row>
void decode_rows(std::uint64_t count, std::uint64_t stride, const char* base,
                 const MappedFile& file, StageProgress& progress, Row row) {
  for (std::uint64_t s = 0; s < count; s += kSlab) {
    const std::uint64_t e = std::min(count, s + kSlab);
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(s, e, 16384),
                      [&](const tbb::blocked_range<std::uint64_t>& r) {
                        for (std::uint64_t i = r.begin(); i < r.end(); ++i) row(i);
                      });
    file.release(base + s * stride, (e - s) * stride);
    progress.advance((e - s) * stride);
  }
}

// The fast path for little-endian faces: one index list whose rows all hold 3 indices, so every
// row has the same size and rows decode in parallel. Checks every row's count; returns false
// (having moved nothing) when a row is not a triangle or the data ends early, for the general path.
bool read_triangle_rows(const ply::Element& e, const char*& p, const char* end,
                        const MappedFile& file, StageProgress& progress,
                        std::vector<std::array<std::uint32_t, 3>>& out) {
  if (e.props.size() != 1 || !is_index_list(e.props[0])) return false;
  const ply::Property& q = e.props[0];
  const std::uint64_t cs = ply::type_size(q.count_type), is = ply::type_size(q.type);
  const std::uint64_t stride = cs + 3 * is;
  if (static_cast<std::uint64_t>(end - p) / stride < e.count) return false;
  const auto* const rows = reinterpret_cast<const unsigned char*>(p);
  std::vector<std::array<std::uint32_t, 3>> tris;
  tris.resize(e.count);
  std::atomic<bool> ok{true};
  for (std::uint64_t s = 0; s < e.count && ok; s += kSlab) {
    const std::uint64_t se = std::min<std::uint64_t>(e.count, s + kSlab);
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(s, se, 16384),
                      [&](const tbb::blocked_range<std::uint64_t>& r) {
                        bool good = true;
                        for (std::uint64_t i = r.begin(); i < r.end(); ++i) {
                          const unsigned char* row = rows + i * stride;
                          good &= ply::read_value(row, q.count_type, false) == 3;
                          for (int k = 0; k < 3; ++k) {
                            const unsigned char* v = row + cs + k * is;
                            if (q.type == Type::kI32) {
                              std::int32_t x;
                              std::memcpy(&x, v, 4);
                              tris[i][k] = x < 0 ? kBadIndex : static_cast<std::uint32_t>(x);
                            } else if (q.type == Type::kU32) {
                              std::memcpy(&tris[i][k], v, 4);
                            } else {
                              tris[i][k] = to_index(ply::read_value(v, q.type, false));
                            }
                          }
                        }
                        if (!good) ok = false;
                      });
    progress.advance((se - s) * stride);
  }
  if (!ok) return false;
  file.release(p, e.count * stride);
  out = std::move(tris);
  p += e.count * stride;
  return true;
}

class BinaryReader {
 public:
  BinaryReader(const std::string& path, const MappedFile& file, const ply::Header& header)
      : path_(path),
        file_(file),
        big_(header.format == ply::Format::kBinaryBigEndian),
        body_(file.data() + header.bytes),
        p_(body_),
        end_(file.data() + file.size()),
        progress_("reading " + std::filesystem::path(path).filename().string(),
                  static_cast<std::uint64_t>(end_ - p_), 64u << 20) {}

  void read(const ply::Header& header, MeshFileData& out) {
    for (const ply::Element& e : header.elements) {
      // Every row takes at least one byte: a count beyond the bytes left is a truncated file,
      // found before anything is allocated (and it keeps the size arithmetic from overflowing).
      if (e.count > static_cast<std::uint64_t>(end_ - p_))
        fail("element '" + e.name + "' has more rows (" + std::to_string(e.count) +
             ") than the file has bytes left: truncated PLY file");
      if (e.name == "vertex")
        read_vertices(e, out);
      else if (e.name == "face")
        read_faces(e, out);
      else
        for (std::uint64_t i = 0; i < e.count; ++i) skip_row(e);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw MeshFileError(path_ + ": " + why + " (at byte " +
                        std::to_string((p_ - body_) + (body_ - file_.data())) + ")");
  }
  void need(std::uint64_t bytes) const {
    if (static_cast<std::uint64_t>(end_ - p_) < bytes) fail("truncated PLY file (data ends early)");
  }
  double value(Type t) {
    need(ply::type_size(t));
    const double v = ply::read_value(reinterpret_cast<const unsigned char*>(p_), t, big_);
    p_ += ply::type_size(t);
    return v;
  }
  std::uint64_t list_count(Type t) {
    const double n = value(t);
    if (!(n >= 0 && n < 1e9)) fail("bad list count " + std::to_string(n));
    return static_cast<std::uint64_t>(n);
  }
  void skip_row(const ply::Element& e) {
    for (const ply::Property& q : e.props) {
      const std::uint64_t n = q.is_list() ? list_count(q.count_type) : 1;
      need(n * ply::type_size(q.type));
      p_ += n * ply::type_size(q.type);
    }
  }

  void read_vertices(const ply::Element& e, MeshFileData& out) {
    const VertexLayout l = vertex_layout(e);
    if (l.prop[0] < 0 || l.prop[1] < 0 || l.prop[2] < 0)
      throw MeshFileError(path_ + ": the PLY vertex element has no x, y, z properties");
    const bool normals = l.normals();
    out.soup.positions.resize(e.count);
    if (normals) out.normals.resize(e.count);
    const bool fixed = std::none_of(e.props.begin(), e.props.end(),
                                    [](const ply::Property& q) { return q.is_list(); });
    if (!fixed) {  // rows of different sizes: one after the other
      for (std::uint64_t i = 0; i < e.count; ++i) {
        double v[6] = {};
        for (std::size_t k = 0; k < e.props.size(); ++k) {
          const ply::Property& q = e.props[k];
          if (q.is_list()) {
            const std::uint64_t n = list_count(q.count_type);
            need(n * ply::type_size(q.type));
            p_ += n * ply::type_size(q.type);
            continue;
          }
          const double x = value(q.type);
          for (int c = 0; c < 6; ++c)
            if (l.prop[c] == static_cast<int>(k)) v[c] = x;
        }
        out.soup.positions[i] = Vec3f(Vec3{v[0], v[1], v[2]});
        if (normals) out.normals[i] = Vec3f(Vec3{v[3], v[4], v[5]});
      }
      return;
    }
    int stride = 0, off[6] = {0, 0, 0, 0, 0, 0};
    Type type[6] = {};
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      for (int c = 0; c < 6; ++c)
        if (l.prop[c] == static_cast<int>(k)) {
          off[c] = stride;
          type[c] = e.props[k].type;
        }
      stride += ply::type_size(e.props[k].type);
    }
    need(e.count * stride);
    // Three consecutive little-endian floats (the usual layout) are copied; anything else
    // converts value by value.
    auto packed = [&](int c) {
      return !big_ && type[c] == Type::kF32 && type[c + 1] == Type::kF32 &&
             type[c + 2] == Type::kF32 && off[c + 1] == off[c] + 4 && off[c + 2] == off[c] + 8;
    };
    const bool fast_xyz = packed(0), fast_n = normals && packed(3);
    const char* const rows = p_;
    const bool big = big_;
    const auto at = [big](const char* r, Type t) {
      return ply::read_value(reinterpret_cast<const unsigned char*>(r), t, big);
    };
    decode_rows(e.count, stride, rows, file_, progress_, [&](std::uint64_t i) {
      const char* r = rows + i * stride;
      if (fast_xyz)
        std::memcpy(&out.soup.positions[i], r + off[0], 12);
      else
        out.soup.positions[i] =
            Vec3f(Vec3{at(r + off[0], type[0]), at(r + off[1], type[1]), at(r + off[2], type[2])});
      if (fast_n)
        std::memcpy(&out.normals[i], r + off[3], 12);
      else if (normals)
        out.normals[i] =
            Vec3f(Vec3{at(r + off[3], type[3]), at(r + off[4], type[4]), at(r + off[5], type[5])});
    });
    p_ += e.count * stride;
  }

  void read_faces(const ply::Element& e, MeshFileData& out) {
    if (!big_ && read_triangle_rows(e, p_, end_, file_, progress_, out.soup.triangles)) return;
    // Smallest row: the fixed properties and every list's count.
    std::uint64_t min_row = 0;
    for (const ply::Property& q : e.props)
      min_row += ply::type_size(q.is_list() ? q.count_type : q.type);
    out.soup.triangles.reserve(
        std::min<std::uint64_t>(e.count, (end_ - p_) / std::max<std::uint64_t>(min_row, 1)));
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (const ply::Property& q : e.props) {
        if (!is_index_list(q)) {
          const std::uint64_t n = q.is_list() ? list_count(q.count_type) : 1;
          need(n * ply::type_size(q.type));
          p_ += n * ply::type_size(q.type);
          continue;
        }
        const double n = value(q.count_type);
        if (!(n >= 0 && n < 1e6)) fail("PLY face " + std::to_string(i) + " has a bad vertex count");
        const auto count = static_cast<std::uint32_t>(n);
        std::uint32_t first = 0, prev = 0;
        for (std::uint32_t k = 0; k < count; ++k) {
          const std::uint32_t idx = to_index(value(q.type));
          if (k == 0)
            first = idx;
          else if (k >= 2)
            out.soup.triangles.push_back({first, prev, idx});
          prev = idx;
        }
      }
      if ((i & (kSlab - 1)) == 0) progress_.set(static_cast<std::uint64_t>(p_ - body_));
    }
  }

  const std::string& path_;
  const MappedFile& file_;
  const bool big_;
  const char* const body_;
  const char* p_;
  const char* const end_;
  StageProgress progress_;
};

// ---- ASCII bodies: one row per line ------------------------------------------------------------

class AsciiReader {
 public:
  AsciiReader(const std::string& path, std::string_view file, const ply::Header& header)
      : path_(path), lines_(file, header.bytes, header.lines + 1) {}

  void read(const ply::Header& header, MeshFileData& out) {
    for (const ply::Element& e : header.elements) {
      // Every row is at least one byte: a count beyond the bytes left is a truncated file.
      if (e.count > lines_.remaining())
        throw MeshFileError(path_, e.line, 1,
                            "element '" + e.name + "' has more rows (" + std::to_string(e.count) +
                                ") than the file has bytes left: truncated PLY file");
      const VertexLayout l = vertex_layout(e);
      if (e.name == "vertex") {
        if (l.prop[0] < 0 || l.prop[1] < 0 || l.prop[2] < 0)
          throw MeshFileError(path_, e.line, 1, "the PLY vertex element has no x, y, z properties");
        out.soup.positions.reserve(e.count);
        if (l.normals()) out.normals.reserve(e.count);
      }
      for (std::uint64_t i = 0; i < e.count; ++i) read_row(e, l, out);
    }
  }

 private:
  void read_row(const ply::Element& e, const VertexLayout& l, MeshFileData& out) {
    std::string_view line;
    do {
      if (!lines_.next(line))
        throw MeshFileError(path_, lines_.number() + 1, 1,
                            "truncated PLY file: a row of element '" + e.name + "' is missing");
      text::split_words(line, words_);
    } while (words_.empty());
    std::size_t w = 0;
    double v[6] = {};
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      const ply::Property& q = e.props[k];
      if (!q.is_list()) {
        const double x = number(line, w++, q.name);
        for (int c = 0; c < 6; ++c)
          if (l.prop[c] == static_cast<int>(k)) v[c] = x;
        continue;
      }
      const double n = number(line, w++, q.name + " count");
      if (!(n >= 0 && n < 1e6 && n == std::floor(n)))
        throw MeshFileError(path_, lines_.number(), words_[w - 1].column,
                            "bad list count '" + std::string(words_[w - 1].text) + "'");
      const auto count = static_cast<std::uint32_t>(n);
      if (e.name == "face" && is_index_list(q)) {
        std::uint32_t first = 0, prev = 0;
        for (std::uint32_t j = 0; j < count; ++j) {
          const double x = number(line, w++, q.name);
          if (x != std::floor(x))
            throw MeshFileError(path_, lines_.number(), words_[w - 1].column,
                                "a vertex index must be a whole number, got '" +
                                    std::string(words_[w - 1].text) + "'");
          const std::uint32_t idx = to_index(x);
          if (j == 0)
            first = idx;
          else if (j >= 2)
            out.soup.triangles.push_back({first, prev, idx});
          prev = idx;
        }
      } else {
        for (std::uint32_t j = 0; j < count; ++j) number(line, w++, q.name);
      }
    }
    if (w < words_.size())
      throw MeshFileError(path_, lines_.number(), words_[w].column,
                          "more values than element '" + e.name + "' declares");
    if (e.name == "vertex") {
      out.soup.positions.push_back(Vec3f(Vec3{v[0], v[1], v[2]}));
      if (l.normals()) out.normals.push_back(Vec3f(Vec3{v[3], v[4], v[5]}));
    }
  }

  double number(std::string_view line, std::size_t w, const std::string& what) {
    if (w >= words_.size())
      throw MeshFileError(path_, lines_.number(), static_cast<int>(line.size()) + 1,
                          "the row ends before its " + what + " value");
    double v;
    if (!text::parse_finite(words_[w].text, v))
      throw MeshFileError(
          path_, lines_.number(), words_[w].column,
          what + " must be a finite number, got '" + std::string(words_[w].text) + "'");
    return v;
  }

  const std::string& path_;
  text::Lines lines_;
  std::vector<text::Word> words_;
};

}  // namespace

MeshFileData read_ply_mesh(const std::string& path) {
  const MappedFile file(path);
  ply::Header header;
  try {
    header = ply::parse_header(file.view());
  } catch (const ply::HeaderError& e) {
    throw MeshFileError(path, e.line(), e.column(), e.what());
  }
  const bool has_vertices = std::any_of(header.elements.begin(), header.elements.end(),
                                        [](const ply::Element& e) { return e.name == "vertex"; });
  if (!has_vertices) throw MeshFileError(path, 2, 1, "the PLY file has no vertex element");
  MeshFileData out;
  if (header.format == ply::Format::kAscii)
    AsciiReader(path, file.view(), header).read(header, out);
  else
    BinaryReader(path, file, header).read(header, out);
  return out;
}

}  // namespace raycast
