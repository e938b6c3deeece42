#pragma once
// Adaptive antialiasing (docs/rendering.md "Adaptive antialiasing"): POV-Ray's method 1
// (neighbour-threshold supersampling) and method 2 (recursive subdivision from the pixel's
// corners), and a variance-driven sampler. Every decision depends only on values traced with
// per-pixel seeded generators, so the image is the same for any thread count.
#include <cstdint>
#include <functional>

#include "io/image.h"
#include "render/integrator.h"
#include "scene/render_settings.h"

namespace raycast {

/// The value seen through raster position (x, y) (pixel (i, j) covers [i, i+1] x [j, j+1]),
/// tracing with the sample's random numbers and counting its rays in `state`.
using RasterSampler = std::function<Color(double x, double y, SampleState& state)>;

/// One sample of a batch: raster position (x, y), traced with *state's random numbers and
/// counting its rays there.
struct RasterSample {
  double x = 0, y = 0;
  SampleState* state = nullptr;
};

/// The most samples in one batch.
inline constexpr int kMaxRasterBatch = 16;

/// Traces samples[0..count) (count in [1, kMaxRasterBatch]), each as RasterSampler would, in
/// any order (no two share a state), into values[0..count): the renderer traces their camera
/// rays as packets where the scene allows it (render/camera_packets.h), and the pass pays one
/// call per batch rather than per sample.
using RasterBatchSampler =
    std::function<void(const RasterSample* samples, int count, Color* values)>;

/// The colour distance of the refinement tests: the sum over the three channels of the absolute
/// difference of the two colours as displayed, each linear channel turned into its 8-bit sRGB
/// code / 255 (clamped to [0, 1]; io/image.h linear_to_srgb8), so that thresholds act on what
/// the image shows.
double colour_distance(const Color& a, const Color& b);

struct AdaptiveStats {
  std::uint64_t rays = 0;     // every scene query, as SampleState counts them
  std::uint64_t samples = 0;  // camera samples traced
};

/// Where `image` sits in the full picture: its pixel (0, 0) is the full image's (x0, y0), and
/// the full image is full_width x full_height (0: the image's own size, i.e. the whole picture).
struct RasterWindow {
  int x0 = 0, y0 = 0, full_width = 0, full_height = 0;
};

/// Renders every pixel of `image` (its size) with `aa.method` (not kNone), `seed` the scene's.
/// `row_done` is called once per image row of each of the two passes (for progress reports).
/// With a window, `image` is that part of the full picture, each pixel bit-identical to the
/// full render's: the decisions that look at neighbours sample one pixel beyond the window.
/// Method 1 and the first pass of `variance` trace through `batch` when it is given (the same
/// image: every pixel draws its numbers in the same order), else through `sample`.
/// Throws std::invalid_argument for a threshold that is negative or not finite, a depth
/// outside [1, 16] or a window that does not fit in the full picture.
void render_adaptive(const AntialiasSettings& aa, unsigned seed, const RasterSampler& sample,
                     Image& image, AdaptiveStats& stats, const std::function<void()>& row_done,
                     const RasterWindow& window = {}, const RasterBatchSampler& batch = {});

}  // namespace raycast
