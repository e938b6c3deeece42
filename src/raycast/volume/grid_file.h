#pragma once
// Reading density grids: raw little-endian float32 (x fastest) with a JSON sidecar
// {"dims": [nx, ny, nz], "min": [..], "max": [..], "type": "float32"} (docs/iso-surfaces.md).
#include <string>

#include "volume/grid.h"
#include "volume/volume_error.h"

namespace raycast {

/// The sidecar of NAME.raw: NAME.json.
std::string grid_sidecar_path(const std::string& raw_path);

/// Reads NAME.raw and its sidecar. Throws VolumeFileError at the sidecar's offending line and
/// column (bad JSON, a missing or bad field, an unknown key), at the raw file for a size that does
/// not match the dims or a value that is not finite, and refuses a grid that does not fit in
/// memory before allocating it (the message gives the bytes it needed).
ScalarGrid read_raw_grid(const std::string& raw_path);

}  // namespace raycast
