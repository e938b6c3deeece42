// The `function` pattern: its value rule (kept up to 1, larger values wrapped, negative ones
// wrapped by the ramp), the YAML formula form, POV-Ray user functions and pigment functions with
// their components, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"
#include "load/pov_loader.h"
#include "math/formula.h"
#include "texture/pigment.h"

namespace raycast {
namespace {

texture::Pattern formula_pattern(const std::string& text) {
  texture::Pattern p = texture::make_pattern(texture::PatternKind::kFunction);
  p.function = texture::formula_function(compile_formula(text));
  return p;
}

TEST(FunctionPattern, KeepsValuesUpToOneAndWrapsTheRest) {
  const texture::Pattern p = formula_pattern("x");
  EXPECT_NEAR(texture::evaluate(p, {0.3, 0, 0}), 0.3, 1e-15);
  EXPECT_EQ(texture::evaluate(p, {1, 0, 0}), 1);                  // 1 stays 1
  EXPECT_NEAR(texture::evaluate(p, {2.25, 0, 0}), 0.25, 1e-12);   // fmod(v, 1) above 1
  EXPECT_NEAR(texture::evaluate(p, {-0.25, 0, 0}), 0.75, 1e-12);  // the ramp's wrap below 0
  EXPECT_EQ(texture::evaluate(formula_pattern("sqrt(x)"), {-1, 0, 0}), 0);  // NaN: 0
  // Moved like any pattern: scaled by 2, x = 1 reads 0.5.
  texture::Pattern q = formula_pattern("x");
  texture::transform_pattern(q, Transform::scale({2, 2, 2}));
  EXPECT_NEAR(texture::evaluate(q, {1, 0, 0}), 0.5, 1e-12);
}

std::string yaml_scene(const std::string& material) {
  return "camera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nmaterials:\n  m: " + material +
         "\nobjects:\n  - sphere: {center: [0, 0, 0], radius: 1}\n    material: m\n";
}

TEST(FunctionPattern, YamlFormula) {
  const Scene s = load_scene_text(yaml_scene(
      "{texture: {pattern: function, function: \"x * y\", colors: [[0, [0, 0, 0]], [1, [1, 1, "
      "1]]]}}"));
  const Material& m = s.materials[static_cast<std::size_t>(s.objects[0].material)];
  EXPECT_NEAR(texture::evaluate(m.texture->layers[0].pigment, {0.5, 0.8, 0}).rgb.x, 0.4, 1e-12);
  EXPECT_THROW(load_scene_text(yaml_scene("{texture: {pattern: function, function: \"x +\"}}")),
               SceneError);
  EXPECT_THROW(load_scene_text(yaml_scene("{texture: {pattern: function}}")), SceneError);
}

Scene load_pov(const std::string& text, std::vector<std::string>* warnings) {
  pov::Options o;
  o.system_library_path = false;
  return load_pov_scene_text(text, "t.pov", ".", -1, o, warnings);
}

TEST(FunctionPattern, PovUserAndPigmentFunctions) {
  std::vector<std::string> warnings;
  const Scene s = load_pov(
      "global_settings { assumed_gamma 1 }\n"
      "#declare F = function (a, b, c) { a * b }\n"
      "#declare P = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] "
      "} } }\n"
      "#declare C = P(0.4, 0, 0);\n"
      "#declare G = function { pattern { gradient y } }\n"
      "sphere { 0, 1 pigment { function { F(x, y, z) } } }\n"
      "sphere { 0, 1 pigment { function { P(x, y, z).green } } }\n"
      "sphere { 0, 1 pigment { function { P(x, y, z).gray + G(x, y, z) } } }\n"
      "sphere { 0, 1 pigment { rgb C } }\n"
      // POV-Ray's gamma macro of its example scenes: the average of three function patterns,
      // each channel's power mapped to three times that channel, gives the channel's power.
      "sphere { 0, 1 pigment { average pigment_map {\n"
      "  [function { pow(P(x, y, z).x, 2) } color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]\n"
      "  [function { pow(P(x, y, z).y, 2) } color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]\n"
      "  [function { pow(P(x, y, z).z, 2) } color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }] } } }\n",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(s.objects.size(), 5u);
  auto colour = [&](std::size_t i, const Vec3& p) {
    const Material& m = s.materials[static_cast<std::size_t>(s.objects[i].material)];
    return texture::evaluate(m.texture ? m.texture->layers[0].pigment : texture::Pigment{},
                             m.texture_transform.point(p));
  };
  EXPECT_NEAR(colour(0, {0.5, 0.6, 0}).rgb.x, 0.3, 1e-12);
  EXPECT_NEAR(colour(1, {0.4, 0, 0}).rgb.x, 0.2, 1e-12);
  EXPECT_NEAR(colour(2, {0.4, 0.1, 0}).rgb.x, 0.4 * (0.297 + 0.589 * 0.5 + 0.114 * 0.25) + 0.1,
              1e-12);
  const Material& plain = s.materials[static_cast<std::size_t>(s.objects[3].material)];
  EXPECT_NEAR(plain.color.y, 0.2, 1e-12);
  const texture::Rgbft g = colour(4, {0.4, 0, 0});
  EXPECT_NEAR(g.rgb.x, 0.4 * 0.4, 1e-12);
  EXPECT_NEAR(g.rgb.y, 0.2 * 0.2, 1e-12);
  EXPECT_NEAR(g.rgb.z, 0.1 * 0.1, 1e-12);
}

TEST(FunctionPattern, SplineFunctions) {
  // A linear spline function's point at t = x, and a cubic_spline's ends: its first and last
  // points only steer, the curve keeps the second and last but one points' values beyond them.
  std::vector<std::string> warnings;
  const Scene s = load_pov(
      "#declare L = function { spline { linear_spline 0, <0, 0, 0> 1, <1, 0.5, 0> } }\n"
      "#declare C = function { spline { cubic_spline -1, <9, 9, 9> 0, <0.2, 0, 0> 1, <0.8, 0, 0> "
      "2, <9, 9, 9> } }\n"
      "#declare A = C(-0.5, 0, 0);\n"
      "#declare B = C(1.5, 0, 0);\n"
      "sphere { 0, 1 pigment { function { L(x, 0, 0).y } } }\n"
      "sphere { 0, 1 pigment { rgb <A.x, B.x, 0> } }\n",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const Material& m = s.materials[static_cast<std::size_t>(s.objects[0].material)];
  EXPECT_NEAR(
      texture::evaluate(m.texture->layers[0].pigment, m.texture_transform.point({0.6, 0, 0})).rgb.x,
      0.3, 1e-12);
  const Material& ends = s.materials[static_cast<std::size_t>(s.objects[1].material)];
  EXPECT_NEAR(ends.color.x, 0.2, 1e-12);
  EXPECT_NEAR(ends.color.y, 0.8, 1e-12);
}

}  // namespace
}  // namespace raycast
