// libFuzzer target for the mesh file readers: the input (after a first byte that picks .ply,
// .obj or .stl) is written to a temporary file and read; it must load or throw MeshFileError,
// and a loaded mesh must build or be refused with SceneError by the scene's mesh validation.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "mesh/mesh_file.h"
#include "scene/loader.h"
#include "scene/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* kExtensions[] = {".ply", ".obj", ".stl"};
  const std::string path =
      "/tmp/raycast_mesh_fuzz_" + std::to_string(getpid()) + kExtensions[data[0] % 3];
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
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
