#pragma once
// The interface between the core and the assimp plugin (libraycast_assimp.so, built from
// plugins/assimp_mesh_reader.cpp; io/plugin_library.h). Both sides are built together from this
// header; the version number guards against a plugin of another build.
#include <string>

#include "io/mesh_file.h"

namespace raycast {

inline constexpr int kAssimpPluginAbiVersion = 1;

struct AssimpPlugin {
  int abi_version;  // kAssimpPluginAbiVersion of the plugin's build
  /// A glTF/GLB file's triangles and normals; throws MeshFileError.
  MeshFileData (*read)(const std::string& path);
};

}  // namespace raycast

/// The plugin's one entry point.
extern "C" const raycast::AssimpPlugin* raycast_assimp_plugin();
