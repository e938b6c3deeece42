// Recorded renders (render/pixel_record.h): the same image as render(), the Whitted terms adding
// up to it, the cost outputs and ray counts consistent with the render's own count; heatmaps,
// the contact sheet and the statistics report.
#include <gtest/gtest.h>

#include <string>

#include "load/demo_scene.h"
#include "load/loader.h"
#include "render/contact_sheet.h"
#include "render/heatmap.h"
#include "render/pixel_record.h"
#include "render/ray_stats.h"

namespace raycast {
namespace {

// Glass with Fresnel, a mirror, a filtered shadow and a soft light.
const std::string kScene = R"(
camera: {position: [0, 1.2, -5], look_at: [0, 0.8, 0], up: [0, 1, 0], fov: 45}
image: {width: 40, height: 30, samples: 1}
render: {max_depth: 4, background: [0.3, 0.4, 0.6], ambient: [0.1, 0.1, 0.1]}
materials:
  glass: {color: [1, 1, 1], diffuse: 0.1, specular: 0.8, shininess: 200, transmission: 0.9, ior: 1.5, fresnel: true}
  mirror: {color: [0.9, 0.9, 0.9], diffuse: 0.1, reflection: 0.8}
lights:
  - {type: point, position: [4, 6, -4], intensity: 0.8}
  - {type: sphere, center: [-4, 5, -2], radius: 0.5, samples: 2, intensity: 0.4}
objects:
  - plane: {normal: [0, 1, 0], point: [0, 0, 0]}
  - sphere: {center: [0.3, 0.8, 0], radius: 0.8}
    material: glass
  - sphere: {center: [-1.5, 0.7, 1.2], radius: 0.7}
    material: mirror
)";

const std::vector<RecordedOutput> kAll = {
    RecordedOutput::kAmbient,    RecordedOutput::kDiffuse,    RecordedOutput::kSpecular,
    RecordedOutput::kReflection, RecordedOutput::kRefraction, RecordedOutput::kShadowed,
    RecordedOutput::kCostRays,   RecordedOutput::kCostDepth,  RecordedOutput::kCostTime};

RenderOptions quiet(int spp) {
  RenderOptions o;
  o.spp = spp;
  o.progress = false;
  return o;
}

TEST(RenderRecorded, Image_EqualsTheRender) {
  const Scene scene = load_scene_text(kScene);
  for (int spp : {1, 4}) {
    RenderStats stats, recorded_stats;
    const Image image = render(scene, quiet(spp), &stats);
    const RecordedRender r = render_recorded(scene, quiet(spp), kAll, &recorded_stats);
    EXPECT_EQ(r.image.rgb, image.rgb) << spp << " spp";
    EXPECT_EQ(r.counts.total(), stats.rays);
    EXPECT_EQ(recorded_stats.rays, stats.rays);
    EXPECT_EQ(r.counts.camera, std::uint64_t(40 * 30 * spp));
  }
}

TEST(RenderRecorded, WhittedTerms_SumToTheImage) {
  const Scene scene = load_scene_text(kScene);
  const RecordedRender r = render_recorded(scene, quiet(4), kAll);
  double largest = 0;
  for (std::size_t i = 0; i < r.image.rgb.size(); ++i) {
    double sum = 0;
    for (int k = 0; k < 5; ++k) sum += r.outputs[std::size_t(k)].rgb[i];
    // Five float32 roundings of the terms and one of the image.
    EXPECT_NEAR(sum, r.image.rgb[i], 4e-7 * (1 + std::abs(sum))) << i;
    largest = std::max(largest, double(r.outputs[3].rgb[i]) + r.outputs[4].rgb[i]);
  }
  EXPECT_GT(largest, 0.05) << "no reflection or refraction in the scene";
}

TEST(RenderRecorded, CostOutputs_CountEachPixelsRays) {
  const Scene scene = load_scene_text(kScene);
  const RecordedRender r = render_recorded(scene, quiet(1), kAll);
  double rays = 0, deepest = 0, shadowed_max = 0;
  for (std::size_t i = 0; i < r.image.rgb.size(); i += 3) {
    rays += r.outputs[6].rgb[i];
    deepest = std::max(deepest, double(r.outputs[7].rgb[i]));
    shadowed_max = std::max(shadowed_max, double(r.outputs[5].rgb[i]));
    EXPECT_GE(r.outputs[5].rgb[i], 0.f);
    EXPECT_LE(r.outputs[5].rgb[i], 1.f);
    EXPECT_GE(r.outputs[8].rgb[i], 0.f);
  }
  EXPECT_EQ(rays, double(r.counts.total()));
  EXPECT_EQ(deepest, 4.0);  // max_depth: inside the glass
  EXPECT_EQ(r.counts.max_depth, 4);
  EXPECT_GT(shadowed_max, 0.5);  // the floor under the mirror ball
}

TEST(RecordedOutputNames, EveryName_RoundTrips) {
  for (RecordedOutput k : kAll) EXPECT_EQ(recorded_output_named(recorded_output_name(k)), k);
  EXPECT_FALSE(recorded_output_named("cost.nothing"));
}

TEST(Heatmap, Values_MapToTheRampWithABarBeside) {
  Image values(10, 60);
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 10; ++x) values.set(x, y, Vec3f(float(x), float(x), float(x)));
  const HeatmapScale scale = heatmap_scale(values);
  EXPECT_EQ(scale.hi, 9.0);
  const Image map = make_heatmap(values, scale);
  EXPECT_EQ(map.width, 10 + 48);
  EXPECT_EQ(map.at(0, 0), heat_color(0));
  EXPECT_EQ(map.at(9, 0), heat_color(1));
  EXPECT_NE(heat_color(0.5), heat_color(0));
  // The bar: the ramp's high end at its top, low end at its bottom.
  EXPECT_EQ(map.at(10 + 6, 6), heat_color(1));
  EXPECT_EQ(map.at(10 + 6, 53), heat_color(0));
}

