// POV-Ray textures through the interpreter and the loader: the material each snippet makes, the
// transformation rule, layers, declared normals, the standard include files' textures.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "load/pov_loader.h"
#include "pov/interpreter.h"

namespace raycast {
namespace {

// The scene and its warnings; the camera's default right vector makes POV-Ray's frame
// left-handed, so raycast mirrors z: the snippets keep z = 0 where it matters.
Scene load(const std::string& text, std::vector<std::string>* warnings = nullptr) {
  pov::Options o;
  o.system_library_path = false;
  std::vector<std::string> local;
  return load_pov_scene_text(text, "t.pov", ".", -1, o, warnings ? warnings : &local);
}

const Material& material_of_object(const Scene& s, std::size_t i) {
  return s.materials[static_cast<std::size_t>(s.objects[i].material)];
}

// The bottom layer's pigment at an object-space point, through the material's transform.
texture::Rgbft pigment_at(const Material& m, const Vec3& object_point, std::size_t layer = 0) {
  return texture::evaluate(m.texture->layers[layer].pigment,
                           m.texture_transform.point(object_point));
}

TEST(PovTexture, GradientWithColourMapAndFinish) {
  std::vector<std::string> warnings;
  const Scene s = load(
      "sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } } "
      "finish { brilliance 2 metallic crand 0.1 phong 0.5 } }",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const Material& m = material_of_object(s, 0);
  ASSERT_TRUE(m.texture);
  ASSERT_EQ(m.texture->layers.size(), 1u);
  const texture::TextureLayer& l = m.texture->layers[0];
  EXPECT_EQ(l.pigment.pattern.kind, texture::PatternKind::kGradient);
  EXPECT_EQ(l.finish.brilliance, 2);
  EXPECT_EQ(l.finish.metallic, 1);
  EXPECT_EQ(l.finish.crand, 0.1);
  EXPECT_EQ(l.finish.phong, 0.5);
  const texture::Rgbft c = pigment_at(m, {0.25, 0.3, 0});
  EXPECT_NEAR(c.rgb.x, 0.25, 1e-12);
  EXPECT_NEAR(c.rgb.y, 0.125, 1e-12);
}

TEST(PovTexture, TransformsAfterTheTextureMoveItWithTheObject) {
  // Written after the pigment, the translation moves the pattern with the sphere: the object's
  // own point x = 0.1 keeps the value 0.1. Written before, the pattern stays in the world: the
  // same surface point is at world x = 0.35.
  const Scene after = load("sphere { 0, 1 pigment { gradient x } translate <0.25, 0, 0> }");
  const Scene before = load("sphere { 0, 1 translate <0.25, 0, 0> pigment { gradient x } }");
  const Material& a = material_of_object(after, 0);
  const Material& b = material_of_object(before, 0);
  // The sphere's own (object-space) point (0.1, 0, 0) in each: raycast keeps the centre in the
  // shape and the translation in the object's transform, or builds it into the centre.
  const Object& oa = after.objects[0];
  const Vec3 pa = oa.xf ? oa.xf->inverse_point({0.35, 0, 0}) : Vec3{0.35, 0, 0};
  const Object& ob = before.objects[0];
  const Vec3 pb = ob.xf ? ob.xf->inverse_point({0.35, 0, 0}) : Vec3{0.35, 0, 0};
  EXPECT_NEAR(pigment_at(a, pa).rgb.x, 0.1, 1e-12);
  EXPECT_NEAR(pigment_at(b, pb).rgb.x, 0.35, 1e-12);
}

TEST(PovTexture, TransformsInsideTheTextureMoveOnlyTheTexture) {
  const Scene s = load("sphere { 0, 1 texture { pigment { gradient x } scale 2 } }");
  EXPECT_NEAR(pigment_at(material_of_object(s, 0), {0.5, 0, 0}).rgb.x, 0.25, 1e-12);
  const Scene p = load("sphere { 0, 1 pigment { gradient x rotate <0, 0, 90> } }");
  // gradient x turned onto y: the value follows y.
  EXPECT_NEAR(pigment_at(material_of_object(p, 0), {0, 0.3, 0}).rgb.x, 0.3, 1e-9);
}

TEST(PovTexture, LayeredTexturesAndDeclaredNormal) {
  std::vector<std::string> warnings;
  const Scene s = load(
      "#declare N = normal { bumps 0.4 scale 0.2 }\n"
      "#declare T = texture { pigment { rgb 1 } } texture { pigment { bozo color_map { "
      "[0 rgbt 1] [1 rgb 0] } } normal { N } }\n"
      "sphere { 0, 1 texture { T } texture { pigment { rgbf <1, 0, 0, 0.5> } } }",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const Material& m = material_of_object(s, 0);
  ASSERT_TRUE(m.texture);
  ASSERT_EQ(m.texture->layers.size(), 3u);
  EXPECT_EQ(m.texture->layers[1].pigment.pattern.kind, texture::PatternKind::kBozo);
  ASSERT_TRUE(m.texture->layers[1].normal);
  EXPECT_EQ(m.texture->layers[1].normal->bump_size, 0.4);
  EXPECT_EQ(m.texture->layers[2].pigment.color.filter, 0.5);
}

TEST(PovTexture, CheckerOfPigmentsAndTurbulence) {
  std::vector<std::string> warnings;
  const Scene s = load(
      "plane { y, 0 pigment { checker pigment { rgb <1, 0, 0> } pigment { marble turbulence 0.5 "
      "octaves 3 color_map { [0 rgb 0] [1 rgb 1] } } } }\n"
      "sphere { 0, 1 pigment { wood warp { turbulence <0.1, 0.2, 0> } sine_wave frequency 2 } }",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const texture::Pigment& p = material_of_object(s, 0).texture->layers[0].pigment;
  EXPECT_EQ(p.kind, texture::Pigment::Kind::kPigmentMap);
  ASSERT_EQ(p.pigment_map.size(), 2u);
  EXPECT_EQ(p.pigment_map[1].pigment->pattern.turbulence.octaves, 3);
  const texture::Pattern& w = material_of_object(s, 1).texture->layers[0].pigment.pattern;
  EXPECT_EQ(w.wave, texture::WaveForm::kSine);
  EXPECT_EQ(w.frequency, 2);
  ASSERT_EQ(w.steps.size(), 1u);
  EXPECT_EQ(w.steps[0].warp.amount.y, 0.2);
}

TEST(PovTexture, PlainTexturesKeepThePlainPath) {
  const Scene s = load(
      "sphere { 0, 1 pigment { rgb 1 } finish { phong 0.5 } }\n"
      "plane { y, 0 pigment { checker rgb 1, rgb 0 scale 2 } }");
  EXPECT_FALSE(material_of_object(s, 0).texture);
  EXPECT_FALSE(material_of_object(s, 1).texture);
  EXPECT_TRUE(material_of_object(s, 1).has_checker);
}

TEST(PovTexture, PatternedTexturesPickAndBlendWholeTextures) {
  std::vector<std::string> warnings;
  const Scene s = load(
      "sphere { 0, 1 texture { checker texture { pigment { rgb <1, 0, 0> } } "
      "texture { pigment { rgb <0, 0, 1> } finish { phong 1 } } } }\n"
      "sphere { 0, 1 texture { gradient x texture_map { [0 pigment { rgb 0 }] "
      "[1 pigment { rgb 1 } finish { ambient 0.5 }] } scale 2 } }",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const Material& checker = material_of_object(s, 0);
  ASSERT_TRUE(checker.texture && checker.texture->map_pattern);
  ASSERT_EQ(checker.texture->map.size(), 2u);
  texture::TextureContext ctx;
  ctx.p = checker.texture_transform.point({0.5, 0.5, 0});
  EXPECT_NEAR(texture::pigment_color(*checker.texture, ctx.p).x, 1, 1e-12);
  ctx.p = checker.texture_transform.point({1.5, 0.5, 0});
  EXPECT_NEAR(texture::pigment_color(*checker.texture, ctx.p).z, 1, 1e-12);
  EXPECT_EQ(texture::evaluate(*checker.texture, ctx).finish.phong, 1);
  // The map blends: gradient x scaled by 2 is 0.25 at x = 0.5.
  const Material& map = material_of_object(s, 1);
  ctx.p = map.texture_transform.point({0.5, 0.3, 0});
  EXPECT_NEAR(texture::pigment_color(*map.texture, ctx.p).y, 0.25, 1e-12);
  EXPECT_NEAR(texture::evaluate(*map.texture, ctx).ambient.y, 0.25 * 0.5 + 0.75 * 0, 1e-12);
}

TEST(PovTexture, FormsTheTextureSystemDoesNotModelStillRead) {
  // `metallic on`, an average map whose entries have no values, a normal made of a pigment
  // pattern with its bump size after a comma, a warp other than turbulence.
  std::vector<std::string> warnings;
  const Scene s = load(
      "sphere { 0, 1 finish { metallic on } }\n"
      "sphere { 0, 1 pigment { average pigment_map { [function { x } color_map { [0 rgb 0] "
      "[1 rgb 1] }] [bozo] } } }\n"
      "sphere { 0, 1 pigment { rgb 1 } normal { pigment_pattern { brick rgb 1, rgb 0 } , 0.5 } }\n"
      "sphere { 0, 1 pigment { bozo warp { repeat x } } }\n"
      "sphere { 0, 1 texture { material_map { png \"m.png\" texture { pigment { rgb 1 } } } } }",
      &warnings);
  EXPECT_EQ(material_of_object(s, 0).texture->layers[0].finish.metallic, 1);
  EXPECT_EQ(s.objects.size(), 5u);
  EXPECT_FALSE(warnings.empty());
}

TEST(PovTexture, StandardIncludeTexturesLoadWithoutTextureWarnings) {
  constexpr const char* kIncludes = "/usr/share/povray-3.7/include";
  if (!std::filesystem::is_directory(kIncludes)) GTEST_SKIP() << kIncludes << " is absent";
  pov::Options o;
  o.system_library_path = false;
  o.library_paths = {kIncludes};
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text(
      "#include \"colors.inc\"\n#include \"textures.inc\"\n#include \"stones.inc\"\n"
      "#include \"woods.inc\"\n#include \"metals.inc\"\n"
      "sphere { 0, 1 texture { T_Stone8 } }\n"
      "sphere { 0, 1 texture { T_Wood10 } }\n"
      "sphere { 0, 1 texture { T_Gold_3C } }\n",
      "t.pov", ".", -1, o, &warnings);
  for (const std::string& w : warnings) {
    for (const char* kind : {"normal", "brilliance", "bozo", "layered", "gradient", "wood", "agate",
                             "metallic", "granite", "marble", "crand", "onion", "wrinkles"})
      EXPECT_EQ(w.find(kind), std::string::npos) << w;
  }
  ASSERT_EQ(material_of_object(s, 0).texture->layers.size(), 3u);  // T_Stone8: three layers
  EXPECT_TRUE(material_of_object(s, 1).texture);
  EXPECT_GT(material_of_object(s, 2).texture->layers.back().finish.metallic, 0);
}

}  // namespace
}  // namespace raycast
