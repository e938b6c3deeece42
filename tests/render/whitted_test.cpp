// The Whitted integrator against docs/rendering.md "Shading", on hand-computed scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

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

// A unit sphere at the origin seen from (0, 0, 5) through a 1x1 image: the single centre sample
// hits p = (0, 0, 1) with n = v = (0, 0, 1).
const std::string kSphereScene = R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 10}
image: {width: 1, height: 1, samples: 1}
render: {ambient: [0.1, 0.2, 0.3], background: [0, 0, 0]}
materials:
  m: {color: [0.5, 0.6, 0.7], ambient: 0.5, diffuse: 0.7, specular: 0.3, shininess: 10}
lights:
  - {type: point, position: [3, 0, 5], color: [1, 0.5, 0.25], intensity: 2}
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
    material: m
)";

// The expected pixel, by hand: l = (3, 0, 4) / 5, n.l = 0.8, r = 2 (n.l) n - l = (-0.6, 0, 0.8),
// r.v = 0.8. L = 0.5 * (0.1, 0.2, 0.3) * C + E * (0.7 * C * 0.8 + 0.3 * 0.8^10), E = (2, 1, 0.5).
Vec3 expected_lit() {
  const Vec3 c{0.5, 0.6, 0.7};
  const Vec3 e{2, 1, 0.5};
  const double highlight = 0.3 * std::pow(0.8, 10);  // 0.03221225472
  const Vec3 ambient = 0.5 * mul(Vec3{0.1, 0.2, 0.3}, c);
  return ambient + mul(e, 0.56 * c + Vec3{highlight, highlight, highlight});
}

Vec3 pixel(const Scene& scene, RenderOptions options = {}) {
  options.progress = false;
  const Image image = render(scene, options);
  return Vec3(image.at(image.width / 2, image.height / 2));
}

TEST(Whitted, SingleSphereAndPointLight_MatchesTheSpecFormula) {
  const Scene scene = load_scene_text(kSphereScene);
  const Vec3 want = expected_lit();
  expect_color(want, {0.64942450944, 0.42821225472, 0.31710612736}, 1e-11);  // the sum worked out
  expect_color(pixel(scene), want, 1e-6);                                    // float image
  SampleState state{Rng(1), 0};
  const Integrator integrator(scene, RenderMode::kWhitted);
  expect_color(integrator.whitted({{0, 0, 5}, {0, 0, -1}}, 0, state), want, 1e-12);
  EXPECT_EQ(state.rays, 2u);  // the primary ray and one shadow ray
}

TEST(Whitted, InverseSquareAttenuation_DividesByDistanceSquared) {
  std::string text = kSphereScene;
  text.replace(text.find("intensity: 2}"), 13, "intensity: 2, attenuation: inverse_square}");
  const Scene scene = load_scene_text(text);
  const Vec3 c{0.5, 0.6, 0.7};
  const Vec3 ambient = 0.5 * mul(Vec3{0.1, 0.2, 0.3}, c);
  const Vec3 want = ambient + (expected_lit() - ambient) / 25.0;  // |(3, 0, 4)|^2 = 25
  expect_color(pixel(scene), want, 1e-6);
}

TEST(Whitted, OpaqueBlocker_LeavesOnlyTheAmbientTerm) {
  const Scene scene = load_scene_text(kSphereScene + R"(
  - sphere: {center: [1.5, 0, 3], radius: 0.2}
)");
  const Vec3 c{0.5, 0.6, 0.7};
  expect_color(pixel(scene), 0.5 * mul(Vec3{0.1, 0.2, 0.3}, c), 1e-7);
}

TEST(Whitted, TransmissiveBlocker_LetsTransmissionTimesColourThrough) {
  const Scene scene = load_scene_text(kSphereScene + R"(
  - sphere: {center: [1.5, 0, 3], radius: 0.2}
    material: {color: [0.8, 0.6, 0.4], transmission: 0.5, ior: 1.5}
)");
  const Vec3 c{0.5, 0.6, 0.7};
  const Vec3 ambient = 0.5 * mul(Vec3{0.1, 0.2, 0.3}, c);
  const Vec3 factor = 0.5 * Vec3{0.8, 0.6, 0.4};
  expect_color(pixel(scene), ambient + mul(factor, expected_lit() - ambient), 1e-6);
}

