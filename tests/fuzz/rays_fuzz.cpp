// libFuzzer target for the ray reader of `raycast cast`: the input (after a first byte that picks
// text or binary rays and the nearest / any / all query) is the ray stream; it must be answered
// or refused with SceneError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "cast/cast.h"
#include "io/scene_error.h"
#include "load/loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const raycast::Scene scene = raycast::load_scene_text(
      "objects:\n  - sphere: {radius: 1}\n  - box: {min: [2, -1, -1], max: [3, 1, 1]}\n"
      "  - plane: {normal: [0, 1, 0], point: [0, -2, 0]}\n",
      "fuzz.yaml");
  if (size < 1) return 0;
  raycast::CastOptions options;
  options.binary = data[0] & 1;
  options.mode = (data[0] >> 1) % 3 == 0   ? raycast::CastMode::kNearest
                 : (data[0] >> 1) % 3 == 1 ? raycast::CastMode::kAny
                                           : raycast::CastMode::kAll;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  std::ostringstream out;
  try {
    raycast::run_cast(scene, in, out, options);
  } catch (const raycast::SceneError& e) {
    if (e.line() < 0 || e.column() < 0) std::abort();
  }
  return 0;
}
