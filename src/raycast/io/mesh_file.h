#pragma once
// Reading triangle meshes from files: OBJ, PLY (ascii, binary), STL, glTF/GLB.
#include <stdexcept>
#include <string>
#include <vector>

#include "io/triangle_soup.h"

namespace raycast {

/// A file that cannot be read as a mesh (missing, truncated, malformed, unsupported); what() says
/// why. The scene loader turns it into a SceneError at the `file` field.
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  /// "file:line:column: message", the position inside the mesh file (text formats, headers).
  MeshFileError(const std::string& path, int line, int column, const std::string& message)
      : std::runtime_error(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                           message) {}
};

/// What a mesh file holds: positions, triangles in file order (polygons fanned into triangles) and
/// the vertex normals when the file has them for every vertex (else empty).
struct MeshFileData {
  TriangleSoup soup;
  std::vector<Vec3f> normals;
};

/// Reads a mesh file by its extension. PLY (ASCII and binary, io/ply_file.cpp), OBJ
/// (io/obj_file.cpp) and STL (ASCII and binary, io/stl_file.cpp) are read by our own readers,
/// with errors naming the line and column; glTF/GLB go through assimp when the build has it. A
/// progress bar is drawn on stderr when it is a terminal and the file is large. Positions and
/// indices are returned as found: validation (finite values, indices in range) is make_mesh's.
MeshFileData load_mesh_file(const std::string& path);

/// Whether this build can read the extension (".obj", ".ply", ...; case-insensitive).
bool mesh_format_supported(const std::string& extension);

}  // namespace raycast
