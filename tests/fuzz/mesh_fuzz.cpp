// libFuzzer target for our mesh file reader (binary PLY) and the mesh validation and BVH behind
// it: the input is written to a temporary .ply file and read; it must load or throw
// MeshFileError, and a loaded mesh must build or be refused with SceneError. Inputs in other
// formats (ASCII or big-endian PLY, which go to assimp) are skipped: assimp 5.2 hangs on some
// malformed files (see README.md), and it is not our code to fix.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

#include "mesh/mesh_file.h"
#include "scene/loader.h"
#include "scene/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kOurs = "format binary_little_endian ";
  const std::size_t format = text.find("format ");
  if (format == std::string_view::npos || text.substr(format, kOurs.size()) != kOurs) return 0;
  const std::string path = "/tmp/raycast_mesh_fuzz_" + std::to_string(getpid()) + ".ply";
  {
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  try {
    (void)raycast::load_mesh_file(path);
    // The same file through the scene: validation of indices and values, then the BVH.
    const raycast::Scene scene =
        raycast::load_scene_text("objects:\n  - mesh: {file: \"" + path + "\"}\n", "fuzz.yaml");
    raycast::Ray ray;
    ray.o = {0.1, 0.2, -10};
    ray.d = {0, 0, 1};
    raycast::SceneHit hit;
    (void)scene.intersect(ray, hit);
  } catch (const raycast::MeshFileError&) {
  } catch (const raycast::SceneError&) {
  }
  std::remove(path.c_str());
  return 0;
}
