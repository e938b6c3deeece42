#include "io/image.h"

#if RAYCAST_HAVE_OPENEXR
#include "io/exr_plugin_abi.h"
#include "io/plugin_library.h"
#endif

namespace raycast {

#if RAYCAST_HAVE_OPENEXR

bool have_exr() { return true; }

// Through the OpenEXR plugin, loaded on the first .exr written (io/plugin_library.h).
void save_exr(const Image& image, const std::string& path) {
  std::string why_not;
  void* entry = plugin_symbol("libraycast_openexr.so", "raycast_openexr_plugin", why_not);
  if (!entry) throw ImageError(path + ": cannot write EXR: " + why_not);
  const ExrPlugin* plugin = reinterpret_cast<const ExrPlugin* (*)()>(entry)();
  if (!plugin || plugin->abi_version != kExrPluginAbiVersion)
    throw ImageError(path + ": the plugin libraycast_openexr.so is from another build of raycast");
  plugin->save(image, path);
}

#else

bool have_exr() { return false; }

void save_exr(const Image&, const std::string& path) {
  throw ImageError(path + ": this build has no OpenEXR support; write .png or .pfm");
}

#endif

}  // namespace raycast