TEST(Whitted, ShadowThroughTwoTransmissiveObjects_MultipliesEachOnce) {
  // Each sphere's surface is crossed twice by the segment; each object counts once.
  const Scene scene = load_scene_text(R"(
materials:
  a: {color: [0.8, 0.6, 0.4], transmission: 0.5}
  b: {color: [1, 0.5, 0.25], transmission: 0.9}
objects:
  - sphere: {center: [0, 0, 2], radius: 0.5}
    material: a
  - sphere: {center: [0, 0, 5], radius: 0.5}
    material: b
)");
  const Integrator integrator(scene, RenderMode::kWhitted);
  SampleState state{Rng(1), 0};
  const Vec3 want = mul(0.5 * Vec3{0.8, 0.6, 0.4}, 0.9 * Vec3{1, 0.5, 0.25});
  expect_color(integrator.shadow({0, 0, 0}, {0, 0, 10}, false, state), want, 1e-15);
  expect_color(integrator.shadow({0, 0, 0}, {0, 0, 1}, true, state), want, 1e-15);
  expect_color(integrator.shadow({0, 0, 0}, {0, 0, 3.5}, false, state), 0.5 * Vec3{0.8, 0.6, 0.4},
               1e-15);
  expect_color(integrator.shadow({0, 0, 0}, {1, 0, 0}, true, state), {1, 1, 1}, 0);
}

TEST(Whitted, ShadowThroughPlainTexturedAndOpaqueObjects_EachByItsOwnRule) {
  // The three cases the integrator sorts objects into once per frame: an untextured transmissive
  // sphere filters by transmission * colour, a textured one by transmission * its albedo at the
  // crossing (the checker's even cell at x = y = 0), an opaque one blocks.
  const Scene scene = load_scene_text(R"(
materials:
  plain: {color: [0.8, 0.6, 0.4], transmission: 0.5}
  textured: {texture: {checker: {colors: [[0.5, 0.25, 1], [1, 1, 1]], scale: 100}}, transmission: 0.5}
  opaque: {color: [1, 1, 1]}
objects:
  - sphere: {center: [0, 0, 2], radius: 0.5}
    material: plain
  - sphere: {center: [0, 0, 5], radius: 0.5}
    material: textured
  - sphere: {center: [0, 0, 8], radius: 0.5}
    material: opaque
)");
  const Integrator integrator(scene, RenderMode::kWhitted);
  SampleState state{Rng(1), 0};
  const Vec3 plain = 0.5 * Vec3{0.8, 0.6, 0.4}, textured = 0.5 * Vec3{0.5, 0.25, 1};
  expect_color(integrator.shadow({0, 0, 0}, {0, 0, 3.5}, false, state), plain, 1e-15);
  expect_color(integrator.shadow({0, 0, 3.5}, {0, 0, 6.5}, false, state), textured, 1e-15);
  expect_color(integrator.shadow({0, 0, 0}, {0, 0, 6.5}, false, state), mul(plain, textured),
               1e-15);
  expect_color(integrator.shadow({0, 0, 0}, {0, 0, 10}, false, state), {0, 0, 0}, 0);
  expect_color(integrator.shadow({0, 0, 6.5}, {0, 0, 1}, true, state), {0, 0, 0}, 0);
  expect_color(integrator.shadow({0, 0, 9}, {0, 0, 1}, true, state), {1, 1, 1}, 0);
}

TEST(Whitted, LightBehindTheSurface_ContributesNothing) {
  std::string text = kSphereScene;
  text.replace(text.find("position: [3, 0, 5]"), 19, "position: [0, 0, -5]");
  const Scene scene = load_scene_text(text);
  expect_color(pixel(scene), 0.5 * mul(Vec3{0.1, 0.2, 0.3}, Vec3{0.5, 0.6, 0.7}), 1e-7);
}

TEST(Whitted, DirectionalLight_HasNoFalloff) {
  std::string text = kSphereScene;
  text.replace(text.find("type: point, position: [3, 0, 5]"), 32,
               "type: directional, direction: [-3, 0, -4]");
  expect_color(pixel(load_scene_text(text)), expected_lit(), 1e-6);
}

