#pragma once
// Our PLY mesh reader (docs/meshes.md): ASCII, binary little-endian and binary big-endian.
#include <string>

#include "io/mesh_file.h"

namespace raycast {

/// Reads the `vertex` element (x, y, z; nx, ny, nz when all three are there) and the `face`
/// element (its `vertex_indices` or `vertex_index` list, polygons fanned into triangles); other
/// elements and properties are skipped. Binary little-endian files, the usual form of big meshes,
/// are decoded in parallel from a memory map when every face is a triangle. Throws MeshFileError:
/// file:line:column for the header and ASCII bodies, the byte offset for binary bodies.
MeshFileData read_ply_mesh(const std::string& path);

}  // namespace raycast
