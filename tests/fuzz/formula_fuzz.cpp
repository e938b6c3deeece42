// libFuzzer target for the equation and function parsers and the solvers behind them: the input
// (after a first byte that picks `algebraic` or `implicit`) is the formula of a shape in a scene,
// which must load or throw SceneError; loaded shapes then answer a fixed fan of rays.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"

namespace {

// The input as a YAML double-quoted scalar: every byte survives, none can end the string early.
std::string quoted(const std::uint8_t* data, std::size_t size) {
  static const char* hex = "0123456789abcdef";
  std::string s = "\"";
  for (std::size_t i = 0; i < size; ++i) {
    const unsigned char c = data[i];
    if (c == '"' || c == '\\' || c < 0x20 || c >= 0x7f) {
      s += "\\x";
      s += hex[c >> 4];
      s += hex[c & 15];
    } else {
      s += static_cast<char>(c);
    }
  }
  return s + "\"";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 512) return 0;
  const bool algebraic = data[0] & 1;
  const std::string text = std::string("objects:\n  - ") +
                           (algebraic ? "algebraic: {equation: " : "implicit: {function: ") +
                           quoted(data + 1, size - 1) +
                           ", bounds: {min: [-2, -2, -2], max: [2, 2, 2]}}\n";
  raycast::Scene scene;
  try {
    scene = raycast::load_scene_text(text, "fuzz.yaml");
  } catch (const raycast::SceneError& e) {
    if (e.line() < 0 || e.column() < 0) std::abort();
    return 0;
  }
  std::vector<raycast::Crossing> crossings;
  for (int k = 0; k < 8; ++k) {
    raycast::Ray ray;
    ray.o = {-3.0 + 0.1 * k, 0.3 * k - 1.0, -3.0};
    ray.d = {1, 0.05 * k, 1};
    raycast::SceneHit hit;
    if (scene.intersect(ray, hit)) (void)scene.surface(ray, hit);
    (void)scene.occluded(ray);
    scene.intersect_all(ray, crossings);
  }
  return 0;
}