TEST(Whitted, SpotLight_LightsInsideItsConeOnly) {
  std::string inside = kSphereScene, outside = kSphereScene;
  inside.replace(inside.find("type: point, position: [3, 0, 5]"), 32,
                 "type: spot, position: [3, 0, 5], direction: [-3, 0, -4], angle: 20, falloff: 5");
  outside.replace(outside.find("type: point, position: [3, 0, 5]"), 32,
                  "type: spot, position: [3, 0, 5], direction: [0, 0, -1], angle: 20, falloff: 5");
  expect_color(pixel(load_scene_text(inside)), expected_lit(), 1e-6);
  expect_color(pixel(load_scene_text(outside)), 0.5 * mul(Vec3{0.1, 0.2, 0.3}, Vec3{0.5, 0.6, 0.7}),
               1e-7);
}

TEST(Whitted, TinySphereLight_MatchesThePointLight) {
  std::string text = kSphereScene;
  text.replace(text.find("type: point, position: [3, 0, 5]"), 32,
               "type: sphere, center: [3, 0, 5], radius: 0.001, samples: 8");
  expect_color(pixel(load_scene_text(text)), expected_lit(), 2e-3);
}

TEST(Whitted, HalfCoveredSphereLight_GivesAPartialShadow) {
  // A blocker covering one side of a sphere light: visibility strictly between 0 and 1.
  std::string text = kSphereScene;
  text.replace(text.find("type: point, position: [3, 0, 5]"), 32,
               "type: sphere, center: [3, 0, 5], radius: 0.5, samples: 64");
  text += "  - sphere: {center: [1.65, 0.15, 3.2], radius: 0.2}\n";
  const Scene scene = load_scene_text(text);
  const Vec3 ambient = 0.5 * mul(Vec3{0.1, 0.2, 0.3}, Vec3{0.5, 0.6, 0.7});
  const double got = pixel(scene).x;
  EXPECT_GT(got, ambient.x + 0.05);
  EXPECT_LT(got, expected_lit().x - 0.05);
}

// A glass half-space (y < 0, looking from inside) over an opaque floor at y = -10 whose colour
// is pure ambient; no lights. Rays start inside the glass heading up.
const std::string kGlassSlab = R"(
render: {ambient: [1, 1, 1], background: [1, 1, 1], max_depth: 5}
materials:
  glass: {color: [1, 1, 1], ambient: 0, diffuse: 0, transmission: 1, ior: 1.5}
  floor: {color: [0.2, 0.4, 0.6], ambient: 1, diffuse: 0}
objects:
  - plane: {normal: [0, 1, 0], point: [0, 0, 0]}
    material: glass
  - plane: {normal: [0, 1, 0], point: [0, -10, 0]}
    material: floor
)";

Vec3 trace_from_inside(const Scene& scene, double degrees_from_normal) {
  const double a = degrees_from_normal * std::numbers::pi / 180;
  SampleState state{Rng(1), 0};
  return Integrator(scene, RenderMode::kWhitted)
      .whitted({{0, -1, 0}, {std::sin(a), std::cos(a), 0}}, 0, state);
}

TEST(Whitted, BeyondCriticalAngle_AllLightIsReflected) {
  const Scene scene = load_scene_text(kGlassSlab);
  // Critical angle asin(1/1.5) = 41.8 degrees: at 60 the ray reflects down onto the floor.
  expect_color(trace_from_inside(scene, 60), {0.2, 0.4, 0.6}, 1e-15);
  // At 20 degrees it leaves the glass to the background.
  expect_color(trace_from_inside(scene, 20), {1, 1, 1}, 1e-15);
}

