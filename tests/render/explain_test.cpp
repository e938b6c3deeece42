// raycast explain (render/explain.h): the tree is recorded by the integrator that renders, so
// its root colour is the rendered pixel and its terms add up.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>
#include <string>

#include "load/demo_scene.h"
#include "load/loader.h"
#include "render/explain.h"
#include "render/explain_format.h"
#include "render/explain_svg.h"
#include "render/renderer.h"

namespace raycast {
namespace {

// A glass sphere and a glass cube with Fresnel over a checker floor, a mirror and a soft light:
// every kind of ray, total internal reflection inside the cube (a ray that entered a sphere
// always leaves it again), and shadows filtered by the glass.
const std::string kGlassScene = R"(
camera: {position: [0, 1.2, -5], look_at: [0, 0.8, 0], up: [0, 1, 0], fov: 45}
image: {width: 32, height: 24, samples: 1}
render: {max_depth: 6, background: [0.3, 0.4, 0.6], ambient: [0.1, 0.1, 0.1]}
materials:
  glass: {color: [1, 1, 1], diffuse: 0, specular: 0.8, shininess: 200, transmission: 0.9, ior: 1.5, fresnel: true}
  mirror: {color: [0.9, 0.9, 0.9], diffuse: 0.1, reflection: 0.8}
  floor: {texture: {checker: {colors: [[0.9, 0.9, 0.9], [0.2, 0.2, 0.3]], scale: 0.5}}}
lights:
  - {type: point, position: [4, 6, -4], intensity: 0.8}
  - {type: sphere, center: [-4, 5, -2], radius: 0.5, samples: 2, intensity: 0.4}
objects:
  - plane: {normal: [0, 1, 0], point: [0, -0.01, 0]}
    material: floor
  - sphere: {center: [0.3, 0.8, 0], radius: 0.8}
    material: glass
  - sphere: {center: [-1.5, 0.7, 1.2], radius: 0.7}
    material: mirror
  - box: {min: [1.3, 0, -1.6], max: [2.3, 1, -0.6]}
    material: glass
)";

// A sphere over a floor, lit from straight above: the floor under the sphere is in its shadow.
const std::string kShadowScene = R"(
camera: {position: [0, 4, -4], look_at: [0, 0, 0], up: [0, 1, 0], fov: 40}
image: {width: 9, height: 9, samples: 1}
lights:
  - {type: point, position: [0, 10, 0]}
objects:
  - plane: {normal: [0, 1, 0], point: [0, 0, 0]}
  - sphere: {center: [0, 1.5, 0], radius: 1}
)";

/// Explains every pixel at 1 spp and compares its root colour with the rendered pixel, bit for
/// bit in the image's float.
void expect_every_pixel_explained(const Scene& scene, int width, int height) {
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.spp = 1;
  options.progress = false;
  const Image image = render(scene, options);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      ExplainOptions o;
      o.x = x;
      o.y = y;
      o.width = width;
      o.height = height;
      o.spp = 1;
      const Explanation e = explain_pixel(scene, o);
      const Vec3f got(e.color), want = image.at(x, y);
      ASSERT_EQ(got.x, want.x) << scene.source << " pixel " << x << " " << y;
      ASSERT_EQ(got.y, want.y) << scene.source << " pixel " << x << " " << y;
      ASSERT_EQ(got.z, want.z) << scene.source << " pixel " << x << " " << y;
      ASSERT_EQ(e.root.radiance, e.color);
    }
}

/// Every ray's named terms add up to its radiance.
void expect_terms_sum(const ExplainedRay& r, int& hits) {
  if (r.hit) {
    ++hits;
    const Color sum = r.hit->ambient + r.diffuse() + r.specular() + r.reflection() + r.refraction();
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(sum[c], r.radiance[c], 1e-12 * (1 + std::abs(r.radiance[c])));
  }
  for (const ExplainedRay& child : r.children) expect_terms_sum(child, hits);
}

bool has_tir(const ExplainedRay& r) {
  if (r.tir) return true;
  for (const ExplainedRay& child : r.children)
    if (has_tir(child)) return true;
  return false;
}

TEST(ExplainPixel, EveryPixelOfTheDemo_EqualsTheRender) {
  expect_every_pixel_explained(load_demo_scene(), 40, 30);
}

TEST(ExplainPixel, EveryPixelOfTheGlassScene_EqualsTheRender) {
  expect_every_pixel_explained(load_scene_text(kGlassScene), 32, 24);
}

TEST(ExplainPixel, GlassSceneUnderSkyAndFog_EqualsTheRender) {
  // Misses see the sky and every segment the fog: the recording mode must add them as the render
  // does.
  Scene scene = load_scene_text(kGlassScene);
  auto a = std::make_shared<Atmosphere>();
  SkySphere sky;
  texture::Pigment p;
  p.kind = texture::Pigment::Kind::kColorMap;
  p.pattern = texture::make_pattern(texture::PatternKind::kGradient);
  p.pattern.vector = {0, 1, 0};
  p.color_map = {{0, {{1, 0.5, 0}, 0, 0}}, {1, {{0, 0.2, 1}, 0, 0}}};
  sky.layers.push_back(p);
  a->sky = sky;
  Fog fog;
  fog.color = {0.5, 0.6, 0.7};
  fog.filter = 0.3;
  fog.distance = 8;
  a->fogs.push_back(fog);
  scene.render.atmosphere = a;
  expect_every_pixel_explained(scene, 32, 24);
}

TEST(ExplainPixel, EveryPixelOfTheExampleScenes_EqualsTheRender) {
  // bench/scenes/mesh.yaml renders its camera rays as packets (render/camera_packets.h).
  for (const char* name :
       {"scenes/csg.yaml", "scenes/quadrics.yaml", "scenes/box.yaml", "scenes/torus.yaml",
        "bench/scenes/mesh.yaml", "bench/scenes/glass.yaml"})
    expect_every_pixel_explained(load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/" + name), 24,
                                 18);
}

