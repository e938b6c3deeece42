#include "io/mesh_file.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

#include "io/obj_file.h"
#include "io/ply_file.h"
#include "io/stl_file.h"

#ifdef RAYCAST_HAVE_ASSIMP
#include "io/assimp_plugin_abi.h"
#include "io/plugin_library.h"
#endif

namespace raycast {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

#ifdef RAYCAST_HAVE_ASSIMP
// glTF/GLB through the assimp plugin, loaded on the first such file (io/plugin_library.h).
MeshFileData read_with_assimp(const std::string& path) {
  std::string why_not;
  const AssimpPlugin* plugin = load_plugin<AssimpPlugin>(
      "libraycast_assimp.so", "raycast_assimp_plugin", kAssimpPluginAbiVersion, why_not);
  if (!plugin) throw MeshFileError("cannot read " + path + ": " + why_not);
  return plugin->read(path);
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
