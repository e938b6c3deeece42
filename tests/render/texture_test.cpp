#include <gtest/gtest.h>

#include <filesystem>

#include "load/loader.h"
#include "render/integrator.h"
#include "render/texture.h"

namespace raycast {
namespace {

ImageTexture two_by_two() {
  ImageTexture t;
  t.image = Image(2, 2);
  t.image.set(0, 0, {1, 0, 0});  // top-left
  t.image.set(1, 0, {0, 1, 0});  // top-right
  t.image.set(0, 1, {0, 0, 1});  // bottom-left
  t.image.set(1, 1, {1, 1, 1});  // bottom-right
  return t;
}

TEST(ImageTexture, TexelCentres_GiveTheTexelsExactly) {
  const ImageTexture t = two_by_two();
  EXPECT_EQ(lookup(t, 0.25, 0.75), (Vec3{1, 0, 0}));  // v up: the top row is v in [0.5, 1)
  EXPECT_EQ(lookup(t, 0.75, 0.75), (Vec3{0, 1, 0}));
  EXPECT_EQ(lookup(t, 0.25, 0.25), (Vec3{0, 0, 1}));
  EXPECT_EQ(lookup(t, 0.75, 0.25), (Vec3{1, 1, 1}));
}

TEST(ImageTexture, BetweenTexels_InterpolatesBilinearlyAndWraps) {
  const ImageTexture t = two_by_two();
  const Vec3 mid = lookup(t, 0.5, 0.75);  // halfway between the two top texels
  EXPECT_DOUBLE_EQ(mid.x, 0.5);
  EXPECT_DOUBLE_EQ(mid.y, 0.5);
  const Vec3 wrapped = lookup(t, 0.0, 0.75);  // u = 0 sits between the last and first columns
  EXPECT_DOUBLE_EQ(wrapped.x, 0.5);
  EXPECT_EQ(lookup(t, 1.25, -0.25), lookup(t, 0.25, 0.75));
}

TEST(ImageTexture, FromAPngFile_ColoursTheSurface) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "raycast_texture_test.png").string();
  Image image(1, 1);
  image.set(0, 0, {0.2f, 0.4f, 0.8f});
  save_png(image, path);
  const Scene scene = load_scene_text(R"(
materials:
  t: {texture: {image: {file: )" + path +
                                      R"(}}}
objects:
  - sphere: {radius: 1}
    material: t
)");
  const Integrator integrator(scene, RenderMode::kAlbedo);
  SampleState state{Rng(1), 0};
  const Vec3 c = integrator.li({{0, 0, 5}, {0, 0, -1}}, state);
  EXPECT_NEAR(c.x, 0.2, 2e-3);  // 8-bit sRGB quantisation
  EXPECT_NEAR(c.y, 0.4, 2e-3);
  EXPECT_NEAR(c.z, 0.8, 3e-3);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace raycast
