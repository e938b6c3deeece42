// POV-Ray's `average` pattern: pigments, normals and textures averaged by their map's weights,
// against closed forms; the YAML and POV-Ray forms that build them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"
#include "load/pov_loader.h"
#include "texture/texture_stack.h"

namespace raycast {
namespace {

using texture::Pigment;

std::shared_ptr<const Pigment> solid(Vec3 c, double transmit = 0) {
  auto p = std::make_shared<Pigment>();
  p->color = {c, 0, transmit};
  return p;
}

std::shared_ptr<const Pigment> gradient(const Vec3& direction) {
  auto p = std::make_shared<Pigment>();
  p->kind = Pigment::Kind::kColorMap;
  p->pattern = texture::make_pattern(texture::PatternKind::kGradient);
  p->pattern.vector = direction;
  p->color_map = {{0, {{0, 0, 0}, 0, 0}}, {1, {{1, 1, 1}, 0, 0}}};
  return p;
}

TEST(AveragePigment, IsTheWeightedMeanOfItsPigments) {
  Pigment p;
  p.kind = Pigment::Kind::kAverage;
  p.pigment_map = {{3, solid({1, 0, 0})}, {1, solid({0, 0, 1}, 0.8)}};
  const texture::Rgbft c = texture::evaluate(p, {0.3, 0.2, 0.1});
  EXPECT_NEAR(c.rgb.x, 0.75, 1e-15);
  EXPECT_NEAR(c.rgb.z, 0.25, 1e-15);
  EXPECT_NEAR(c.transmit, 0.2, 1e-15);
  EXPECT_TRUE(texture::may_transmit(p));
  // Patterned entries are evaluated at the point: (x + y + z) / 3 for three gradients.
  p.pigment_map = {{1, gradient({1, 0, 0})}, {1, gradient({0, 1, 0})}, {1, gradient({0, 0, 1})}};
  EXPECT_NEAR(texture::evaluate(p, {0.3, 0.6, 0.9}).rgb.y, 0.6, 1e-12);
  // Weights summing to 0 give black, not NaN.
  p.pigment_map = {{0, solid({1, 1, 1})}};
  EXPECT_EQ(texture::evaluate(p, {0, 0, 0}).rgb, Vec3(0, 0, 0));
}

TEST(AveragePigment, MovesWithItsPigments) {
  Pigment p;
  p.kind = Pigment::Kind::kAverage;
  p.pigment_map = {{1, gradient({1, 0, 0})}, {1, solid({0, 0, 0})}};
  texture::transform_pigment(p, Transform::scale({2, 2, 2}));
  // The gradient scaled by 2 is 0.25 at x = 0.5, averaged with black.
  EXPECT_NEAR(texture::evaluate(p, {0.5, 0, 0}).rgb.x, 0.125, 1e-12);
}

// A normal from gradient x of bump size b tilts n = z by the pattern's slope: at a point where
// the ramp is smooth its tilt is b * kPatternNormalScale along x.
std::shared_ptr<const texture::Normal> gradient_normal(const Vec3& direction, double bump) {
  auto n = std::make_shared<texture::Normal>();
  n->pattern = texture::make_pattern(texture::PatternKind::kGradient);
  n->pattern.vector = direction;
  n->bump_size = bump;
  return n;
}

TEST(AverageNormal, IsTheWeightedMeanOfTheUnitNormals) {
  texture::TextureContext ctx;
  ctx.p = {0.3, 0.4, 0};
  ctx.n = {0, 0, 1};
  const double s = texture::kPatternNormalScale;
  texture::Normal avg;
  avg.bump_size = 1;
  avg.average = {{3, gradient_normal({1, 0, 0}, 1)}, {1, gradient_normal({0, 1, 0}, 2)}};
  // Each entry's unit normal is (n - tilt) / |n - tilt|; their weighted mean, normalised, is
  // what the average's tilt must lean n onto.
  const Vec3 a = normalize(Vec3{-s, 0, 1});
  const Vec3 b = normalize(Vec3{0, -2 * s, 1});
  const Vec3 want = normalize(0.75 * a + 0.25 * b);
  const Vec3 tilt = texture::normal_tilt(avg, ctx);
  const Vec3 got = normalize(ctx.n - (tilt - dot(tilt, ctx.n) * ctx.n));
  EXPECT_NEAR(got.x, want.x, 1e-9);
  EXPECT_NEAR(got.y, want.y, 1e-9);
  EXPECT_NEAR(got.z, want.z, 1e-9);
  // Through a whole texture's look.
  texture::TextureStack stack;
  texture::TextureLayer layer;
  layer.normal = avg;
  stack.layers.push_back(layer);
  const Vec3 n = texture::evaluate(stack, ctx).normal;
  EXPECT_NEAR(n.x, want.x, 1e-9);
  EXPECT_NEAR(n.y, want.y, 1e-9);
}

TEST(AverageTexture, AveragesColoursFinishesAndTransmittance) {
  auto red = std::make_shared<texture::TextureStack>();
  texture::TextureLayer l;
  l.pigment.color = {{1, 0, 0}, 0, 0};
  l.finish.phong = 1;
  red->layers.push_back(l);
  auto clear = std::make_shared<texture::TextureStack>();
  l.pigment.color = {{0, 0, 1}, 0, 1};
  l.finish.phong = 0;
  clear->layers.push_back(l);
  texture::TextureStack avg;
  avg.map_pattern = texture::make_pattern(texture::PatternKind::kBozo);
  avg.average = true;
  avg.map = {{1, red}, {3, clear}};
  texture::TextureContext ctx;
  EXPECT_NEAR(texture::pigment_color(avg, ctx.p).x, 0.25, 1e-12);
  EXPECT_NEAR(texture::pigment_color(avg, ctx.p).z, 0, 1e-12);  // the clear one shows nothing
  EXPECT_NEAR(texture::transmittance(avg, ctx.p).z, 0.75, 1e-12);
  const texture::SurfaceLook look = texture::evaluate(avg, ctx);
  EXPECT_NEAR(look.finish.phong, 0.25, 1e-12);
  EXPECT_NEAR(look.through.x, 0.75, 1e-12);
}

Scene load_pov(const std::string& text, std::vector<std::string>* warnings) {
  pov::Options o;
  o.system_library_path = false;
  return load_pov_scene_text(text, "t.pov", ".", -1, o, warnings);
}

TEST(AveragePov, PigmentNormalAndTextureAverages) {
  std::vector<std::string> warnings;
  const Scene s = load_pov(
      "global_settings { assumed_gamma 1 }\n"
      "sphere { 0, 1 pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 rgb <0, 0, 1>] } } }\n"
      "sphere { 0, 1 pigment { average pigment_map { [rgb 1] [rgb 0] } } }\n"
      "sphere { 0, 1 normal { average normal_map { [3 gradient x, 1] [gradient y, 2] } } }\n"
      "sphere { 0, 1 texture { average texture_map { [pigment { rgb 1 }] "
      "[3 pigment { rgb 0 } finish { phong 1 }] } } }",
      &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(s.objects.size(), 4u);
  auto material = [&](std::size_t i) -> const Material& {
    return s.materials[static_cast<std::size_t>(s.objects[i].material)];
  };
  const texture::Rgbft c = texture::evaluate(material(0).texture->layers[0].pigment, {0, 0, 0});
  EXPECT_NEAR(c.rgb.x, 0.25, 1e-12);
  EXPECT_NEAR(c.rgb.z, 0.75, 1e-12);
  // Entries without a value weigh 1.
  EXPECT_NEAR(texture::evaluate(material(1).texture->layers[0].pigment, {0, 0, 0}).rgb.y, 0.5,
              1e-12);
  const std::optional<texture::Normal>& n = material(2).texture->layers[0].normal;
  ASSERT_TRUE(n.has_value());
  ASSERT_EQ(n->average.size(), 2u);
  EXPECT_EQ(n->average[0].weight, 3);
  EXPECT_EQ(n->average[1].weight, 1);
  EXPECT_EQ(n->average[1].normal->bump_size, 2);
  const texture::TextureStack& t = *material(3).texture;
  ASSERT_TRUE(t.average);
  EXPECT_NEAR(texture::pigment_color(t, {0, 0, 0}).x, 0.25, 1e-12);
  EXPECT_NEAR(texture::evaluate(t, texture::TextureContext{}).finish.phong, 0.75, 1e-12);
}

std::string yaml_scene(const std::string& material) {
  return "camera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nmaterials:\n  m: " + material +
         "\nobjects:\n  - sphere: {center: [0, 0, 0], radius: 1}\n    material: m\n";
}

TEST(AverageYaml, PigmentsAndNormals) {
  const Scene s = load_scene_text(yaml_scene(
      "{texture: {pattern: average, pigments: [[1, {color: [1, 0, 0]}], [3, {pattern: gradient, "
      "colors: [[0, [0, 0, 0]], [1, [1, 1, 1]]]}]]}, normal: {pattern: average, normals: [[1, "
      "{pattern: gradient, bump_size: 1}], [1, {pattern: gradient, direction: [0, 1, 0]}]]}}"));
  const Material& m = s.materials[static_cast<std::size_t>(s.objects[0].material)];
  ASSERT_TRUE(m.texture);
  const texture::Rgbft c = texture::evaluate(m.texture->layers[0].pigment, {0.4, 0, 0});
  EXPECT_NEAR(c.rgb.x, 0.25 + 0.75 * 0.4, 1e-12);
  EXPECT_NEAR(c.rgb.y, 0.75 * 0.4, 1e-12);
  ASSERT_EQ(m.texture->layers[0].normal->average.size(), 2u);
  EXPECT_EQ(m.texture->layers[0].normal->average[1].normal->bump_size, 0.5);
  EXPECT_THROW(load_scene_text(yaml_scene(
                   "{texture: {pattern: average, pigments: [[0, {color: [1, 0, 0]}]]}}")),
               SceneError);
  EXPECT_THROW(load_scene_text(yaml_scene(
                   "{texture: {pattern: average, pigments: [[-1, {color: [1, 0, 0]}]]}}")),
               SceneError);
}

}  // namespace
}  // namespace raycast
