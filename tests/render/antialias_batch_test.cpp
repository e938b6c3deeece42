// Method 1's batches (render/antialias.h RasterBatchSampler): the image, rays and samples are
// those of the one-sample-at-a-time passes, bit for bit: with a sampler that draws random numbers
// (so the order of each pixel's draws shows), a window, and through the renderer with camera-ray
// packets on a mesh scene with a sphere light, one and two threads.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "load/loader.h"
#include "mesh/procedural.h"
#include "render/antialias.h"
#include "render/renderer.h"
#include "scene/scene_packets.h"
#include "support/scene_text.h"

namespace raycast {
namespace {

TEST(AntialiasBatch, Method1_BatchesGiveTheOneByOneImage) {
  // Stripes with a value that depends on the sample's own random number: a pixel's value
  // changes if its draws come in another order.
  const RasterSampler sample = [](double x, double y, SampleState& state) {
    ++state.rays;
    const double u = state.rng.uniform();
    const double g = std::fmod(std::floor(x / 3) + std::floor(y / 2), 3.0) * 0.4 + 0.05 * u;
    return Color{g, 0.5 * g, 1 - g};
  };
  int batches = 0;
  const RasterBatchSampler batch = [&](const RasterSample* at, int count, Color* values) {
    ++batches;
    EXPECT_GE(count, 1);
    EXPECT_LE(count, kMaxRasterBatch);
    for (int i = count - 1; i >= 0; --i)  // any order
      values[i] = sample(at[i].x, at[i].y, *at[i].state);
  };
  const int w = 41, h = 13;
  for (const RasterWindow window : {RasterWindow{}, RasterWindow{3, 2, w, h}}) {
    for (int depth : {2, 3, 4}) {
      const int iw = window.full_width ? 30 : w, ih = window.full_height ? 9 : h;
      Image one(iw, ih), batched(iw, ih);
      AdaptiveStats one_stats, batched_stats;
      const AntialiasSettings aa{AntialiasMethod::kNeighbour, 0.3, depth};
      render_adaptive(aa, 7, sample, one, one_stats, nullptr, window);
      batches = 0;
      render_adaptive(aa, 7, sample, batched, batched_stats, nullptr, window, batch);
      EXPECT_GT(batches, 0);
      EXPECT_EQ(one.rgb, batched.rgb) << depth;
      EXPECT_EQ(one_stats.rays, batched_stats.rays) << depth;
      EXPECT_EQ(one_stats.samples, batched_stats.samples) << depth;
      EXPECT_GT(one_stats.samples, std::uint64_t(iw) * ih) << depth;  // some pixels refined
    }
  }
}

using testing::octa_sphere_entry;

TEST(AntialiasBatch, Method1_CameraPacketsGiveTheSingleRayImage) {
  // A sphere light (shading draws random numbers), a mirror mesh and a textured plane.
  const Scene scene = load_scene_text(
      testing::lit_scene_head(45, 29) +
      "  - {plane: {normal: [0, 1, 0], point: [0, -0.6, 0]}, material: floor}\n" +
      octa_sphere_entry(6, "    transform: [{translate: [-0.5, 0.4, 0]}]\n    material: mirror\n") +
      octa_sphere_entry(3,
                        "    transform: [{scale: 0.6}, {translate: [0.9, 1.0, -0.8]}]\n"
                        "    material: clay\n"));
  ASSERT_TRUE(ScenePackets(scene).usable());
  // Method 1 (both passes batched) and variance (its first pass).
  for (const AntialiasMethod method : {AntialiasMethod::kNeighbour, AntialiasMethod::kVariance}) {
    for (int threads : {1, 2}) {
      for (const auto& region :
           {std::optional<PixelRect>{}, std::optional(PixelRect{5, 3, 38, 20})}) {
        RenderOptions options;
        options.progress = false;
        options.threads = threads;
        options.region = region;
        options.antialias = AntialiasSettings{method, 0.2, 3};
        RenderStats single_stats, packet_stats;
        options.camera_packets = false;
        const Image single = render(scene, options, &single_stats);
        options.camera_packets = true;
        const Image packets = render(scene, options, &packet_stats);
        EXPECT_EQ(single.rgb, packets.rgb) << threads;  // bit-identical
        EXPECT_EQ(single_stats.rays, packet_stats.rays) << threads;
        EXPECT_EQ(single_stats.samples, packet_stats.samples) << threads;
        EXPECT_GT(single_stats.samples, std::uint64_t(single.width) * single.height);
      }
    }
  }
}

}  // namespace
}  // namespace raycast
