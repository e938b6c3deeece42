#pragma once
// The interface between the core and the OpenVDB plugin (libraycast_openvdb.so, built from
// plugins/openvdb_grid_reader.cpp). Both sides are built together from this header; the version
// number guards against a plugin of another build.
#include <array>
#include <cstdint>
#include <string>

#include "volume/grid.h"

namespace raycast {

inline constexpr int kVdbPluginAbiVersion = 1;

struct VdbPlugin {
  int abi_version;  // kVdbPluginAbiVersion of the plugin's build
  /// read_vdb_grid (volume/vdb_file.h) minus the memory check, which the plugin calls back
  /// through `check_fits` (grid.h's check_grid_fits) before it allocates the dense grid.
  ScalarGrid (*read)(const std::string& path, const std::string& name,
                     void (*check_fits)(const std::array<std::uint64_t, 3>&));
};

}  // namespace raycast

/// The plugin's one entry point.
extern "C" const raycast::VdbPlugin* raycast_openvdb_plugin();
