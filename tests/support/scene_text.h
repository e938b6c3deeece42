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

/// The head of a small Whitted scene, up to its `objects:` line: a perspective camera, a
/// width x height image at 1 sample, materials floor (checker), clay, mirror and glass, a point
/// light and a sphere light of 2 samples (shading draws random numbers).
inline std::string lit_scene_head(int width, int height) {
  return R"(camera: {type: perspective, position: [0, 1.6, -5], look_at: [0, 0.4, 0], up: [0, 1, 0], fov: 45}
image: {width: )" +
         std::to_string(width) + ", height: " + std::to_string(height) + R"(, samples: 1}
render: {integrator: whitted, max_depth: 4, background: [0.3, 0.4, 0.7], ambient: [0.1, 0.1, 0.1]}
materials:
  floor: {texture: {checker: {colors: [[0.9, 0.9, 0.85], [0.25, 0.3, 0.3]], scale: 0.5}}}
  clay: {color: [0.8, 0.45, 0.3], specular: 0.4, shininess: 50}
  mirror: {color: [0.9, 0.9, 0.9], reflection: 0.7, specular: 0.5, shininess: 80}
  glass: {color: [0.95, 0.97, 1.0], ambient: 0, diffuse: 0, specular: 0.8, shininess: 200, transmission: 0.9, ior: 1.5, fresnel: true}
lights:
  - {type: point, position: [-5, 8, -6], color: [1, 1, 1], intensity: 0.8}
  - {type: sphere, center: [4, 5, -3], radius: 0.6, samples: 2, color: [1, 1, 1], intensity: 0.5}
objects:
)";
}

}  // namespace raycast::testing
