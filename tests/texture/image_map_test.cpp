// Image maps: the projections of map_type against their closed forms, repetition and `once`,
// nearest and bilinear sampling, and the POV-Ray and YAML forms reading a PNG written here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "io/image.h"
#include "io/scene_error.h"
#include "load/loader.h"
#include "load/pov_loader.h"
#include "texture/pigment.h"

namespace raycast {
namespace {

using texture::ImageMap;
using texture::ImagePixel;

// 2 x 2: top row red, green; bottom row blue, white.
ImageMap two_by_two() {
  ImageMap m;
  m.width = m.height = 2;
  m.pixels = {{1, 0, 0, 0, 0}, {0, 1, 0, 0, 0}, {0, 0, 1, 0, 0}, {1, 1, 1, 0, 0}};
  return m;
}

texture::Pigment image_pigment(const ImageMap& m) {
  texture::Pigment p;
  p.kind = texture::Pigment::Kind::kImage;
  p.pattern = texture::make_pattern(texture::PatternKind::kImage);
  p.pattern.image = std::make_shared<const ImageMap>(m);
  return p;
}

TEST(ImageMap, PlanarNearestRepeatsAndOnceIsClear) {
  ImageMap m = two_by_two();
  texture::Pigment p = image_pigment(m);
  EXPECT_EQ(texture::evaluate(p, {0.25, 0.75, 3}).rgb, Vec3(1, 0, 0));  // top left, any z
  EXPECT_EQ(texture::evaluate(p, {0.75, 0.75, 0}).rgb, Vec3(0, 1, 0));
  EXPECT_EQ(texture::evaluate(p, {0.25, 0.25, 0}).rgb, Vec3(0, 0, 1));
  EXPECT_EQ(texture::evaluate(p, {-0.75, 2.25, 0}).rgb, Vec3(0, 0, 1));  // repeated
  m.once = true;
  p = image_pigment(m);
  EXPECT_EQ(texture::evaluate(p, {0.75, 0.25, 0}).rgb, Vec3(1, 1, 1));
  EXPECT_EQ(texture::evaluate(p, {1.5, 0.25, 0}).transmit, 1);  // clear outside its copy
  EXPECT_TRUE(texture::may_transmit(p));
}

TEST(ImageMap, BilinearBetweenPixelCentres) {
  ImageMap m = two_by_two();
  m.interpolate = true;
  double u = 0.25, v = 0.75;
  ImagePixel c = texture::image_sample(m, u, v);  // a pixel centre: the pixel
  EXPECT_NEAR(c.r, 1, 1e-6);
  EXPECT_NEAR(c.g, 0, 1e-6);
  c = texture::image_sample(m, 0.5, 0.5);  // the four centres' mean
  EXPECT_NEAR(c.r, 0.5, 1e-6);
  EXPECT_NEAR(c.g, 0.5, 1e-6);
  EXPECT_NEAR(c.b, 0.5, 1e-6);
  c = texture::image_sample(m, 0.5, 0.75);  // between red and green
  EXPECT_NEAR(c.r, 0.5, 1e-6);
  EXPECT_NEAR(c.g, 0.5, 1e-6);
  EXPECT_NEAR(c.b, 0, 1e-6);
  (void)u, (void)v;
}

TEST(ImageMap, SphericalAndCylindricalCoordinates) {
  ImageMap m = two_by_two();
  m.projection = texture::ImageProjection::kSpherical;
  double u = -1, v = -1;
  ASSERT_TRUE(texture::image_uv(m, {2, 0, 0}, u, v));
  EXPECT_NEAR(u, 0, 1e-12);
  EXPECT_NEAR(v, 0.5, 1e-12);
  ASSERT_TRUE(texture::image_uv(m, {0, 0, 3}, u, v));
  EXPECT_NEAR(u, 0.25, 1e-12);
  ASSERT_TRUE(texture::image_uv(m, {0, 0, -1}, u, v));
  EXPECT_NEAR(u, 0.75, 1e-12);
  ASSERT_TRUE(texture::image_uv(m, {1, 1, 0}, u, v));
  EXPECT_NEAR(v, 0.75, 1e-12);  // latitude 45 degrees
  ASSERT_TRUE(texture::image_uv(m, {-1, 0, 1}, u, v));
  EXPECT_NEAR(u, 0.375, 1e-12);
  EXPECT_FALSE(texture::image_uv(m, {0, 0, 0}, u, v));
  m.projection = texture::ImageProjection::kCylindrical;
  ASSERT_TRUE(texture::image_uv(m, {0, 0.3, 5}, u, v));
  EXPECT_NEAR(u, 0.25, 1e-12);
  EXPECT_NEAR(v, 0.3, 1e-12);
}

TEST(ImageMap, ImagePatternIsTheGrey) {
  texture::Pattern p = texture::make_pattern(texture::PatternKind::kImage);
  p.image = std::make_shared<const ImageMap>(two_by_two());
  EXPECT_NEAR(texture::evaluate(p, {0.75, 0.75, 0}), 0.589, 1e-6);  // green
  EXPECT_NEAR(texture::evaluate(p, {0.25, 0.75, 0}), 0.297, 1e-6);  // red
}

// A 3 x 1 PNG of linear values (0.25, 0.5, 1) in red, green, blue, written to a fresh folder.
std::filesystem::path write_png() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("raycast_image_map_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Image image(3, 1);
  image.set(0, 0, {0.25f, 0, 0});
  image.set(1, 0, {0, 0.5f, 0});
  image.set(2, 0, {0, 0, 1});
  save_png(image, (dir / "strip.png").string());
  return dir;
}

TEST(ImageMap, PovImageMapAndFunctionImage) {
  const auto dir = write_png();
  pov::Options o;
  o.system_library_path = false;
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text(
      "global_settings { assumed_gamma 1 }\n"
      "plane { z, 0 pigment { image_map { png \"strip.png\" once transmit all 0.25 } } }\n"
      "plane { z, 0 pigment { image_map { function 4, 4 { x } } } }\n"
      "plane { z, 0 pigment { image_map { png \"strip.png\" map_type 7 } } }\n"
      "plane { z, 0 normal { bump_map { png \"strip.png\" bump_size 3 } scale 2 } }\n",
      "t.pov", dir.string(), -1, o, &warnings);
  ASSERT_EQ(warnings.size(), 1u);  // map_type 7
  auto colour = [&](std::size_t i, const Vec3& p) {
    const Material& m = s.materials[static_cast<std::size_t>(s.objects[i].material)];
    return texture::evaluate(m.texture->layers[0].pigment, m.texture_transform.point(p));
  };
  // 8-bit sRGB codes read back in linear light: within one code's step.
  EXPECT_NEAR(colour(0, {0.1, 0.5, 0}).rgb.x, 0.25, 0.005);
  EXPECT_NEAR(colour(0, {0.5, 0.5, 0}).rgb.y, 0.5, 0.005);
  EXPECT_NEAR(colour(0, {0.9, 0.5, 0}).rgb.z, 1, 0.005);
  EXPECT_EQ(colour(0, {0.9, 0.5, 0}).transmit, 0.25f);
  EXPECT_EQ(colour(0, {1.5, 0.5, 0}).transmit, 1);
  EXPECT_NEAR(colour(1, {0.3, 0.5, 0}).rgb.x, 0.375, 1e-6);  // column 1's centre, x = 0.375
  // A bump map: the image's grey as the normal's pattern, its bump_size kept.
  const Material& bumped = s.materials[static_cast<std::size_t>(s.objects[3].material)];
  const texture::Normal& n = *bumped.texture->layers[0].normal;
  EXPECT_EQ(n.pattern.kind, texture::PatternKind::kImage);
  EXPECT_EQ(n.bump_size, 3);
  EXPECT_NEAR(texture::evaluate(n.pattern, bumped.texture_transform.point({1, 1, 0})), 0.589 * 0.5,
              0.005);  // x = 1 of the image scaled by 2: the green pixel
  EXPECT_THROW(load_pov_scene_text("plane { z, 0 pigment { image_map { png \"none.png\" } } }",
                                   "t.pov", dir.string(), -1, o, &warnings),
               SceneError);
  // The YAML form, relative to the scene's folder.
  const Scene y = load_scene_text(
      "camera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nmaterials:\n  m: {texture: {pattern: "
      "image_map, file: strip.png, once: true, scale: 2}}\nobjects:\n  - sphere: {center: [0, 0, "
      "0], radius: 1}\n"
      "    material: m\n",
      "t.yaml", dir.string());
  const Material& m = y.materials[static_cast<std::size_t>(y.objects[0].material)];
  EXPECT_NEAR(texture::evaluate(m.texture->layers[0].pigment, {1, 1, 0}).rgb.y, 0.5, 0.005);
  EXPECT_THROW(
      load_scene_text(
          "camera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nmaterials:\n "
          " m: {texture: {pattern: image_map, file: none.png}}\nobjects:\n  - sphere: {center: "
          "[0, 0, 0], radius: 1}\n    material: m\n",
          "t.yaml", dir.string()),
      SceneError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace raycast
