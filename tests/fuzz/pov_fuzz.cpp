// libFuzzer target for the POV-Ray interpreter and scene builder (docs/pov-import.md): any input
// must load or throw a SceneError with a position, never crash or hang. #include resolves in
// tests/pov/scenes (and POV-Ray's library folder when installed); no file is written, and the
// interpreter's bounds are lowered so that every input ends quickly. Not built by default
// (needs clang's -fsanitize=fuzzer); see README.md in this folder.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/scene_error.h"
#include "load/pov_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  raycast::pov::Options o;
  o.system_library_path = false;
  o.library_paths = {"/usr/share/povray-3.7/include"};
  o.file_output = false;
  o.limits.loop_iterations = 20000;
  o.limits.macro_depth = 64;
  o.limits.array_elements = 100000;
  o.limits.string_bytes = 1 << 16;
  o.limits.scene_weight = 2000000;
  o.limits.file_reads = 10000;
  std::vector<std::string> warnings;
  try {
    raycast::load_pov_scene_text(text, "fuzz.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes", -1, o,
                                 &warnings);
  } catch (const raycast::SceneError& e) {
    if (e.line() < 0 || e.column() < 0) std::abort();
  }
  // Any other exception escapes and libFuzzer reports it as a crash.
  return 0;
}
