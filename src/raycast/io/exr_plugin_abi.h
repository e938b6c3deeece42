#pragma once
// The interface between the core and the OpenEXR plugin (libraycast_openexr.so, built from
// plugins/openexr_image_writer.cpp; io/plugin_library.h). Both sides are built together from this
// header; the version number guards against a plugin of another build.
#include <string>

#include "io/image.h"

namespace raycast {

inline constexpr int kExrPluginAbiVersion = 1;

struct ExrPlugin {
  int abi_version;  // kExrPluginAbiVersion of the plugin's build
  /// save_exr (io/image.h); throws ImageError.
  void (*save)(const Image& image, const std::string& path);
};

}  // namespace raycast

/// The plugin's one entry point.
extern "C" const raycast::ExrPlugin* raycast_openexr_plugin();
