#pragma once
// One pixel's ray tree (`raycast explain`, docs/explain.md): the camera ray of one of the pixel's
// samples traced by the Whitted integrator with a recorder attached (render/ray_recorder.h), so
// every number comes from the code path that renders the image.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/ray_recorder.h"
#include "scene/scene.h"

namespace raycast {

/// A light's part of the direct term at a hit, with what its shadow ray met.
struct ExplainedLight {
  LightSample sample;
  std::int32_t blocker = -1;          // the nearest opaque object on the segment (scene index)
  double blocker_t = 0;               // its t along the segment
  Vec3 blocker_n;                     // its unit normal there (out of its solid)
  std::vector<std::int32_t> filters;  // transmissive objects the segment crosses (scene index)
};

/// A hit and the shading terms at it.
struct ExplainedHit {
  SceneHit hit;
  SurfaceInfo si;
  std::size_t material = 0;
  bool outside = true;  // the ray arrived from the outside (entering a solid)
  Vec3 n;               // the shading normal turned to face the viewer
  Color ambient;
  std::vector<ExplainedLight> lights;
};

/// One ray of the tree: kind, the ray, its recursion depth and the weight it carries of its
/// parent (1 for the camera ray), its hit (none on a miss), the split of its secondary rays and
/// their subtrees, its radiance.
struct ExplainedRay {
  RayKind kind = RayKind::kCamera;
  Ray ray;
  int depth = 0;
  double weight = 1;
  Color tint{1, 1, 1};  // what colours the ray's radiance in its parent's: a filter, a band
  std::optional<ExplainedHit> hit;
  bool split = false;  // whether the split below was reached (not at max depth, not a miss)
  double w_reflect = 0, w_refract = 0, fresnel = -1, bailout = 0;
  bool tir = false;
  RayStop stop = RayStop::kNone;
  Color radiance;
  std::vector<ExplainedRay> children;

  /// The shading terms by name, summing to `radiance` up to rounding: ambient, diffuse and
  /// specular (visible parts, all lights), reflection and refraction (weighted children), and
  /// background on a miss.
  Color diffuse() const;
  Color specular() const;
  Color reflection() const;
  Color refraction() const;
};

struct ExplainOptions {
  int x = 0, y = 0;                  // the pixel, x from the left and y from the top
  int sample = 0;                    // which of the pixel's samples, in [0, spp)
  int width = 0;                     // > 0 overrides image.width
  int height = 0;                    // > 0 overrides image.height
  int spp = 0;                       // > 0 overrides image.samples
  std::optional<CameraDesc> camera;  // overrides the scene's camera (`raycast serve`'s view)
};

struct Explanation {
  int x = 0, y = 0, sample = 0, spp = 1, width = 0, height = 0;
  Color color;  // the sample's linear colour: at 1 spp, the rendered pixel
  ExplainedRay root;
  std::uint64_t rays = 0;  // scene queries of the sample: camera, secondary and shadow rays
  double seconds = 0;      // wall time of explain_pixel (set-up, tracing, the shadow details)
};

/// Traces sample `options.sample` of the pixel as `render` does at fixed samples (the earlier
/// samples are traced to advance the pixel's random numbers) with the Whitted integrator, and
/// returns its tree. Throws std::invalid_argument for a pixel or sample outside the image and
/// SceneError when an image texture cannot be read.
Explanation explain_pixel(const Scene& scene, const ExplainOptions& options);

/// The kind's name: camera, reflection, refraction.
const char* ray_kind_name(RayKind kind);

}  // namespace raycast
