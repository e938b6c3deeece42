#include "mesh/mesh_file.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

#include "mesh/obj_file.h"
#include "mesh/ply_file.h"
#include "mesh/stl_file.h"

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
  if (e == ".obj" || e == ".ply" || e == ".stl") return true;
#ifdef RAYCAST_HAVE_ASSIMP
  return e == ".gltf" || e == ".glb";
#else
  return false;
#endif
}

MeshFileData load_mesh_file(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (!mesh_format_supported(ext))
    throw MeshFileError("unsupported mesh format '" + ext + "' (expected .obj, .ply, .stl" +
                        (mesh_format_supported(".gltf") ? ", .gltf or .glb)"
                                                        : "; .gltf and .glb "
                                                          "need a build with assimp)"));
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshFileError("cannot open the mesh file (not found)");
  if (ext == ".ply") return read_ply_mesh(path);
  if (ext == ".obj") return read_obj_mesh(path);
  if (ext == ".stl") return read_stl_mesh(path);
#ifdef RAYCAST_HAVE_ASSIMP
  return read_with_assimp(path);
#else
  throw MeshFileError("this build cannot read " + ext + " files (assimp was not found)");
#endif
}

}  // namespace raycast
