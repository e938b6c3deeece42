// The assimp plugin (mesh/assimp_plugin_abi.h): the only code that links assimp, loaded by
// mesh/mesh_file.cpp the first time a scene reads a glTF/GLB mesh. It throws the core's own
// header-only MeshFileError, which the core catches by type across the module boundary.
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <string>

#include "io/assimp_plugin_abi.h"

namespace raycast {
namespace {

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

const AssimpPlugin kPlugin{kAssimpPluginAbiVersion, read_with_assimp};

}  // namespace
}  // namespace raycast

extern "C" __attribute__((visibility("default"))) const raycast::AssimpPlugin*
raycast_assimp_plugin() {
  return &raycast::kPlugin;
}
