// normal_map: the pattern's value blends the two neighbouring entries' unit normals (a colour
// map's rule), or picks a block pattern's entry; against the closed form of gradient normals.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "load/pov_loader.h"
#include "texture/texture_stack.h"

namespace raycast {
namespace {

std::shared_ptr<const texture::Normal> gradient_normal(const Vec3& direction, double bump) {
  auto n = std::make_shared<texture::Normal>();
  n->pattern = texture::make_pattern(texture::PatternKind::kGradient);
  n->pattern.vector = direction;
  n->bump_size = bump;
  return n;
}

Vec3 leaned(const Vec3& tilt, const Vec3& n) { return normalize(n - (tilt - dot(tilt, n) * n)); }

TEST(NormalMap, BlendsTheNeighbouringEntriesUnitNormals) {
  texture::Normal map;
  map.pattern = texture::make_pattern(texture::PatternKind::kGradient);
  map.pattern.vector = {0, 0, 1};  // the map's value is z (0.3 here), the entries' x and y
  map.bump_size = 1;
  map.map = {{0.2, gradient_normal({1, 0, 0}, 1)}, {0.6, gradient_normal({0, 1, 0}, 2)}};
  texture::TextureContext ctx;
  ctx.p = {0.3, 0.4, 0.3};
  ctx.n = {0, 0, 1};
  const double s = texture::kPatternNormalScale;
  // 0.3 is a quarter of the way from 0.2 to 0.6.
  const Vec3 a = normalize(Vec3{-s, 0, 1});
  const Vec3 b = normalize(Vec3{0, -2 * s, 1});
  const Vec3 want = normalize(0.75 * a + 0.25 * b);
  const Vec3 got = leaned(texture::normal_tilt(map, ctx), ctx.n);
  EXPECT_NEAR(got.x, want.x, 1e-9);
  EXPECT_NEAR(got.y, want.y, 1e-9);
  // Below the first entry: the first entry's normal alone.
  ctx.p.z = 0.1;
  const Vec3 first = leaned(texture::normal_tilt(map, ctx), ctx.n);
  EXPECT_NEAR(first.x, a.x, 1e-9);
  EXPECT_NEAR(first.y, 0, 1e-9);
}

TEST(NormalMap, PovNormalMapAndBlockNormals) {
  pov::Options o;
  o.system_library_path = false;
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text(
      "sphere { 0, 1 normal { gradient z normal_map { [0.6 gradient y, 2] [0.2 gradient x, 1] } "
      "} }\n"
      "sphere { 0, 1 normal { checker normal { gradient x, 1 } normal { gradient y, 2 } } }\n",
      "t.pov", ".", -1, o, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const auto& m0 = s.materials[static_cast<std::size_t>(s.objects[0].material)];
  const texture::Normal& n0 = *m0.texture->layers[0].normal;
  ASSERT_EQ(n0.map.size(), 2u);
  EXPECT_EQ(n0.map[0].weight, 0.2);  // sorted by value
  EXPECT_EQ(n0.map[1].normal->bump_size, 2);
  const auto& m1 = s.materials[static_cast<std::size_t>(s.objects[1].material)];
  const texture::Normal& n1 = *m1.texture->layers[0].normal;
  ASSERT_EQ(n1.map.size(), 2u);
  EXPECT_EQ(n1.map[1].normal->bump_size, 2);
}

}  // namespace
}  // namespace raycast

namespace raycast {
namespace {

// POV-Ray's ripples normal keeps its tilt's size as the frequency rises (the frequency is inside
// the wave): the mean tilt at frequency 8 stays near frequency 1's, not 8 times it.
TEST(NormalMap, RipplesTiltDoesNotGrowWithFrequency) {
  auto mean_tilt = [](double frequency) {
    texture::Normal n;
    n.pattern = texture::make_pattern(texture::PatternKind::kRipples);
    n.pattern.frequency = frequency;
    n.bump_size = 0.5;
    double sum = 0;
    texture::TextureContext ctx;
    for (int i = 0; i < 200; ++i) {
      ctx.p = {0.013 * i, 0.3 + 0.007 * i, 0.011 * i};
      sum += length(texture::normal_tilt(n, ctx));
    }
    return sum / 200;
  };
  const double one = mean_tilt(1), eight = mean_tilt(8);
  EXPECT_GT(one, 0);
  EXPECT_LT(eight, 2 * one);
  EXPECT_GT(eight, 0.5 * one);
}

}  // namespace
}  // namespace raycast
