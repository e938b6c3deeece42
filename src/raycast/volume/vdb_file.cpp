#include "volume/vdb_file.h"

#include "io/plugin_library.h"
#include "volume/vdb_plugin_abi.h"

namespace raycast {
namespace {

#if RAYCAST_HAVE_OPENVDB
// The plugin, or nullptr with the reason: loaded once, on first use (io/plugin_library.h).
const VdbPlugin* plugin(std::string& why_not) {
  return load_plugin<VdbPlugin>("libraycast_openvdb.so", "raycast_openvdb_plugin",
                                kVdbPluginAbiVersion, why_not);
}
#endif

}  // namespace

bool vdb_supported() {
#if RAYCAST_HAVE_OPENVDB
  std::string why_not;
  return plugin(why_not) != nullptr;
#else
  return false;
#endif
}

std::string vdb_unsupported_reason() {
#if RAYCAST_HAVE_OPENVDB
  std::string why_not;
  plugin(why_not);
  return why_not;
#else
  return "this build of raycast cannot read OpenVDB files (built without libopenvdb-dev; "
         "docs/iso-surfaces.md)";
#endif
}

ScalarGrid read_vdb_grid(const std::string& path, const std::string& name) {
#if RAYCAST_HAVE_OPENVDB
  std::string why_not;
  if (const VdbPlugin* p = plugin(why_not)) return p->read(path, name, check_grid_fits);
  throw VdbUnsupportedError(why_not);
#else
  (void)path, (void)name;
  throw VdbUnsupportedError(vdb_unsupported_reason());
#endif
}

}  // namespace raycast