TEST(ExplainPixel, GlassScene_TermsSumToEachRaysRadiance) {
  const Scene scene = load_scene_text(kGlassScene);
  int hits = 0;
  bool tir = false;
  for (int y = 0; y < 24; y += 2)
    for (int x = 0; x < 32; x += 2) {
      ExplainOptions o;
      o.x = x;
      o.y = y;
      const Explanation e = explain_pixel(scene, o);
      expect_terms_sum(e.root, hits);
      tir = tir || has_tir(e.root);
    }
  EXPECT_GT(hits, 50);
  EXPECT_TRUE(tir) << "no total internal reflection inside the glass cube";
}

TEST(ExplainPixel, SamplesOfAPixel_AverageToTheRenderedPixel) {
  const Scene scene = load_scene_text(kGlassScene);
  RenderOptions options;
  options.spp = 4;
  options.progress = false;
  const Image image = render(scene, options);
  for (const auto& [x, y] : {std::pair{16, 12}, std::pair{5, 20}, std::pair{20, 8}}) {
    Color sum{0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      ExplainOptions o;
      o.x = x;
      o.y = y;
      o.spp = 4;
      o.sample = k;
      sum += explain_pixel(scene, o).color;
    }
    const Vec3f got(sum / 4.0), want = image.at(x, y);
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.z, want.z);
  }
}

TEST(ExplainPixel, FloorUnderTheSphere_ShadowRayBlockedByTheSphere) {
  const Scene scene = load_scene_text(kShadowScene);
  ExplainOptions o;
  o.x = 4;
  o.y = 6;  // below the sphere's image: the floor right under it
  const Explanation e = explain_pixel(scene, o);
  ASSERT_TRUE(e.root.hit);
  EXPECT_EQ(scene.objects[std::size_t(e.root.hit->hit.object)].entry, 0);
  ASSERT_EQ(e.root.hit->lights.size(), 1u);
  const ExplainedLight& l = e.root.hit->lights[0];
  EXPECT_TRUE(l.sample.shadow_ray);
  EXPECT_EQ(l.sample.visibility, (Color{0, 0, 0}));
  ASSERT_GE(l.blocker, 0);
  EXPECT_EQ(scene.objects[std::size_t(l.blocker)].entry, 1);
  // The segment p + t (light - p) enters the sphere |x - c| = 1 at the smaller root of
  // |p - c + t d|^2 = 1.
  const Vec3 p = l.sample.shadow.o, d = l.sample.shadow.d, pc = p - Vec3{0, 1.5, 0};
  const double a = dot(d, d), b = dot(pc, d), c = dot(pc, pc) - 1;
  EXPECT_NEAR(l.blocker_t, (-b - std::sqrt(b * b - a * c)) / a, 1e-9);
  EXPECT_NE(explain_text(scene, e).find("blocked by sphere #1"), std::string::npos);
}

TEST(ExplainPixel, PixelOutsideTheImage_Throws) {
  const Scene scene = load_scene_text(kShadowScene);
  ExplainOptions o;
  o.x = 9;
  EXPECT_THROW(explain_pixel(scene, o), std::invalid_argument);
  o.x = 0;
  o.sample = 1;
  EXPECT_THROW(explain_pixel(scene, o), std::invalid_argument);
}

TEST(ExplainJson, GlassPixel_HasTheDocumentedKeys) {
  const Scene scene = load_scene_text(kGlassScene);
  ExplainOptions o;
  o.x = 17;
  o.y = 10;
  const Explanation e = explain_pixel(scene, o);
  const YAML::Node root = YAML::Load(explain_json(scene, e));
  ASSERT_TRUE(root["pixel"] && root["color"] && root["ray"]);
  EXPECT_EQ(root["pixel"][0].as<int>(), 17);
  EXPECT_EQ(root["color"][0].as<double>(), e.color.x);
  const YAML::Node ray = root["ray"];
  for (const char* key : {"kind", "origin", "direction", "depth", "hit", "children"})
    EXPECT_TRUE(ray[key]) << key;
  EXPECT_EQ(ray["kind"].as<std::string>(), "camera");
  const YAML::Node hit = ray["hit"];
  ASSERT_TRUE(hit.IsMap());
  for (const char* key : {"object", "t", "point", "normal", "shading"})
    EXPECT_TRUE(hit[key]) << key;
  EXPECT_EQ(hit["object"].as<int>(), 1);  // the glass sphere
  bool shadow = false, refraction = false;
  for (const YAML::Node& child : ray["children"]) {
    shadow = shadow || child["kind"].as<std::string>() == "shadow";
    refraction = refraction || child["kind"].as<std::string>() == "refraction";
  }
  EXPECT_TRUE(shadow);
  EXPECT_TRUE(refraction);
  double sum = 0;
  for (const auto& term : hit["shading"]) sum += term.second[0].as<double>();
  EXPECT_NEAR(sum, ray["radiance"][0].as<double>(), 1e-12);
}

TEST(ExplainSvg, ShadowScene_DrawsTheSectionAndABlockedShadowRay) {
  const Scene scene = load_scene_text(kShadowScene);
  ExplainOptions o;
  o.x = 4;
  o.y = 6;
  const std::string svg = explain_svg(scene, explain_pixel(scene, o));
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("class=\"camera\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"blocked\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"blocker\""), std::string::npos);
  EXPECT_NE(svg.find("<rect x="), std::string::npos);  // the sphere's and the floor's section
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

}  // namespace
}  // namespace raycast
