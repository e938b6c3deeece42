// The sky sphere and fog of docs/rendering.md "Sky and fog": the sky looked up by direction, the
// constant fog's blend in closed form, the ground fog against a numeric integral of its density,
// and both through a YAML scene's render (camera rays that miss and hit, a mirror's reflection).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"
#include "render/atmosphere.h"
#include "render/renderer.h"

namespace raycast {
namespace {

void expect_color(const Vec3& got, const Vec3& want, double tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// POV-Ray's example sky: gradient y from red (straight down) to blue (straight up), the pattern
// scaled by 2 and moved down by 1 so that the unit sphere's y in [-1, 1] spans the map once.
SkySphere gradient_sky() {
  texture::Pigment p;
  p.kind = texture::Pigment::Kind::kColorMap;
  p.pattern = texture::make_pattern(texture::PatternKind::kGradient);
  p.pattern.vector = {0, 1, 0};
  p.color_map = {{0, {{1, 0, 0}, 0, 0}}, {1, {{0, 0, 1}, 0, 0}}};
  texture::transform_pigment(p, Transform::translate({0, -1, 0}) * Transform::scale({2, 2, 2}));
  SkySphere sky;
  sky.layers.push_back(p);
  return sky;
}

TEST(SkySphere, GradientByDirection) {
  const SkySphere sky = gradient_sky();
  const Vec3 bg{0.3, 0.3, 0.3};
  expect_color(sky_color(sky, bg, {0, 1, 0}), {0, 0, 1}, 1e-12);
  expect_color(sky_color(sky, bg, {0, -5, 0}), {1, 0, 0}, 1e-12);  // any length
  expect_color(sky_color(sky, bg, {1, 0, 0}), {0.5, 0, 0.5}, 1e-12);
  // 30 degrees above the horizon: y = 0.5, value 0.75.
  expect_color(sky_color(sky, bg, {std::sqrt(3.0), 1, 0}), {0.25, 0, 0.75}, 1e-12);
}

TEST(SkySphere, EmissionScalesAndTransformTurns) {
  SkySphere sky = gradient_sky();
  sky.emission = {2, 1, 0.5};
  expect_color(sky_color(sky, {0, 0, 0}, {0, 1, 0}), {0, 0, 0.5}, 1e-12);
  // The sky turned 90 degrees about z: its top now lies along -x.
  sky.emission = {1, 1, 1};
  sky.to_sky = Transform::rotate({0, 0, 1}, 90).inverse();
  expect_color(sky_color(sky, {0, 0, 0}, {-1, 0, 0}), {0, 0, 1}, 1e-12);
}

TEST(SkySphere, LayersShowThroughFilterTransmitAndBackground) {
  SkySphere sky;
  texture::Pigment bottom, top;
  bottom.color = {{0.2, 0.4, 0.6}, 0, 0.5};  // half transmitting: the background shows
  top.color = {{1, 0.5, 0}, 0.5, 0.25};      // filter 0.5, transmit 0.25
  sky.layers = {bottom, top};
  const Vec3 bg{0.8, 0.8, 0.8};
  // Top: 0.25 of its colour, letting 0.5 C + 0.25 through; bottom: 0.5 of its colour, 0.5 through.
  const Vec3 through_top = 0.5 * Vec3{1, 0.5, 0} + Vec3{0.25, 0.25, 0.25};
  const Vec3 want = 0.25 * Vec3{1, 0.5, 0} + 0.5 * mul(through_top, Vec3{0.2, 0.4, 0.6}) +
                    0.5 * mul(through_top, bg);
  expect_color(sky_color(sky, bg, {0, 0, 1}), want, 1e-12);
}

Fog constant_fog(const Vec3& c, double filter, double transmit, double distance) {
  Fog f;
  f.color = c;
  f.filter = filter;
  f.transmit = transmit;
  f.distance = distance;
  return f;
}

TEST(Fog, ConstantFogIsTheExponentialBlend) {
  const Fog fog = constant_fog({0.4, 0.2, 0.8}, 0, 0, 150);
  const Ray ray{{1, 2, 3}, {0, 0, 2}};
  const Vec3 light{0.2, 0.6, 1};
  for (double d : {0.0, 10.0, 150.0, 1000.0}) {
    const double k = std::exp(-d / 150);
    expect_color(apply_fogs({fog}, ray, d, light), k * light + (1 - k) * fog.color, 1e-14);
  }
  // A miss sees the fog's colour alone.
  expect_color(apply_fogs({fog}, ray, kInfinity, light), fog.color, 0);
}

TEST(Fog, FilterTintsAndTransmitBoundsTheVeil) {
  // Figures POV-Ray 3.7 renders for a 1x1 image of these fogs (checked by hand with povray).
  const Ray ray{{0, 0, 0}, {0, 0, 1}};
  const Vec3 light{0.2, 0.6, 1};
  const Fog filtering = constant_fog({0.4, 0.2, 0.8}, 0.5, 0, 10);
  const double k = std::exp(-1.0);
  expect_color(apply_fogs({filtering}, ray, 10, light),
               k * mul(light, Vec3{0.7, 0.6, 0.9}) + (1 - k) * filtering.color, 1e-14);
  const Fog thin = constant_fog({0.4, 0.2, 0.8}, 0.5, 0.3, 1);
  expect_color(apply_fogs({thin}, ray, kInfinity, {0.5, 0.5, 0.5}), {0.385, 0.23, 0.695}, 1e-12);
  // Two fogs multiply what they let through and add their colours.
  const Fog second = constant_fog({0.9, 0.9, 0.1}, 0, 0.2, 20);
  const double k2 = std::max(0.2, std::exp(-0.5));
  const Vec3 want = k2 * (k * mul(light, Vec3{0.7, 0.6, 0.9})) + (1 - k) * filtering.color +
                    (1 - k2) * second.color;
  expect_color(apply_fogs({filtering, second}, ray, 10, light), want, 1e-14);
}

// The ground fog's density: 1 up to the offset, 1 / (1 + ((h - offset) / alt)^2) above it.
double density(double offset, double alt, double h) {
  if (h <= offset) return 1;
  const double x = (h - offset) / alt;
  return 1 / (1 + x * x);
}

TEST(Fog, GroundFogDepthMatchesItsIntegral) {
  const double offset = 1, alt = 2;
  struct Case {
    double h0, dh, length;
  };
  for (const Case c : {Case{0, 0.4472, 10.18}, Case{-3, 0.9, 7}, Case{5, -0.6, 12}, Case{4, 0, 3},
                       Case{0.5, 0, 3}, Case{2, 1e-9, 50}, Case{8, -1, 4}}) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += density(offset, alt, c.h0 + (i + 0.5) / n * c.length * c.dh);
    const double numeric = sum * c.length / n;
    EXPECT_NEAR(ground_fog_depth(offset, alt, c.h0, c.dh, c.length), numeric, 1e-6 * c.length)
        << c.h0 << " " << c.dh << " " << c.length;
  }
  // Unbounded segments: rising, the integral is finite; level or sinking, it is not.
  EXPECT_NEAR(ground_fog_depth(1, 2, 0, 0.5, kInfinity), 1 / 0.5 + 2 * (M_PI / 2) / 0.5, 1e-12);
  EXPECT_TRUE(std::isinf(ground_fog_depth(1, 2, 3, 0, kInfinity)));
  EXPECT_TRUE(std::isinf(ground_fog_depth(1, 2, 3, -0.1, kInfinity)));
}

TEST(Fog, GroundFogFollowsUpAndItsTransform) {
  Fog fog;
  fog.kind = Fog::Kind::kGround;
  fog.offset = 1;
  fog.alt = 2;
  fog.distance = 3;
  // up along x and the fog moved by 1 along x: heights are x - 1.
  fog.up = {1, 0, 0};
  fog.to_fog = Transform::translate({1, 0, 0}).inverse();
  const Ray ray{{0, 5, 0}, {0, 0, 4}};  // level at x = 0: height -1, under the offset
  EXPECT_NEAR(fog_depth(fog, ray, 7), 7, 1e-12);
  const Ray rising{{1, 0, 0}, {3, 0, 4}};  // height 0, rising 0.6 per unit
  EXPECT_NEAR(fog_depth(fog, rising, 5), ground_fog_depth(1, 2, 0, 0.6, 5), 1e-12);
}

// A YAML scene: a gradient sky and, below the camera, a mirror facing up.
const std::string kSkyScene = R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], up: [0, 1, 0], fov: 90}
image: {width: 3, height: 3, samples: 1}
render:
  background: [0.3, 0.3, 0.3]
  sky_sphere:
    pigment: {pattern: gradient, direction: [0, 1, 0], colors: [[0, [1, 0, 0]], [1, [0, 0, 1]]],
              transform: [{scale: 2}, {translate: [0, -1, 0]}]}
