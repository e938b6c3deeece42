// libFuzzer target for our mesh file readers (PLY in its three encodings, OBJ, STL ASCII and
// binary) and the mesh validation and BVH behind them. The first byte picks the format ('P' PLY,
// 'O' OBJ, 'S' STL; anything else is skipped); the rest is written to a temporary file of that
// extension and read: it must load or throw MeshFileError, and a loaded mesh must build or be
// refused with SceneError. glTF (assimp's) is not fuzzed: assimp is not our code.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

#include "io/mesh_file.h"
#include "io/scene_error.h"
#include "load/loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char* ext = data[0] == 'P'   ? ".ply"
                    : data[0] == 'O' ? ".obj"
                    : data[0] == 'S' ? ".stl"
                                     : nullptr;
  if (!ext) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string path = "/tmp/raycast_mesh_fuzz_" + std::to_string(getpid()) + ext;
  {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  try {
    (void)raycast::load_mesh_file(path);
    // The same file through the scene: validation of indices and values, then the BVH.
    const raycast::Scene scene = raycast::load_scene_text(
        "objects:\n  - mesh: {file: \"" + path + "\", smooth: true}\n", "fuzz.yaml");
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
