#pragma once
// Reading particle positions: PLY (ascii, binary little or big endian; vertex x, y, z of any
// numeric type), CSV and whitespace-separated .xyz (x y z per line; a first line that is not
// numbers is a header, and a CSV header naming x, y and z picks those columns).
#include <string>
#include <vector>

#include "math/vec3.h"
#include "volume/volume_error.h"

namespace raycast {

/// Whether the extension (".ply", ".csv", ".xyz"; case-insensitive) is a particle format.
bool particle_format_supported(const std::string& extension);

/// The particle positions in file order. Throws VolumeFileError at the offending line and column
/// for a missing, malformed or truncated file, a value that is not a finite number, or a file
/// without particles.
std::vector<Vec3> read_particles(const std::string& path);

}  // namespace raycast
