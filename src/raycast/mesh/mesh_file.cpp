#include "mesh/mesh_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string_view>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "accel/progress.h"

#ifdef RAYCAST_HAVE_ASSIMP
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#endif

namespace raycast {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A read-only memory map of a whole file (empty files map to nothing).
class MappedFile {
 public:
  explicit MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw MeshFileError("cannot open the mesh file");
    struct stat st;
    if (::fstat(fd, &st) != 0) {
      ::close(fd);
      throw MeshFileError("cannot read the mesh file");
    }
    size_ = static_cast<std::size_t>(st.st_size);
    if (size_ > 0) {
      void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
      if (p == MAP_FAILED) {
        ::close(fd);
        throw MeshFileError("cannot map the mesh file");
      }
      data_ = static_cast<const char*>(p);
      ::madvise(p, size_, MADV_SEQUENTIAL);
    }
    ::close(fd);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  const char* data() const { return data_; }
  std::size_t size() const { return size_; }
  // Drops the pages of [p, p + bytes) from the process (they stay in the page cache): a part
  // already decoded need not count towards the peak memory.
  void release(const char* p, std::size_t bytes) const {
    const std::uintptr_t page = 4096;
    const auto b = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
    const auto e = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
    if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_DONTNEED);
  }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

// ---- Binary little-endian PLY (our own reader) --------------------------------------------------

enum class PlyType { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64, kNone };

PlyType ply_type(const std::string& s) {
  if (s == "char" || s == "int8") return PlyType::kI8;
  if (s == "uchar" || s == "uint8") return PlyType::kU8;
  if (s == "short" || s == "int16") return PlyType::kI16;
  if (s == "ushort" || s == "uint16") return PlyType::kU16;
  if (s == "int" || s == "int32") return PlyType::kI32;
  if (s == "uint" || s == "uint32") return PlyType::kU32;
  if (s == "float" || s == "float32") return PlyType::kF32;
  if (s == "double" || s == "float64") return PlyType::kF64;
  return PlyType::kNone;
}

int ply_size(PlyType t) {
  switch (t) {
    case PlyType::kI8:
    case PlyType::kU8:
      return 1;
    case PlyType::kI16:
    case PlyType::kU16:
      return 2;
    case PlyType::kI32:
    case PlyType::kU32:
    case PlyType::kF32:
      return 4;
    case PlyType::kF64:
      return 8;
    default:
      return 0;
  }
}

double ply_read(const char* p, PlyType t) {
  switch (t) {
    case PlyType::kI8:
      return static_cast<std::int8_t>(*p);
    case PlyType::kU8:
      return static_cast<std::uint8_t>(*p);
    case PlyType::kI16: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case PlyType::kU16: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case PlyType::kI32: {
      std::int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case PlyType::kU32: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case PlyType::kF32: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case PlyType::kF64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
    default:
      return 0;
  }
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kNone;
  PlyType count_type = PlyType::kNone;  // a list property when set
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> props;
};

// A vertex index as stored: negative or huge values become an out-of-range index, reported by
// make_mesh.
std::uint32_t ply_index(const char* p, PlyType t) {
  const double v = ply_read(p, t);
  return v >= 0 && v < 4294967295.0 ? static_cast<std::uint32_t>(v) : 0xFFFFFFFFu;
}

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

// The fast path for faces: one index list whose rows all hold 3 indices, so that every row has
// the same size and rows decode in parallel. Checks every row's count; returns false (having
// moved nothing) when a row is not a triangle or the data ends early, for the general path.
bool read_triangle_rows(const PlyElement& e, const char*& p, const char* end,
                        const MappedFile& file, StageProgress& progress,
                        std::vector<std::array<std::uint32_t, 3>>& out) {
  if (e.props.size() != 1) return false;
  const PlyProperty& q = e.props[0];
  if (q.count_type == PlyType::kNone || (q.name != "vertex_indices" && q.name != "vertex_index"))
    return false;
  const std::uint64_t cs = ply_size(q.count_type), is = ply_size(q.type);
  const std::uint64_t stride = cs + 3 * is;
  if (static_cast<std::uint64_t>(end - p) / stride < e.count) return false;
  const char* const rows = p;
  std::vector<std::array<std::uint32_t, 3>> tris;
  tris.resize(e.count);
  std::atomic<bool> ok{true};
  for (std::uint64_t s = 0; s < e.count && ok; s += kSlab) {
    const std::uint64_t se = std::min<std::uint64_t>(e.count, s + kSlab);
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(s, se, 16384),
                      [&](const tbb::blocked_range<std::uint64_t>& r) {
                        bool good = true;
                        for (std::uint64_t i = r.begin(); i < r.end(); ++i) {
                          const char* row = rows + i * stride;
                          good &= ply_read(row, q.count_type) == 3;
                          for (int k = 0; k < 3; ++k) {
                            const char* v = row + cs + k * is;
                            if (q.type == PlyType::kI32) {
                              std::int32_t x;
                              std::memcpy(&x, v, 4);
                              tris[i][k] = x < 0 ? 0xFFFFFFFFu : static_cast<std::uint32_t>(x);
                            } else if (q.type == PlyType::kU32) {
                              std::memcpy(&tris[i][k], v, 4);
                            } else {
                              tris[i][k] = ply_index(v, q.type);
                            }
                          }
                        }
                        if (!good) ok = false;
                      });
    progress.advance((se - s) * stride);
  }
  if (!ok) return false;
  file.release(rows, e.count * stride);
  out = std::move(tris);
  p += e.count * stride;
  return true;
}

// A PLY header, read line by line as the format defines it: "ply", then format, comment,
// obj_info, element and property lines, up to an "end_header" line.
struct PlyHeader {
  std::string format;  // ascii, binary_little_endian or binary_big_endian
  std::vector<PlyElement> elements;
  bool types_known = true;  // every property type is one PLY defines
  std::size_t bytes = 0;    // the header's length, through the newline after end_header
};

// Throws MeshFileError for a malformed header (naming the line), so that no reader, ours or
// assimp's, ever sees one: assimp 5.2 loops forever on a header without end_header.
PlyHeader parse_ply_header(std::string_view file) {
  constexpr std::size_t kMaxHeader = std::size_t{1} << 20;  // far beyond any real header
  const std::string_view head = file.substr(0, std::min(file.size(), kMaxHeader));
  if (head.substr(0, 3) != "ply") throw MeshFileError("not a PLY file (no 'ply' magic line)");
  PlyHeader h;
  std::size_t pos = 0;
  for (int line_no = 1;; ++line_no) {
    const std::size_t eol = head.find('\n', pos);
    if (eol == std::string_view::npos)
      throw MeshFileError(file.size() > kMaxHeader ? "PLY header longer than 1 MiB"
                                                   : "truncated PLY header (no end_header line)");
    std::string line(head.substr(pos, eol - pos));
    pos = eol + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    auto bad = [&](const std::string& why) {
      return MeshFileError("malformed PLY header, line " + std::to_string(line_no) + ": " + why);
    };
    if (line_no == 1) {
      if (line != "ply") throw MeshFileError("not a PLY file (no 'ply' magic line)");
      continue;
    }
    std::string extra;
    if (word == "end_header") {
      if (ls >> extra) throw bad("text after end_header");
      if (h.format.empty()) throw bad("no format line before end_header");
      h.bytes = pos;
      return h;
    }
    if (word == "comment" || word == "obj_info") continue;
    if (word == "format") {
      std::string version;
      ls >> h.format >> version;
      if (h.format != "ascii" && h.format != "binary_little_endian" &&
          h.format != "binary_big_endian")
        throw bad("unknown format '" + h.format + "'");
      if (version.empty() || (ls >> extra)) throw bad("expected 'format TYPE VERSION'");
    } else if (word == "element") {
      PlyElement e;
      std::string count;
      ls >> e.name >> count;
      if (e.name.empty() || count.empty() || (ls >> extra) ||
          count.find_first_not_of("0123456789") != std::string::npos || count.size() > 20)
        throw bad("expected 'element NAME COUNT'");
      errno = 0;
      e.count = std::strtoull(count.c_str(), nullptr, 10);
      if (errno == ERANGE) throw bad("element count " + count + " is too large");
      h.elements.push_back(e);
    } else if (word == "property") {
      if (h.elements.empty()) throw bad("a property before any element");
      PlyProperty p;
      std::string type;
      ls >> type;
      if (type == "list") {
        std::string ct, it;
        ls >> ct >> it >> p.name;
        p.count_type = ply_type(ct);
        p.type = ply_type(it);
        if (p.count_type == PlyType::kNone || p.type == PlyType::kNone) h.types_known = false;
      } else {
        p.type = ply_type(type);
        ls >> p.name;
        if (p.type == PlyType::kNone) h.types_known = false;
      }
      if (p.name.empty() || (ls >> extra)) throw bad("expected 'property TYPE NAME'");
      h.elements.back().props.push_back(p);
    } else {
      throw bad("unknown keyword '" + word + "'");
    }
  }
}

// Reads binary little-endian PLY files of the common shape (vertex element with x, y, z and
// optional nx, ny, nz; face element with one index list) in one pass over a memory map. Returns
// false, having read nothing, for ASCII and big-endian PLY (assimp reads those). Vertices are
// decoded in parallel; faces too when every row is a triangle with the same layout (the usual
// case), else by a serial pass that fans polygons.
bool read_binary_ply(const std::string& path, MeshFileData& out) {
  const MappedFile file(path);
  const char* const data = file.data();
  const std::size_t size = file.size();
  const PlyHeader header = parse_ply_header(std::string_view(data, size));
  if (header.format != "binary_little_endian") return false;
  // Binary little-endian PLY is ours alone: assimp 5.2 aborts the process on some malformed ones.
  if (!header.types_known) throw MeshFileError("PLY property of an unknown type");
  const std::vector<PlyElement>& elements = header.elements;
  const char* const body = data + header.bytes;
  const char* p = body;
  const char* const end = data + size;
  auto need = [&](std::uint64_t bytes) {
    if (static_cast<std::uint64_t>(end - p) < bytes)
      throw MeshFileError("truncated PLY file (data ends early)");
  };
  StageProgress progress("reading " + std::filesystem::path(path).filename().string(),
                         static_cast<std::uint64_t>(end - p), 64u << 20);
  bool have_vertices = false;
  for (const PlyElement& e : elements) {
    // Every row takes at least one byte: a count beyond the bytes left is a truncated file, found
    // before anything is allocated (and it keeps the size arithmetic below from overflowing).
    if (e.count > static_cast<std::uint64_t>(end - p))
      throw MeshFileError("truncated PLY file (element " + e.name +
                          " has more rows than the file has bytes)");
    const bool any_list = std::any_of(e.props.begin(), e.props.end(),
                                      [](const auto& q) { return q.count_type != PlyType::kNone; });
    if (e.name == "vertex") {
      if (any_list) throw MeshFileError("PLY vertex element with a list property (not supported)");
      int stride = 0, off[6] = {-1, -1, -1, -1, -1, -1};
      PlyType type[6] = {};
      const char* names[6] = {"x", "y", "z", "nx", "ny", "nz"};
      for (const PlyProperty& q : e.props) {
        for (int k = 0; k < 6; ++k)
          if (q.name == names[k]) {
            off[k] = stride;
            type[k] = q.type;
          }
        stride += ply_size(q.type);
      }
      if (off[0] < 0 || off[1] < 0 || off[2] < 0)
        throw MeshFileError("PLY vertices have no x, y, z");
      const bool normals = off[3] >= 0 && off[4] >= 0 && off[5] >= 0;
      need(e.count * stride);
      // Three consecutive floats (the usual layout) are copied; anything else converts per value.
      auto packed = [&](int k) {
        return type[k] == PlyType::kF32 && type[k + 1] == PlyType::kF32 &&
               type[k + 2] == PlyType::kF32 && off[k + 1] == off[k] + 4 && off[k + 2] == off[k] + 8;
      };
      const bool fast_xyz = packed(0), fast_n = normals && packed(3);
      out.soup.positions.resize(e.count);
      if (normals) out.normals.resize(e.count);
      const char* const rows = p;
      decode_rows(e.count, stride, rows, file, progress, [&](std::uint64_t i) {
        const char* r = rows + i * stride;
        if (fast_xyz)
          std::memcpy(&out.soup.positions[i], r + off[0], 12);
        else
          out.soup.positions[i] =
              Vec3f(Vec3{ply_read(r + off[0], type[0]), ply_read(r + off[1], type[1]),
                         ply_read(r + off[2], type[2])});
        if (fast_n)
          std::memcpy(&out.normals[i], r + off[3], 12);
        else if (normals)
          out.normals[i] = Vec3f(Vec3{ply_read(r + off[3], type[3]), ply_read(r + off[4], type[4]),
                                      ply_read(r + off[5], type[5])});
      });
      p += e.count * stride;
      have_vertices = true;
    } else if (e.name == "face") {
      if (read_triangle_rows(e, p, end, file, progress, out.soup.triangles)) continue;
      // Smallest row: the fixed properties and every list's count.
      std::uint64_t min_row = 0;
      for (const PlyProperty& q : e.props)
        min_row += ply_size(q.count_type != PlyType::kNone ? q.count_type : q.type);
      out.soup.triangles.reserve(
          std::min<std::uint64_t>(e.count, (end - p) / std::max<std::uint64_t>(min_row, 1)));
      for (std::uint64_t i = 0; i < e.count; ++i) {
        for (const PlyProperty& q : e.props) {
          if (q.count_type == PlyType::kNone) {
            need(ply_size(q.type));
            p += ply_size(q.type);
            continue;
          }
          need(ply_size(q.count_type));
          const double n = ply_read(p, q.count_type);
          p += ply_size(q.count_type);
          if (!(n >= 0 && n < 1e6))
            throw MeshFileError("PLY face " + std::to_string(i) + " has a bad vertex count");
          const auto count = static_cast<std::uint32_t>(n);
          need(std::uint64_t(count) * ply_size(q.type));
          if (q.name != "vertex_indices" && q.name != "vertex_index") {
            p += count * ply_size(q.type);
            continue;
          }
          std::uint32_t first = 0, prev = 0;
          for (std::uint32_t k = 0; k < count; ++k, p += ply_size(q.type)) {
            const std::uint32_t idx = ply_index(p, q.type);
            if (k == 0)
              first = idx;
            else if (k >= 2)
              out.soup.triangles.push_back({first, prev, idx});
            prev = idx;
          }
        }
        if ((i & (kSlab - 1)) == 0) progress.set(static_cast<std::uint64_t>(p - body));
      }
    } else {
      // Skip another element; it must have fixed-size rows to be skippable.
      if (any_list)
        throw MeshFileError("PLY element '" + e.name + "' with a list property (not supported)");
      std::uint64_t stride = 0;
      for (const PlyProperty& q : e.props) stride += ply_size(q.type);
      need(e.count * stride);
      p += e.count * stride;
    }
  }
  if (!have_vertices) throw MeshFileError("PLY file has no vertex element");
  return true;
}

#ifdef RAYCAST_HAVE_ASSIMP
MeshFileData read_with_assimp(const std::string& path) {
  Assimp::Importer importer;
  // Vertices are joined only after checking them: JoinIdenticalVertices merges a NaN vertex into
  // another one, which silently turned `v 1 nan 0` into a degenerate triangle.
  const unsigned flags = aiProcess_Triangulate | aiProcess_PreTransformVertices |
                         aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFile(path, flags);
  auto fail = [&] {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unknown reason";
    throw MeshFileError("cannot read the mesh: " + why);
  };
  if (!scene) fail();
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw MeshFileError("a vertex is not finite: (" + std::to_string(p.x) + ", " +
                            std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
    }
  }
  scene = importer.ApplyPostProcessing(aiProcess_JoinIdenticalVertices);
  if (!scene) fail();
  MeshFileData out;
  bool all_normals = true;
  std::size_t triangle_meshes = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    ++triangle_meshes;
    const auto base = static_cast<std::uint32_t>(out.soup.positions.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      out.soup.positions.push_back({p.x, p.y, p.z});
    }
    if (mesh->HasNormals()) {
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const aiVector3D& n = mesh->mNormals[v];
        out.normals.push_back({n.x, n.y, n.z});
      }
    } else {
      all_normals = false;
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      out.soup.triangles.push_back(
          {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  if (triangle_meshes == 0) throw MeshFileError("the file holds no triangles");
  if (!all_normals) out.normals.clear();
  return out;
}
#endif

}  // namespace

bool mesh_format_supported(const std::string& extension) {
  const std::string e = lower(extension);
#ifdef RAYCAST_HAVE_ASSIMP
  return e == ".obj" || e == ".ply" || e == ".stl" || e == ".gltf" || e == ".glb";
#else
  return e == ".ply";
#endif
}

MeshFileData load_mesh_file(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (!mesh_format_supported(ext))
    throw MeshFileError("unsupported mesh format '" + ext +
                        "' (expected .obj, .ply, .stl, .gltf or .glb)");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshFileError("cannot open the mesh file (not found)");
  MeshFileData out;
  if (ext == ".ply" && read_binary_ply(path, out)) return out;
#ifdef RAYCAST_HAVE_ASSIMP
  return read_with_assimp(path);
#else
  throw MeshFileError(
      "this build reads only binary little-endian PLY files (assimp was not found)");
#endif
}

}  // namespace raycast