materials:
  mirror: {color: [0, 0, 0], ambient: 0, diffuse: 0, reflection: 1}
objects:
  - plane: {point: [0, -1, 0], normal: [0, 1, 0]}
    material: mirror
)";

Image render_text(const std::string& yaml) {
  const Scene s = load_scene_text(yaml);
  RenderOptions o;
  o.progress = false;
  return render(s, o);
}

TEST(SkySphere, CameraRaysAndReflectionsSeeTheSky) {
  const Image im = render_text(kSkyScene);
  // The centre pixel looks along -z: the horizon, halfway between red and blue.
  const Vec3f c = im.at(1, 1);
  EXPECT_NEAR(c.x, 0.5, 1e-6);
  EXPECT_NEAR(c.z, 0.5, 1e-6);
  // The top row's centre looks along (0, 2/3, -1) (a 90 degree field over three rows).
  const double up = 0.5 + 0.5 * (2.0 / 3) / std::sqrt(1 + 4.0 / 9);
  EXPECT_NEAR(im.at(1, 0).z, up, 1e-6);
  // The bottom row sees the mirror, which shows the same sky mirrored: the top row's colour.
  EXPECT_NEAR(im.at(1, 2).z, up, 1e-6);
  EXPECT_NEAR(im.at(1, 2).x, 1 - up, 1e-6);
}

