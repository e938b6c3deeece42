#pragma once
// Pieces of scene files (docs/scene-format.md) written by the tests.
#include <sstream>
#include <string>

#include "mesh/procedural.h"

namespace raycast::testing {

/// An inline mesh entry of the scene format: a displaced octa-sphere (make_octa_sphere(n, 0.1)),
/// followed by `extra` (more keys of the entry, each line indented by four spaces).
inline std::string octa_sphere_entry(int n, const std::string& extra) {
  const TriangleSoup soup = make_octa_sphere(n, 0.1);
  std::ostringstream s;
  s.precision(9);
  s << "  - mesh:\n      vertices: [";
  for (std::size_t i = 0; i < soup.positions.size(); ++i)
    s << (i ? ", " : "") << "[" << soup.positions[i].x << ", " << soup.positions[i].y << ", "
      << soup.positions[i].z << "]";
  s << "]\n      triangles: [";
  for (std::size_t i = 0; i < soup.triangles.size(); ++i)
    s << (i ? ", " : "") << "[" << soup.triangles[i][0] << ", " << soup.triangles[i][1] << ", "
      << soup.triangles[i][2] << "]";
  s << "]\n" << extra;
  return s.str();
}

}  // namespace raycast::testing
