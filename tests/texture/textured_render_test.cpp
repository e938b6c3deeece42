// Textured materials through the Whitted integrator: the textured path agrees with the plain one
// where they mean the same, brilliance and colour maps give their formulas, and a tiny golden
// image of a gradient.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scene_error.h"
#include "load/loader.h"
#include "render/integrator.h"
#include "render/renderer.h"

namespace raycast {
namespace {

void expect_color(const Vec3& got, const Vec3& want, double tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// A unit sphere seen head-on: the ray from (0, 0, 5) hits (0, 0, 1) with n = v = (0, 0, 1); the
// light at (3, 0, 5) gives l = (0.6, 0, 0.8), N.L = 0.8, R.V = 0.8.
std::string sphere_scene(const std::string& material) {
  return R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 10}
image: {width: 1, height: 1, samples: 1}
render: {ambient: [0.1, 0.2, 0.3], background: [0, 0, 0]}
materials:
  m: )" + material +
         R"(
lights:
  - {type: point, position: [3, 0, 5], color: [1, 0.5, 0.25], intensity: 2}
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
    material: m
)";
}

Vec3 centre(const Scene& scene) {
  SampleState state{Rng(1), 0};
  const Integrator integrator(scene, RenderMode::kWhitted);
  return integrator.whitted({{0, 0, 5}, {0, 0, -1}}, 0, state);
}

TEST(TexturedRender, BrillianceOneMatchesThePlainPath) {
  const std::string plain =
      "{color: [0.5, 0.6, 0.7], ambient: 0.5, diffuse: 0.7, specular: 0.3, shininess: 10}";
  const std::string textured =
      "{color: [0.5, 0.6, 0.7], ambient: 0.5, diffuse: 0.7, specular: 0.3, shininess: 10, "
      "brilliance: 1}";
  const Scene a = load_scene_text(sphere_scene(plain));
  const Scene b = load_scene_text(sphere_scene(textured));
  ASSERT_FALSE(a.materials[1].texture);
  ASSERT_TRUE(b.materials[1].texture);
  expect_color(centre(b), centre(a), 1e-12);
}

TEST(TexturedRender, BrillianceRaisesTheDiffuseCosine) {
  const Scene s = load_scene_text(
      sphere_scene("{color: [0.5, 0.6, 0.7], ambient: 0.5, diffuse: 0.7, brilliance: 3}"));
  const Vec3 c{0.5, 0.6, 0.7}, e{2, 1, 0.5};
  const Vec3 want = 0.5 * mul(Vec3{0.1, 0.2, 0.3}, c) + mul(e, 0.7 * std::pow(0.8, 3) * c);
  expect_color(centre(s), want, 1e-12);
}

TEST(TexturedRender, BlinnAndMetallicHighlight) {
  // N.H with h = (l + v) / |l + v| = (0.6, 0, 1.8) / sqrt(3.6): N.H = 1.8 / sqrt(3.6).
  const Scene s = load_scene_text(sphere_scene(
      "{color: [0.5, 0.6, 0.7], ambient: 0, diffuse: 0, blinn: 0.4, roughness: 0.1, metallic: 1}"));
  const double h = 0.4 * std::pow(1.8 / std::sqrt(3.6), 10);
  expect_color(centre(s), h * mul(Vec3{2, 1, 0.5}, Vec3{0.5, 0.6, 0.7}), 1e-12);
}

TEST(TexturedRender, ColorMapAtTheHitPoint) {
  // gradient z at the hit z = 1: value frac(1 * 0.25 / 1)... scaled by 4: z / 4 = 0.25.
  const Scene s = load_scene_text(sphere_scene(
      "{texture: {pattern: gradient, direction: [0, 0, 1], scale: 4, colors: [[0, [0, 0, 0]], "
      "[1, [1, 1, 1]]]}, ambient: 1, diffuse: 0}"));
  expect_color(centre(s), 0.25 * Vec3{0.1, 0.2, 0.3}, 1e-12);
}

TEST(TexturedRender, LayeredTextureShowsTheLowerLayerThroughTransmit) {
  const Scene s = load_scene_text(sphere_scene(
      "{color: [1, 0, 0], ambient: 1, diffuse: 0, layers: [{texture: {color: [0, 0, 1, 0, 0.25]}, "
      "ambient: 1, diffuse: 0}]}"));
  expect_color(centre(s), mul(Vec3{0.1, 0.2, 0.3}, Vec3{0.25, 0, 0.75}), 1e-12);
}

TEST(TexturedRender, GoldenGradientImage) {
  // An orthographic view 8 units wide of a plane at z = 0, lit by ambient light only: each
  // pixel is the colour map at x, the gradient's value frac(x / 4) with x the pixel centre.
  const Scene s = load_scene_text(R"(
camera: {type: orthographic, position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], height: 1}
image: {width: 8, height: 1, samples: 1}
render: {ambient: [1, 1, 1], background: [0, 0, 0]}
materials:
  g: {texture: {pattern: gradient, scale: 4, colors: [[0, [0, 0, 0]], [1, [1, 0.5, 0.25]]]}, ambient: 1, diffuse: 0}
objects:
  - plane: {normal: [0, 0, 1], point: [0, 0, 0]}
    material: g
)");
  RenderOptions options;
  options.progress = false;
  const Image image = render(s, options);
  ASSERT_EQ(image.width, 8);
  for (int i = 0; i < 8; ++i) {
    const double x = -4 + (i + 0.5);  // pixel centres across the 8-unit width
    const double v = x / 4 - std::floor(x / 4);
    expect_color(Vec3(image.at(i, 0)), Vec3{v, 0.5 * v, 0.25 * v}, 1e-6);
  }
}

TEST(TexturedRender, UnknownPatternIsAPositionedError) {
  try {
    load_scene_text(sphere_scene("{texture: {pattern: plaid}}"));
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("no pattern named 'plaid'"), std::string::npos);
    EXPECT_GT(e.line(), 0);
  }
}

}  // namespace
}  // namespace raycast