TEST(Fog, YamlFogOverAHit) {
  // The second fog lies 10 units below the camera: over a level segment its density is
  // 1 / (1 + 10^2). The sphere glows its colour (ambient 1 under a white ambient light).
  const std::string scene = R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], up: [0, 1, 0], fov: 10}
image: {width: 1, height: 1, samples: 1}
render:
  background: [0.5, 0.5, 0.5]
  ambient: [1, 1, 1]
  fog:
    - {color: [0.4, 0.2, 0.8, 0.5], distance: 10}
    - {type: ground, color: [1, 1, 1], distance: 5, offset: -10, alt: 1}
materials:
  glow: {color: [0.2, 0.6, 1], ambient: 1, diffuse: 0}
objects:
  - sphere: {center: [0, 0, -11], radius: 1}
    material: glow
)";
  const Image im = render_text(scene);
  const double k1 = std::exp(-1.0), k2 = std::exp(-10.0 / 101 / 5);
  const Vec3 want = k2 * k1 * mul(Vec3{0.2, 0.6, 1}, Vec3{0.7, 0.6, 0.9}) +
                    (1 - k1) * Vec3{0.4, 0.2, 0.8} + (1 - k2) * Vec3{1, 1, 1};
  const Vec3f c = im.at(0, 0);
  expect_color({c.x, c.y, c.z}, want, 1e-5);
}

// A ring 42.5 +- 5 degrees around +z, red inside to blue outside, filter 0.2, transmit 0.3.
Rainbow test_rainbow() {
  Rainbow r;
  r.direction = {0, 0, 1};
  r.angle = 42.5;
  r.width = 10;
  r.colors = {{0, {{1, 0, 0}, 0.2, 0.3}}, {1, {{0, 0, 1}, 0.2, 0.3}}};
  return r;
}

