// libFuzzer target for the POV-Ray import (docs/pov-import.md): any input must load or throw a
// SceneError with a position, never crash or hang. #include resolves in tests/pov/scenes. Not
// built by default (needs clang's -fsanitize=fuzzer); see README.md in this folder.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/scene_error.h"
#include "load/pov_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    raycast::load_pov_scene_text(text, "fuzz.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes");
  } catch (const raycast::SceneError& e) {
    if (e.line() < 0 || e.column() < 0) std::abort();
  }
  // Any other exception escapes and libFuzzer reports it as a crash.
  return 0;
}
