#pragma once
// Whole images: pixels in 16x16 tiles over oneTBB, `samples` stratified jittered samples per
// pixel averaged in linear light (a box filter), each pixel's random numbers seeded by (x, y,
// scene seed) so that the result does not depend on the thread count.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "io/image.h"
#include "scene/scene.h"

namespace raycast {

/// The most worker threads a render may ask for (`--threads`; 0 means all cores).
inline constexpr int kMaxThreads = 4096;

/// The pixels [x0, x1) x [y0, y1) of the full image.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct RenderOptions {
  int width = 0;                         // > 0 overrides the scene's image.width
  int height = 0;                        // > 0 overrides image.height
  int spp = 0;                           // > 0 overrides image.samples
  std::optional<RenderMode> integrator;  // overrides render.integrator (not kAlbedo)
  std::optional<RenderMode> aov;         // render this extra output (--aov) instead
  int threads = 0;                       // > 0 caps the worker threads (tbb::global_control)
  /// Overrides render.antialias. Without it, spp > 0 renders fixed samples (no adaptive pass).
  std::optional<AntialiasSettings> antialias;
  bool progress = true;  // a progress bar on stderr, only when it is a terminal
  /// Render only this part of the full image (a tile of a distributed render): the result is
  /// the rectangle's size and each of its pixels is bit-identical to the whole render's.
  std::optional<PixelRect> region;
  /// When set and true, the render stops early and its image is incomplete (`raycast serve`
  /// restarts a pass when the scene or the view changes).
  const std::atomic<bool>* cancel = nullptr;
  /// Fixed samples and antialiasing method 1: trace the camera rays as packets where the scene
  /// allows it (render/camera_packets.h, render/antialias.h; the same image either way). False:
  /// one by one.
  bool camera_packets = true;
};

struct RenderStats {
  int width = 0, height = 0, spp = 0;  // spp: the fixed count (0 with adaptive antialiasing)
  AntialiasMethod antialias = AntialiasMethod::kNone;
  std::uint64_t samples = 0;  // camera samples traced
  int threads = 0;            // the parallelism allowed while rendering
  double seconds = 0;         // wall time of the pixel loop
  double cpu_seconds = 0;     // CPU time of the whole process (all threads) during the pixel loop
  std::uint64_t rays = 0;     // every scene query: primary, secondary and shadow rays
  double mrays_per_second() const { return seconds > 0 ? double(rays) / seconds * 1e-6 : 0; }
};

/// What the render computes: the AOV when there is one, else the integrator (options first).
inline RenderMode render_mode(const Scene& scene, const RenderOptions& options) {
  return options.aov.value_or(options.integrator.value_or(scene.render.integrator));
}

/// Renders the scene with its camera (or the default one). Throws SceneError when an image
/// texture cannot be loaded and std::invalid_argument for a non-positive override or a region
/// that is empty or not inside the image. Statistics describe the region when there is one.
Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr);

/// The one summary line: "800x600, 4 spp, 2 threads: 1.23 s (cpu 2.40 s), 9876543 rays,
/// 8.03 Mrays/s".
std::string format_summary(const RenderStats& stats);

/// The pixel position of sample k of n inside a pixel, in [0, 1)^2: the pixel is cut into an
/// sx x sy grid of strata (sx the largest divisor of n not above sqrt(n)) and sample k is jittered
/// inside stratum k. A single sample sits at the pixel centre.
void sample_offset(int k, int n, double jitter_x, double jitter_y, double& x, double& y);

}  // namespace raycast
