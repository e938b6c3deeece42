#pragma once
// Our Wavefront OBJ reader (docs/meshes.md).
#include <string>

#include "io/mesh_file.h"

namespace raycast {

/// Reads `v` (x y z, extra values such as colours ignored), `vn` and `f` statements: face corners
/// `i`, `i/t`, `i//n` or `i/t/n`, negative indices counting back from the last vertex, polygons
/// fanned into triangles. Vertex normals are returned when every face corner names one (a vertex
/// named with several normals gets their normalised sum; all are dropped, to be computed, when a
/// vertex ends with none or with normals that cancel). Statements that do not shape the
/// surface (vt, o, g, s, usemtl, mtllib, l, p, ...) are skipped. Throws MeshFileError naming
/// file:line:column (a bad number, an index of no vertex, a face of fewer than 3 corners).
MeshFileData read_obj_mesh(const std::string& path);

}  // namespace raycast
