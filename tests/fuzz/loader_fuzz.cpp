// libFuzzer target for the scene loader: any input must load or throw a SceneError. Not built by
// default (needs clang's -fsanitize=fuzzer); see README.md in this folder.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/scene_error.h"
#include "load/loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    raycast::load_scene_text(text, "fuzz.yaml", RAYCAST_SOURCE_DIR "/scenes");
  } catch (const raycast::SceneError& e) {
    if (e.line() < 0 || e.column() < 0) std::abort();
  }
  // Any other exception escapes and libFuzzer reports it as a crash.
  return 0;
}
