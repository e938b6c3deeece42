// The render's thread start-up (render() starts oneTBB's workers before its clock): renders
// under changing thread limits, and renders from several threads at once, give the one image.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "load/demo_scene.h"
#include "render/renderer.h"

namespace raycast {
namespace {

RenderOptions small_options(int threads, int spp) {
  RenderOptions options;
  options.width = 48;
  options.height = 32;
  options.spp = spp;
  options.progress = false;
  options.threads = threads;
  return options;
}

TEST(RenderThreads, ChangingThreadLimits_SameImageAndRays) {
  const Scene scene = load_demo_scene();
  for (int spp : {1, 2}) {
    RenderStats first_stats;
    const Image first = render(scene, small_options(1, spp), &first_stats);
    EXPECT_EQ(first_stats.threads, 1);
    for (int threads : {2, 3, 1, 0, 2}) {
      RenderStats stats;
      const Image image = render(scene, small_options(threads, spp), &stats);
      EXPECT_EQ(image.rgb, first.rgb) << "spp " << spp << ", threads " << threads;
      EXPECT_EQ(stats.rays, first_stats.rays);
      if (threads > 0) {
        EXPECT_EQ(stats.threads, threads);
      }
      EXPECT_GE(stats.seconds, 0);
      EXPECT_GE(stats.cpu_seconds, 0);
    }
  }
}

TEST(RenderThreads, RendersFromSeveralThreadsAtOnce_SameImage) {
  const Scene scene = load_demo_scene();
  const Image expected = render(scene, small_options(1, 1));
  std::vector<Image> images(4);
  std::vector<std::thread> callers;
  for (int i = 0; i < 4; ++i)
    callers.emplace_back([&, i] { images[i] = render(scene, small_options(1 + i % 2, 1)); });
  for (std::thread& t : callers) t.join();
  for (const Image& image : images) EXPECT_EQ(image.rgb, expected.rgb);
}

}  // namespace
}  // namespace raycast