TEST(Whitted, FresnelAtNormalIncidence_ReflectsSquaredIndexRatio) {
  // From above, straight down onto glass with fresnel: 4% to the (white) sky, 96% down to a
  // black floor.
  const Scene scene = load_scene_text(R"(
render: {ambient: [0, 0, 0], background: [1, 1, 1]}
materials:
  glass: {color: [1, 1, 1], ambient: 0, diffuse: 0, transmission: 1, ior: 1.5, fresnel: true}
objects:
  - plane: {normal: [0, 1, 0], point: [0, 0, 0]}
    material: glass
  - plane: {normal: [0, 1, 0], point: [0, -10, 0]}
)");
  SampleState state{Rng(1), 0};
  const Vec3 got =
      Integrator(scene, RenderMode::kWhitted).whitted({{0, 5, 0}, {0, -1, 0}}, 0, state);
  const double f = 0.5 * 0.5 / (2.5 * 2.5);
  expect_color(got, {f, f, f}, 1e-15);
}

TEST(Whitted, MaxDepth_CountsSecondaryRays) {
  // A perfect mirror floor under a grey sky, looked at from above.
  const std::string base = R"(
materials:
  mirror: {color: [1, 1, 1], ambient: 0, diffuse: 0, reflection: 1}
objects:
  - plane: {normal: [0, 1, 0], point: [0, 0, 0]}
    material: mirror
)";
  const Ray down{{0, 1, 0}, {0.6, -0.8, 0}};
  for (int max_depth : {0, 1}) {
    const Scene scene = load_scene_text("render: {background: [0.5, 0.5, 0.5], max_depth: " +
                                        std::to_string(max_depth) + "}\n" + base);
    SampleState state{Rng(1), 0};
    const Vec3 got = Integrator(scene, RenderMode::kWhitted).whitted(down, 0, state);
    expect_color(got, max_depth == 0 ? Vec3{0, 0, 0} : Vec3{0.5, 0.5, 0.5}, 0);
    EXPECT_EQ(state.rays, max_depth == 0 ? 1u : 2u);
  }
}

TEST(Whitted, Bailout_StopsRaysWhoseWeightFallsBelowIt) {
  // Two facing half mirrors (reflection 0.5, nothing else): the k-th secondary ray of a vertical
  // ray between them has weight 0.5^k and is traced only when 0.5^k >= bailout.
  const std::string base = R"(
materials:
  half: {color: [1, 1, 1], ambient: 0, diffuse: 0, reflection: 0.5}
objects:
  - {plane: {normal: [0, 1, 0], point: [0, 0, 0]}, material: half}
  - {plane: {normal: [0, -1, 0], point: [0, 1, 0]}, material: half}
)";
  const Ray down{{0, 0.5, 0}, {0, -1, 0}};
  // bailout -> secondary rays traced (of max_depth 20): 0 traces all; 1/255 stops at 0.5^8 =
  // 1/256; 0.25 = 0.5^2 exactly keeps the second; above 0.5 none.
  const std::pair<std::string, std::uint64_t> cases[] = {
      {"0", 20}, {"0.00392156862745098", 7}, {"0.25", 2}, {"0.6", 0}};
  for (const auto& [bailout, secondary] : cases) {
    const Scene scene =
        load_scene_text("render: {max_depth: 20, bailout: " + bailout + "}\n" + base);
    SampleState state{Rng(1), 0};
    expect_color(Integrator(scene, RenderMode::kWhitted).whitted(down, 0, state), {0, 0, 0}, 0);
    EXPECT_EQ(state.rays, 1 + secondary) << "bailout " << bailout;
  }
  // The default is 1/255; a negative or non-numeric cut-off is a scene error.
  EXPECT_EQ(load_scene_text(base).render.bailout, 1.0 / 255);
  for (const char* bad : {"-0.1", ".nan", "a lot"})
    EXPECT_THROW(load_scene_text(std::string("render: {bailout: ") + bad + "}\n" + base),
                 SceneError)
        << bad;
  // A cut ray contributes nothing: one half mirror under a white sky.
  const std::string floor = R"(
materials:
  half: {color: [1, 1, 1], ambient: 0, diffuse: 0, reflection: 0.5}
objects:
  - {plane: {normal: [0, 1, 0], point: [0, 0, 0]}, material: half}
)";
  for (const char* bailout : {"0.5", "0.6"}) {
    const Scene scene = load_scene_text(std::string("render: {background: [1, 1, 1], bailout: ") +
                                        bailout + "}\n" + floor);
    SampleState state{Rng(1), 0};
    const double want = std::string(bailout) == "0.5" ? 0.5 : 0;
    expect_color(Integrator(scene, RenderMode::kWhitted).whitted(down, 0, state),
                 {want, want, want}, 0);
  }
}

