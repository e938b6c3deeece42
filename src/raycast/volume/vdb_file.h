#pragma once
// OpenVDB float grids as iso-surface input (docs/iso-surfaces.md "From a grid"). Optional at build
// time like Embree: built when libopenvdb-dev was found (CMake option RAYCAST_OPENVDB), as the
// plugin libraycast_openvdb.so, loaded on the first .vdb read (io/plugin_library.h).
#include <stdexcept>
#include <string>

#include "volume/grid.h"

namespace raycast {

/// Whether this build reads OpenVDB files (built with them and the plugin loads).
bool vdb_supported();

/// Why not, when !vdb_supported(): a sentence for the user.
std::string vdb_unsupported_reason();

/// This build cannot read OpenVDB files (built without them, or the plugin does not load); the
/// message says why (the same sentence as vdb_unsupported_reason()).
class VdbUnsupportedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A problem with the grid asked for rather than with the file: no grid of that name (the
/// message lists the file's grids), not a float grid, a rotated or sheared or non-linear
/// transform, no active voxels. The scene loader points at the `name` field.
class VdbGridError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The float grid `name` of an OpenVDB file (its only float grid when `name` is empty), densified
/// over the box of its active voxels grown by one voxel on every side (those hold the grid's
/// background value). Node (i, j, k) of the result is the voxel whose centre the grid's
/// transform puts at lo + (i, j, k) * cell. Throws VolumeFileError when the file cannot be read,
/// VdbGridError (above), std::length_error (with the bytes needed) for a grid that does not fit
/// in memory, checked before allocating; VdbUnsupportedError when !vdb_supported().
ScalarGrid read_vdb_grid(const std::string& path, const std::string& name);

}  // namespace raycast
