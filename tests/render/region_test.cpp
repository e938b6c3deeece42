// RenderOptions::region (the tiles of a distributed render): a render cut into regions and
// stitched back is bit-identical to the whole render, for fixed samples and every adaptive
// method (whose neighbour tests read one pixel beyond the region).
#include <gtest/gtest.h>

#include <stdexcept>

#include "load/demo_scene.h"
#include "render/renderer.h"

namespace raycast {
namespace {

/// Renders the image as regions of tile_w x tile_h (ragged at the right and bottom edges) and
/// copies each into place.
Image stitched(const Scene& scene, RenderOptions options, int tile_w, int tile_h) {
  Image out(options.width, options.height);
  for (int y0 = 0; y0 < options.height; y0 += tile_h) {
    for (int x0 = 0; x0 < options.width; x0 += tile_w) {
      const PixelRect r{x0, y0, std::min(options.width, x0 + tile_w),
                        std::min(options.height, y0 + tile_h)};
      options.region = r;
      const Image part = render(scene, options);
      EXPECT_EQ(part.width, r.x1 - r.x0);
      EXPECT_EQ(part.height, r.y1 - r.y0);
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) out.set(x, y, part.at(x - r.x0, y - r.y0));
    }
  }
  return out;
}

RenderOptions small() {
  RenderOptions options;
  options.width = 37;  // not a multiple of the tiles: ragged edges
  options.height = 29;
  options.progress = false;
  return options;
}

TEST(RenderRegion, FixedSamples_StitchedRegionsEqualTheWholeImage) {
  const Scene scene = load_demo_scene();
  RenderOptions options = small();
  options.spp = 3;
  const Image whole = render(scene, options);
  EXPECT_EQ(stitched(scene, options, 16, 16).rgb, whole.rgb);
  EXPECT_EQ(stitched(scene, options, 7, 5).rgb, whole.rgb);
  EXPECT_EQ(stitched(scene, options, 37, 1).rgb, whole.rgb);  // rows
}

TEST(RenderRegion, EveryAdaptiveMethod_StitchedRegionsEqualTheWholeImage) {
  const Scene scene = load_demo_scene();
  for (auto method :
       {AntialiasMethod::kNeighbour, AntialiasMethod::kSubdivide, AntialiasMethod::kVariance}) {
    RenderOptions options = small();
    options.antialias = AntialiasSettings{method, 0.05, 3};
    const Image whole = render(scene, options);
    EXPECT_EQ(stitched(scene, options, 8, 8).rgb, whole.rgb) << int(method);
    EXPECT_EQ(stitched(scene, options, 1, 29).rgb, whole.rgb) << int(method);  // columns
  }
}

TEST(RenderRegion, EmptyOrOutsideRegion_Throws) {
  const Scene scene = load_demo_scene();
  RenderOptions options = small();
  options.spp = 1;
  for (const PixelRect r : {PixelRect{0, 0, 0, 5}, PixelRect{-1, 0, 4, 4}, PixelRect{0, 0, 38, 4},
                            PixelRect{0, 25, 4, 30}, PixelRect{5, 5, 4, 6}}) {
    options.region = r;
    EXPECT_THROW(render(scene, options), std::invalid_argument);
  }
}

}  // namespace
}  // namespace raycast
