// The built-in demo: its text matches scenes/demo.yaml, and it renders like the committed golden
// image (set RAYCAST_UPDATE_GOLDEN=1 to regenerate tests/golden/demo_64x48.png).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "io/image.h"
#include "load/demo_scene.h"
#include "render/renderer.h"

namespace raycast {
namespace {

const std::string kSourceDir = RAYCAST_SOURCE_DIR;
const std::string kGolden = kSourceDir + "/tests/golden/demo_64x48.png";

TEST(Demo, EmbeddedText_EqualsScenesDemoYaml) {
  std::ifstream in(kSourceDir + "/scenes/demo.yaml", std::ios::binary);
  ASSERT_TRUE(in) << "cannot open scenes/demo.yaml";
  const std::string file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(file, std::string(demo_scene_text()));
}

TEST(Demo, Loads_WithTheDocumentedContents) {
  const Scene scene = load_demo_scene();
  EXPECT_EQ(scene.source, "<demo>");
  EXPECT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.lights.size(), 1u);
  ASSERT_TRUE(scene.camera.has_value());
  // The floor lies inside a checker cell, never on a cell boundary (docs/rendering.md).
  const Plane& floor = std::get<Plane>(scene.objects[0].shape);
  const Material& m = scene.materials[scene.objects[0].material];
  ASSERT_TRUE(m.has_checker);
  const double cell = floor.offset / m.checker.scale;
  EXPECT_GT(std::abs(cell - std::round(cell)), 0.1);
}

/// 8-bit sRGB code values in [0, 255] as doubles, the units the golden tolerance is stated in.
double code(float linear) { return 255.0 * linear_to_srgb(linear); }

TEST(Demo, Render64x48_MatchesTheGoldenImage) {
  const Scene scene = load_demo_scene();
  RenderOptions options;
  options.width = 64;
  options.height = 48;
  options.progress = false;
  const Image image = render(scene, options);
  const char* update = std::getenv("RAYCAST_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    save_png(image, kGolden);
    GTEST_SKIP() << "regenerated " << kGolden;
  }
  const Image golden = load_png(kGolden);
  ASSERT_EQ(golden.width, 64);
  ASSERT_EQ(golden.height, 48);
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const double diff = std::abs(std::round(code(image.rgb[i])) - code(golden.rgb[i]));
    sum += diff;
    worst = std::max(worst, diff);
  }
  const double mean = sum / double(image.rgb.size());
  EXPECT_LT(mean, 1.0) << "mean abs difference in 8-bit units";
  EXPECT_LT(worst, 8.0) << "max abs difference in 8-bit units";
}

}  // namespace
}  // namespace raycast