TEST(ContactSheet, Images_SitSideBySide) {
  Image a(20, 10), b(20, 10);
  b.set(3, 4, Vec3f{0.5f, 0.25f, 1});
  const Image sheet = make_contact_sheet({a, b}, {"d=0", "d=1"}, 4);
  EXPECT_EQ(sheet.width, 2 * 20 + 3 * 4);
  EXPECT_EQ(sheet.at(4 + 20 + 4 + 3, 4 + 4), (Vec3f{0.5f, 0.25f, 1}));
  EXPECT_EQ(sheet.at(0, 0), (Vec3f{1, 1, 1}));
  EXPECT_THROW(make_contact_sheet({a, Image(5, 5)}, {"a", "b"}), std::invalid_argument);
}

TEST(RayStats, Report_NamesEveryKindAndTheMeshTree) {
  const Scene scene = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/bench/scenes/mesh.yaml");
  RenderStats stats;
  RenderOptions o = quiet(1);
  o.width = 32;
  o.height = 24;
  const RecordedRender r = render_recorded(scene, o, {}, &stats);
  const std::string report = format_stats(scene, stats, r.counts, PhaseTimes{0.1, 0.2, 0.3});
  for (const char* word : {"camera", "reflection", "refraction", "shadow", "load+build", "mesh BVH",
                           "triangles per leaf"})
    EXPECT_NE(report.find(word), std::string::npos) << word << "\n" << report;
  const std::vector<MeshTreeStats> trees = mesh_tree_stats(scene);
  ASSERT_FALSE(trees.empty());
  EXPECT_GT(trees[0].depth, 1);
  EXPECT_GT(trees[0].leaves, 1u);
  EXPECT_LE(trees[0].max_leaf, 16);
  EXPECT_GE(trees[0].mean_leaf * double(trees[0].leaves), double(trees[0].triangles));
}

}  // namespace
}  // namespace raycast
