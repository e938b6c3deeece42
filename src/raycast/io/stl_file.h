#pragma once
// Our STL reader (docs/meshes.md): binary and ASCII.
#include <string>

#include "io/mesh_file.h"

namespace raycast {

/// Reads an STL file: binary when its size is exactly 84 + 50 * (the count at byte 80), else
/// ASCII (`solid` ... `facet normal` / `outer loop` / three `vertex x y z` / `endloop` /
/// `endfacet` ... `endsolid`). Corners at the same position become one vertex (STL repeats them
/// per facet), so smooth shading and closedness see the surface as connected; facet normals are
/// not used (they are often wrong). Throws MeshFileError: file:line:column for ASCII, the byte
/// count for a binary file of the wrong size.
MeshFileData read_stl_mesh(const std::string& path);

}  // namespace raycast
