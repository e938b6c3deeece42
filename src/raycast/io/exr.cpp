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
  const ExrPlugin* plugin = load_plugin<ExrPlugin>(
      "libraycast_openexr.so", "raycast_openexr_plugin", kExrPluginAbiVersion, why_not);
  if (!plugin) throw ImageError(path + ": cannot write EXR: " + why_not);
  plugin->save(image, path);
}

#else

bool have_exr() { return false; }

void save_exr(const Image&, const std::string& path) {
  throw ImageError(path + ": this build has no OpenEXR support; write .png or .pfm");
}

#endif

}  // namespace raycast
