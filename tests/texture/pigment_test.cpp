// Colour maps, pigment maps, block lists, layered textures and normal perturbation.
#include <gtest/gtest.h>

#include "texture/texture_stack.h"

namespace raycast::texture {
namespace {

Pigment solid(Vec3 c, double filter = 0, double transmit = 0) {
  Pigment p;
  p.color = {c, filter, transmit};
  return p;
}

TEST(ColorMap, InterpolatesBetweenEntriesAndClampsOutside) {
  const std::vector<ColorMapEntry> map = {{0.2, {{1, 0, 0}, 0, 0}}, {0.6, {{0, 0, 1}, 0, 1}}};
  EXPECT_EQ(lookup(map, 0.0).rgb, Vec3(1, 0, 0));
  EXPECT_EQ(lookup(map, 0.9).rgb, Vec3(0, 0, 1));
  const Rgbft mid = lookup(map, 0.3);
  EXPECT_NEAR(mid.rgb.x, 0.75, 1e-12);
  EXPECT_NEAR(mid.rgb.z, 0.25, 1e-12);
  EXPECT_NEAR(mid.transmit, 0.25, 1e-12);
  EXPECT_EQ(lookup({}, 0.5).rgb, Vec3(0, 0, 0));
}

TEST(ColorMap, AStepWhereTwoEntriesShareAValue) {
  const std::vector<ColorMapEntry> map = {{0, {{0, 0, 0}, 0, 0}},
                                          {0.5, {{0, 0, 0}, 0, 0}},
                                          {0.5, {{1, 1, 1}, 0, 0}},
                                          {1, {{1, 1, 1}, 0, 0}}};
  EXPECT_EQ(lookup(map, 0.49).rgb, Vec3(0, 0, 0));
  EXPECT_EQ(lookup(map, 0.51).rgb, Vec3(1, 1, 1));
}

TEST(Pigment, PatternWithColorMap) {
  Pigment p;
  p.kind = Pigment::Kind::kColorMap;
  p.pattern = make_pattern(PatternKind::kGradient);
  p.color_map = {{0, {{0, 0, 0}, 0, 0}}, {1, {{1, 1, 1}, 0, 0}}};
  EXPECT_NEAR(evaluate(p, {0.25, 0, 0}).rgb.y, 0.25, 1e-12);
  transform_pigment(p, Transform::scale({2, 2, 2}));
  EXPECT_NEAR(evaluate(p, {0.25, 0, 0}).rgb.y, 0.125, 1e-12);
}

TEST(Pigment, CheckerOfPigmentsAndNestedMaps) {
  Pigment inner;
  inner.kind = Pigment::Kind::kColorMap;
  inner.pattern = make_pattern(PatternKind::kGradient);
  inner.color_map = {{0, {{0, 0, 0}, 0, 0}}, {1, {{0, 1, 0}, 0, 0}}};
  Pigment p;
  p.kind = Pigment::Kind::kPigmentMap;
  p.pattern = make_pattern(PatternKind::kChecker);
  p.pigment_map = {{0, std::make_shared<Pigment>(solid({1, 0, 0}))},
                   {1, std::make_shared<Pigment>(inner)}};
  EXPECT_EQ(evaluate(p, {0.5, 0.5, 0.5}).rgb, Vec3(1, 0, 0));
  EXPECT_NEAR(evaluate(p, {1.5, 0.5, 0.5}).rgb.y, 0.5, 1e-12);
  // Moving the outer pigment moves the inner one with it.
  transform_pigment(p, Transform::translate({1, 0, 0}));
  EXPECT_NEAR(evaluate(p, {0.5, 0.5, 0.5}).rgb.y, 0.5, 1e-12);
}

TEST(Pigment, PigmentMapBlendsNeighbours) {
  Pigment p;
  p.kind = Pigment::Kind::kPigmentMap;
  p.pattern = make_pattern(PatternKind::kGradient);
  p.pigment_map = {{0, std::make_shared<Pigment>(solid({1, 0, 0}))},
                   {1, std::make_shared<Pigment>(solid({0, 0, 1}))}};
  const Rgbft c = evaluate(p, {0.75, 0, 0});
  EXPECT_NEAR(c.rgb.x, 0.25, 1e-12);
  EXPECT_NEAR(c.rgb.z, 0.75, 1e-12);
}

TEST(Layers, AnUpperLayerShowsTheLowerThroughItsTransmit) {
  TextureStack t;
  TextureLayer bottom, top;
  bottom.pigment = solid({1, 0, 0});
  bottom.finish.diffuse = 1;
  bottom.finish.ambient = 0;
  top.pigment = solid({0, 0, 1}, 0, 0.25);  // three quarters opaque blue
  top.finish.diffuse = 1;
  top.finish.ambient = 0;
  t.layers = {bottom, top};
  const SurfaceLook look = evaluate(t, {});
  EXPECT_NEAR(look.diffuse.x, 0.25, 1e-12);
  EXPECT_NEAR(look.diffuse.z, 0.75, 1e-12);
  EXPECT_EQ(look.through, Vec3(0, 0, 0));  // the bottom layer is opaque
  EXPECT_FALSE(t.may_transmit());
  // filter tints what shows through: a red filter over white lets only red through.
  TextureLayer white, red_glass;
  white.pigment = solid({1, 1, 1});
  red_glass.pigment = solid({1, 0, 0}, 1, 0);
  t.layers = {white, red_glass};
  const SurfaceLook tinted = evaluate(t, {});
  EXPECT_NEAR(tinted.pigment.x, 1, 1e-12);
  EXPECT_NEAR(tinted.pigment.y, 0, 1e-12);
}

TEST(Layers, FinishesAddByVisibility) {
  TextureStack t;
  TextureLayer a, b;
  a.pigment = solid({1, 1, 1});
  a.finish.phong = 0.4;
  b.pigment = solid({1, 1, 1}, 0, 1);  // clear: its highlight still shows
  b.finish.specular = 0.5;
  t.layers = {a, b};
  const SurfaceLook look = evaluate(t, {});
  EXPECT_NEAR(look.finish.phong, 0.4, 1e-12);
  EXPECT_NEAR(look.finish.specular, 0.5, 1e-12);
}

TEST(Normal, TiltsAgainstTheGradient) {
  TextureStack t;
  TextureLayer l;
  l.pigment = solid({1, 1, 1});
  Normal n;
  n.pattern = make_pattern(PatternKind::kGradient);
  n.pattern.vector = {1, 0, 0};
  n.bump_size = 0.5;
  l.normal = n;
  t.layers = {l};
  TextureContext ctx;
  ctx.p = {0.3, 0, 0};
  ctx.n = {0, 0, 1};
  const SurfaceLook look = evaluate(t, ctx);
  // Gradient (1, 0, 0) per pattern unit, times the slope scale: the normal leans to -x by
  // 0.5 * kPatternNormalScale before normalising.
  const double lean = 0.5 * kPatternNormalScale;
  EXPECT_NEAR(look.normal.x, -lean / std::sqrt(1 + lean * lean), 1e-6);
  EXPECT_NEAR(look.normal.z, 1 / std::sqrt(1 + lean * lean), 1e-6);
  // A pattern scaled by 10 tilts the same (the gradient is per pattern unit).
  transform_layer(t.layers[0], Transform::scale({10, 10, 10}));
  ctx.p = {3, 0, 0};
  EXPECT_NEAR(evaluate(t, ctx).normal.x, -lean / std::sqrt(1 + lean * lean), 1e-6);
}

TEST(Normal, BumpsChangeTheNormalSomewhere) {
  TextureLayer l;
  l.pigment = solid({1, 1, 1});
  l.normal = Normal{make_pattern(PatternKind::kBumps), 0.5, {}, {}};
  TextureStack t;
  t.layers = {l};
  int tilted = 0;
  for (int i = 0; i < 50; ++i) {
    TextureContext ctx;
    ctx.p = {0.37 * i, 0.11 * i, 0.5};
    const Vec3 n = evaluate(t, ctx).normal;
    EXPECT_NEAR(length(n), 1, 1e-12);
    EXPECT_GT(n.z, 0);
    tilted += n.z < 0.999;
  }
  EXPECT_GT(tilted, 40);
}

TEST(Normal, WrinklesTiltIsBoundedVectorNoise) {
  TextureLayer l;
  l.normal = Normal{make_pattern(PatternKind::kWrinkles), 1, {}, {}};
  TextureStack t;
  t.layers = {l};
  double largest = 0;
  for (int i = 0; i < 200; ++i) {
    TextureContext ctx;
    ctx.p = {0.173 * i, 0.31 * i, -0.07 * i};
    const Vec3 g = pattern_gradient(l.normal->pattern, ctx);
    // Each component: 3 * sum of 2^-i over ten octaves of values in [-1, 1].
    EXPECT_LE(std::abs(g.x), 3 * 2.0);
    largest = std::max(largest, length(g));
  }
  EXPECT_GT(largest, 0.3);
}

}  // namespace
}  // namespace raycast::texture
