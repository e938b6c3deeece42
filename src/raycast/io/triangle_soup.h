#pragma once
// Triangles as read from a file or made in memory, before a mesh is built from them.
#include <array>
#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace raycast {

/// Positions and triangles (three indices into positions each, counter-clockwise seen from the
/// front), unvalidated: make_mesh checks them.
struct TriangleSoup {
  std::vector<Vec3f> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace raycast