// The direction `degrees` away from +z, turned `around` degrees from +y about +z.
Vec3 ring_direction(double degrees, double around) {
  const double t = degrees * M_PI / 180, a = around * M_PI / 180;
  return {std::sin(t) * std::sin(a), std::sin(t) * std::cos(a), std::cos(t)};
}

TEST(Rainbow, RingColourVeilsAsPovRay) {
  const std::vector<Rainbow> rs = {test_rainbow()};
  // POV-Ray 3.7 on a white background at the ring's middle: 0.6291 0.2580 0.6289; by the
  // formula: k = 0.3, k (1 - 0.2 * 0.7 * (1 - c)) + 0.7 c.
  const Ray mid{{0, 0, 0}, ring_direction(42.5, 0)};
  expect_color(apply_rainbows(rs, mid, kInfinity, {1, 1, 1}), {0.629, 0.258, 0.629}, 1e-9);
  // The inner edge is the map's 0: red.
  const Ray inner{{0, 0, 0}, ring_direction(37.5 + 1e-9, 0)};
  expect_color(apply_rainbows(rs, inner, kInfinity, {0, 0, 0}), {0.7, 0, 0}, 1e-6);
  // Outside the ring nothing changes; a near hit is barely veiled.
  const Ray outside{{0, 0, 0}, ring_direction(50, 0)};
  expect_color(apply_rainbows(rs, outside, kInfinity, {0.1, 0.2, 0.3}), {0.1, 0.2, 0.3}, 0);
  const Vec3 near = apply_rainbows(rs, mid, 1, {1, 1, 1});
  EXPECT_NEAR(near.y, 1, 1e-6);
}

TEST(Rainbow, ArcFadesAroundUp) {
  Rainbow r = test_rainbow();
  r.colors = {{0, {{1, 1, 1}, 0, 0}}, {1, {{1, 1, 1}, 0, 0}}};
  r.arc_angle = 120;
  r.falloff_angle = 60;
  const std::vector<Rainbow> rs = {r};
  // POV-Ray 3.7 on black: 1 up to 30 degrees from up, 0.5 at 45, 0 from 60 on.
  for (const auto& [around, want] :
       {std::pair{0.0, 1.0}, std::pair{30.0, 1.0}, std::pair{45.0, 0.5}, std::pair{-45.0, 0.5},
        std::pair{60.0, 0.0}, std::pair{180.0, 0.0}}) {
    const Ray ray{{0, 0, 0}, ring_direction(42.5, around)};
    EXPECT_NEAR(apply_rainbows(rs, ray, kInfinity, {0, 0, 0}).x, want, 1e-9) << around;
  }
}

TEST(Rainbow, YamlRainbow) {
  const std::string scene = R"(
camera: {position: [0, 0, 0], look_at: [0, 0.9163, -1], up: [0, 1, 0], fov: 10}
image: {width: 1, height: 1, samples: 1}
render:
  background: [1, 1, 1]
  rainbow: {direction: [0, 0, -1], angle: 42.5, width: 10,
            colors: [[0, [1, 0, 0, 0.2, 0.3]], [1, [0, 0, 1, 0.2, 0.3]]]}
objects:
  - sphere: {center: [0, 0, 50], radius: 1}  # behind the camera
)";
  const Vec3f c = render_text(scene).at(0, 0);
  expect_color({c.x, c.y, c.z}, {0.629, 0.258, 0.629}, 1e-3);
}

TEST(Fog, YamlErrorsArePositioned) {
  const std::string bad = R"(
render:
  fog: {color: [1, 1, 1], distance: 0}
)";
  EXPECT_THROW(load_scene_text(bad), SceneError);
  const std::string both = R"(
render:
  sky_sphere: {pigment: {color: [1, 1, 1]}, pigments: [{color: [1, 1, 1]}]}
)";
  EXPECT_THROW(load_scene_text(both), SceneError);
}

}  // namespace
}  // namespace raycast