TEST(Whitted, ZeroLightTerm_CastsNoShadowRay) {
  // A floor seen along (1, -1, 0) from (0, 1, 0), hit at (1, 0, 0). Without a diffuse part the
  // light term is the highlight only, 0 when the mirrored light direction faces away from the
  // viewer: then no shadow ray is cast (the pixel is the same either way). A light at (-3, 2, 0)
  // gives l ~ (-2, 1, 0), r ~ (2, 1, 0), r.v < 0; one at (3, 2, 0) gives r.v > 0.
  const Ray ray{{0, 1, 0}, {1, -1, 0}};
  for (const char* diffuse : {"0", "0.5"}) {
    for (const char* light : {"[-3, 2, 0]", "[3, 2, 0]"}) {
      const Scene scene = load_scene_text(std::string(R"(
render: {max_depth: 0}
materials:
  m: {color: [1, 1, 1], ambient: 0, specular: 0.5, shininess: 10, diffuse: )") +
                                          diffuse + R"(}
lights:
  - {type: point, position: )" + light + R"(, color: [1, 1, 1]}
objects:
  - {plane: {normal: [0, 1, 0], point: [0, 0, 0]}, material: m}
)");
      SampleState state{Rng(1), 0};
      const Vec3 got = Integrator(scene, RenderMode::kWhitted).whitted(ray, 0, state);
      const bool dark = std::string(diffuse) == "0" && std::string(light) == "[-3, 2, 0]";
      EXPECT_EQ(state.rays, dark ? 1u : 2u) << diffuse << " " << light;
      if (dark) {
        expect_color(got, {0, 0, 0}, 0);
      } else {
        EXPECT_GT(got.x, 0) << diffuse << " " << light;
      }
    }
  }
}

TEST(Whitted, CheckerOnTransformedObject_IsEvaluatedInObjectSpace) {
  // The plane's object-space point sits in the middle of a cell; the transform moves it by half
  // a cell in x, so a world-space checker would change colour at world x = 0 and an object-space
  // one at world x = 0.5.
  const Scene scene = load_scene_text(R"(
materials:
  c: {texture: {checker: {colors: [[1, 0, 0], [0, 0, 1]], scale: 1}}}
objects:
  - plane: {normal: [0, 1, 0], point: [0, 0.5, 0]}
    transform: [{translate: [0.5, -0.5, 0]}]
    material: c
)");
  const Integrator integrator(scene, RenderMode::kAlbedo);
  SampleState state{Rng(1), 0};
  // Object-space x = world x - 0.5; y = 0.5, z = 0.5 -> floor sum = floor(x - 0.5).
  expect_color(integrator.li({{0.25, 1, 0.5}, {0, -1, 0}}, state), {0, 0, 1},
               0);  // floor(-0.25) = -1: odd
  expect_color(integrator.li({{0.75, 1, 0.5}, {0, -1, 0}}, state), {1, 0, 0},
               0);  // floor(0.25) = 0: even
  expect_color(integrator.li({{1.75, 1, 0.5}, {0, -1, 0}}, state), {0, 0, 1}, 0);
}

TEST(Whitted, Checker_EvenAndOddCells) {
  const CheckerTexture t{{1, 1, 1}, {0, 0, 0}, 2};
  EXPECT_EQ(checker(t, {0.5, 0.5, 0.5}), (Vec3{1, 1, 1}));
  EXPECT_EQ(checker(t, {2.5, 0.5, 0.5}), (Vec3{0, 0, 0}));
  EXPECT_EQ(checker(t, {-0.5, 0.5, 0.5}), (Vec3{0, 0, 0}));
  EXPECT_EQ(checker(t, {-0.5, -0.5, 0.5}), (Vec3{1, 1, 1}));
  EXPECT_EQ(checker(t, {-2.5, -0.5, -0.5}), (Vec3{1, 1, 1}));  // -2 - 1 - 1: even
  EXPECT_EQ(checker(t, {-2.5, -0.5, 0.5}), (Vec3{0, 0, 0}));
}

}  // namespace
}  // namespace raycast
