#include "mesh/mesh_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>

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

// A progress bar on stderr for large files when stderr is a terminal.
class Progress {
 public:
  Progress(const std::string& what, std::uint64_t total)
      : what_(what), total_(total), on_(total >= (64u << 20) && isatty(2)) {}
  ~Progress() {
    if (on_) std::fprintf(stderr, "\r%s: done%30s\n", what_.c_str(), "");
  }
  void update(std::uint64_t done) {
    if (!on_ || total_ == 0) return;
    const int pct = static_cast<int>(100 * done / total_);
    if (pct == last_) return;
    last_ = pct;
    const int bars = pct / 4;
    std::fprintf(stderr, "\r%s: [%.*s%*s] %3d%%", what_.c_str(), bars,
                 "=========================", 25 - bars, "", pct);
    std::fflush(stderr);
  }

 private:
  std::string what_;
  std::uint64_t total_;
  bool on_;
  int last_ = -1;
};

std::vector<char> read_all(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!f) throw MeshFileError("cannot open the mesh file");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw MeshFileError("cannot read the mesh file");
  std::vector<char> data(size);
  Progress progress("loading " + std::filesystem::path(path).filename().string(), size);
  std::size_t done = 0;
  while (done < size) {
    const std::size_t chunk = std::min<std::size_t>(size - done, 16u << 20);
    const std::size_t got = std::fread(data.data() + done, 1, chunk, f.get());
    if (got == 0) throw MeshFileError("cannot read the mesh file");
    done += got;
    progress.update(done);
  }
  return data;
}

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

// Reads binary little-endian PLY files of the common shape (vertex element with x, y, z and
// optional nx, ny, nz; face element with one index list). Returns false, having read nothing,
// for any other PLY so that assimp gets it.
bool read_binary_ply(const std::string& path, MeshFileData& out) {
  {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw MeshFileError("cannot open the mesh file");
    char magic[64] = {};
    const std::size_t got = std::fread(magic, 1, sizeof magic - 1, f);
    std::fclose(f);
    if (got < 4 || std::strncmp(magic, "ply", 3) != 0)
      throw MeshFileError("not a PLY file (no 'ply' magic)");
    if (!std::strstr(magic, "binary_little_endian")) return false;
  }
  const std::vector<char> data = read_all(path);
  const char* end_header = nullptr;
  for (std::size_t i = 0; i + 10 <= data.size(); ++i)
    if (std::memcmp(data.data() + i, "end_header", 10) == 0) {
      end_header = data.data() + i;
      break;
    }
  if (!end_header) throw MeshFileError("truncated PLY header (no end_header)");
  const char* body = static_cast<const char*>(
      std::memchr(end_header, '\n', data.data() + data.size() - end_header));
  if (!body) throw MeshFileError("truncated PLY header");
  ++body;
  std::istringstream header(std::string(data.data(), end_header));
  std::vector<PlyElement> elements;
  std::string line;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "element") {
      PlyElement e;
      ls >> e.name >> e.count;
      if (!ls) throw MeshFileError("malformed PLY element line: " + line);
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) throw MeshFileError("PLY property before any element");
      PlyProperty p;
      std::string type;
      ls >> type;
      if (type == "list") {
        std::string ct, it;
        ls >> ct >> it >> p.name;
        p.count_type = ply_type(ct);
        p.type = ply_type(it);
        if (p.count_type == PlyType::kNone || p.type == PlyType::kNone) return false;
      } else {
        p.type = ply_type(type);
        ls >> p.name;
        if (p.type == PlyType::kNone) return false;
      }
      elements.back().props.push_back(p);
    }
  }
  const char* p = body;
  const char* const end = data.data() + data.size();
  auto need = [&](std::uint64_t bytes) {
    if (static_cast<std::uint64_t>(end - p) < bytes)
      throw MeshFileError("truncated PLY file (data ends early)");
  };
  bool have_vertices = false;
  for (const PlyElement& e : elements) {
    // Every row takes at least one byte: a count beyond the bytes left is a truncated file (and
    // keeps the size arithmetic below from overflowing).
    if (e.count > static_cast<std::uint64_t>(end - p))
      throw MeshFileError("truncated PLY file (element " + e.name +
                          " has more rows than the file has bytes)");
    const bool any_list = std::any_of(e.props.begin(), e.props.end(),
                                      [](const auto& q) { return q.count_type != PlyType::kNone; });
    if (e.name == "vertex") {
      if (any_list) return false;
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
      out.soup.positions.resize(e.count);
      if (normals) out.normals.resize(e.count);
      for (std::uint64_t i = 0; i < e.count; ++i, p += stride) {
        out.soup.positions[i] =
            Vec3f(Vec3{ply_read(p + off[0], type[0]), ply_read(p + off[1], type[1]),
                       ply_read(p + off[2], type[2])});
        if (normals)
          out.normals[i] = Vec3f(Vec3{ply_read(p + off[3], type[3]), ply_read(p + off[4], type[4]),
                                      ply_read(p + off[5], type[5])});
      }
      have_vertices = true;
    } else if (e.name == "face") {
      out.soup.triangles.reserve(e.count);
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
            const double v = ply_read(p, q.type);
            // Negative or huge indices become out-of-range indices, reported by make_mesh.
            const std::uint32_t idx =
                v >= 0 && v < 4294967295.0 ? static_cast<std::uint32_t>(v) : 0xFFFFFFFFu;
            if (k == 0)
              first = idx;
            else if (k >= 2)
              out.soup.triangles.push_back({first, prev, idx});
            prev = idx;
          }
        }
      }
    } else {
      // Skip another element; it must have fixed-size rows to be skippable.
      if (any_list) return false;
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
