// Light fading inside a transmissive object (Material::fade_distance, POV-Ray's interior fade):
// rays through a glass slab of known thickness against the closed forms, shadow rays through
// it, the POV-Ray reader's interior items and `raycast explain` against the render.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "load/loader.h"
#include "load/pov_loader.h"
#include "render/explain.h"
#include "render/integrator.h"
#include "render/renderer.h"

namespace raycast {
namespace {

// A slab 0.5 <= z <= 0.5 + kThickness of glass with ior 1 (rays pass straight) that neither
// reflects nor shows a surface colour of its own, in front of a background of known colour.
constexpr double kThickness = 1.5;
const Color kBackground{0.2, 0.4, 0.8};

std::string slab_scene(const std::string& fade) {
  return R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 10}
image: {width: 1, height: 1, samples: 1}
render: {background: [0.2, 0.4, 0.8], max_depth: 5, bailout: 0}
materials:
  glass: {color: [1, 1, 1], ambient: 0, diffuse: 0, specular: 0, transmission: 1, ior: 1, )" +
         fade + R"(}
objects:
  - box: {min: [-50, -50, 0.5], max: [50, 50, )" +
         std::to_string(0.5 + kThickness) + R"(]}
    material: glass
)";
}

Color through_slab(const Scene& scene) {
  const Integrator integrator(scene, RenderMode::kWhitted);
  SampleState state{Rng(1), 0};
  return integrator.whitted(Ray{{0, 0, 5}, {0, 0, -1}}, 0, state);
}

void expect_color(const Color& got, const Color& want, double tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

TEST(InteriorFade, SlabWithoutFade_PassesTheBackground) {
  expect_color(through_slab(load_scene_text(slab_scene(""))), kBackground, 1e-12);
}

TEST(InteriorFade, ClassicForm_IsOneOverOnePlusDistanceRatioToThePower) {
  // a = 1 / (1 + (1.5 / 0.75)^2) = 1 / 5; blended towards fade_color c: c + (1 - c) a.
  const Scene scene =
      load_scene_text(slab_scene("fade_distance: 0.75, fade_power: 2, fade_color: [0.5, 0.25, 0]"));
  const double a = 0.2;
  const Color c{0.5, 0.25, 0};
  const Color factor = c + a * (Color{1, 1, 1} - c);
  expect_color(factor, {0.6, 0.4, 0.2}, 1e-15);
  expect_color(through_slab(scene), mul(factor, kBackground), 1e-12);
}

TEST(InteriorFade, FadeDistance_IsWhereLightIsHalved) {
  const Scene scene = load_scene_text(slab_scene("fade_distance: 1.5, fade_power: 1"));
  expect_color(through_slab(scene), 0.5 * kBackground, 1e-12);
}

TEST(InteriorFade, PowerOf1000OrMore_IsExponential) {
  // exp(-(1 - c) d / fade_distance) per channel: d / fade_distance = 3.
  const Scene scene =
      load_scene_text(slab_scene("fade_distance: 0.5, fade_power: 1001, fade_color: [0, 0.5, 1]"));
  const Color factor{std::exp(-3.0), std::exp(-1.5), 1};
  expect_color(through_slab(scene), mul(factor, kBackground), 1e-12);
}

TEST(InteriorFade, ZeroPowerOrDistance_TurnsItOff) {
  expect_color(through_slab(load_scene_text(slab_scene("fade_distance: 0.75, fade_power: 0"))),
               kBackground, 1e-12);
  expect_color(through_slab(load_scene_text(slab_scene("fade_distance: 0, fade_power: 2"))),
               kBackground, 1e-12);
}

TEST(InteriorFade, ShadowRayThroughTheSlab_FadesByTheLengthInside) {
  // A segment from z = 3 to z = -1 crosses the whole slab: 1.5 inside, a = 1 / 5.
  const Scene scene = load_scene_text(slab_scene("fade_distance: 0.75, fade_power: 2"));
  const Integrator integrator(scene, RenderMode::kWhitted);
  SampleState state{Rng(1), 0};
  expect_color(integrator.shadow({0, 0, 3}, {0, 0, -1}, false, state), {0.2, 0.2, 0.2}, 1e-12);
  // From inside the slab (z = 1.25) to outside below: 0.75 inside, a = 1 / 2.
  expect_color(integrator.shadow({0, 0, 1.25}, {0, 0, -1}, false, state), {0.5, 0.5, 0.5}, 1e-12);
}

TEST(InteriorFade, ExplainedPixel_EqualsTheRender) {
  const Scene scene = load_scene_text(slab_scene("fade_distance: 0.75, fade_power: 2"));
  RenderOptions options;
  options.progress = false;
  const Image image = render(scene, options);
  ExplainOptions o;
  o.width = o.height = 1;
  const Explanation e = explain_pixel(scene, o);
  EXPECT_EQ(Vec3f(e.color).x, image.at(0, 0).x);
  EXPECT_EQ(e.root.radiance, e.color);
  expect_color(e.color, 0.2 * kBackground, 1e-6);
}

TEST(InteriorFade, PovInterior_GivesTheMaterialsFade) {
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text(
      "#declare I = interior { ior 1.5 fade_distance 2 fade_power 1001 }\n"
      "sphere { 0, 1 pigment { rgbf 1 } interior { I fade_color rgb <1, 0.5, 0> } }\n",
      "t.pov", ".", -1, {}, &warnings);
  ASSERT_EQ(s.objects.size(), 1u);
  const Material& m = s.materials[std::size_t(s.objects[0].material)];
  EXPECT_EQ(m.ior, 1.5);
  EXPECT_EQ(m.fade_distance, 2);
  EXPECT_EQ(m.fade_power, 1001);
  EXPECT_EQ(m.fade_color.x, 1);
  EXPECT_GT(m.fade_color.y, 0);  // linearised from the scene's gamma
  EXPECT_LE(m.fade_color.y, 0.5);
  EXPECT_EQ(m.fade_color.z, 0);
  for (const std::string& w : warnings) EXPECT_EQ(w.find("fade"), std::string::npos) << w;
}

TEST(InteriorFade, PovFinishFadeItems_AreKeptWhenTheInteriorHasNone) {
  const Scene s = load_pov_scene_text(
      "sphere { 0, 1 pigment { rgbf 1 } finish { fade_distance 3 fade_power 2 } }\n", "t.pov", ".",
      -1, {}, nullptr);
  const Material& m = s.materials[std::size_t(s.objects[0].material)];
  EXPECT_EQ(m.fade_distance, 3);
  EXPECT_EQ(m.fade_power, 2);
}

}  // namespace
}  // namespace raycast
