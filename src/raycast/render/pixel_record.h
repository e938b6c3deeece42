#pragma once
// Renders that also take the image apart per pixel through a RayRecorder (render/ray_recorder.h):
// the Whitted terms of the camera ray's hit (docs/rendering.md "Term outputs"), what each pixel
// cost (rays, depth, time: "Cost outputs") and the rays cast by kind (`render --stats`).
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "io/image.h"
#include "render/ray_recorder.h"
#include "render/renderer.h"

namespace raycast {

/// The outputs a recorded render can write beside the image.
enum class RecordedOutput {
  kAmbient,     // ambient term of the camera ray's hit
  kDiffuse,     // direct diffuse term (all lights, after their shadow rays)
  kSpecular,    // direct Phong highlight
  kReflection,  // the mirror ray's weighted radiance
  kRefraction,  // the refracted ray's weighted radiance
  kShadowed,    // the fraction of the direct light (sum of the lights' terms) that shadows remove
  kCostRays,    // scene queries per pixel: camera, secondary and shadow rays
  kCostDepth,   // the deepest secondary ray of the pixel (0: camera rays only)
  kCostTime,    // wall time of the pixel, in microseconds
};

/// The outputs' names as `--aov` takes them: ambient, diffuse, specular, reflection, refraction,
/// shadowed, cost.rays, cost.depth, cost.time.
std::optional<RecordedOutput> recorded_output_named(std::string_view name);
const char* recorded_output_name(RecordedOutput output);
/// For messages: the list above.
inline constexpr const char* kRecordedOutputNames =
    "ambient, diffuse, specular, reflection, refraction, shadowed, cost.rays, cost.depth, "
    "cost.time";

struct RecordedRender {
  Image image;                 // the beauty image, as render() gives it at fixed samples
  std::vector<Image> outputs;  // one per requested output, in order (grey: r = g = b)
  RayCounts counts;
};

/// Renders the scene with the Whitted integrator at fixed samples per pixel (the scene's
/// adaptive antialiasing is not used), one ray at a time with a recorder per sample, and fills
/// the requested outputs (averaged over the pixel's samples). The ambient, diffuse, specular,
/// reflection and refraction outputs sum to the image (up to float rounding). Statistics as
/// render()'s. Throws as render() does.
RecordedRender render_recorded(const Scene& scene, const RenderOptions& options,
                               const std::vector<RecordedOutput>& outputs,
                               RenderStats* stats = nullptr);

}  // namespace raycast
