// The renderer's camera-ray packets (render/camera_packets.h): the image and the ray count are
// those of the one-ray-at-a-time loop, bit for bit, on small scenes with meshes: a mesh alone, a
// mesh with analytic objects (mirror, glass, a textured plane), one and several samples with a
// sphere light (shading draws random numbers), the diagnostic integrators, image sizes and
// regions that do not fill the packets' blocks, one and two threads.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "load/loader.h"
#include "mesh/procedural.h"
#include "render/renderer.h"
#include "scene/scene_packets.h"
#include "support/scene_text.h"

namespace raycast {
namespace {

using testing::octa_sphere_entry;

Scene mesh_scene() {
  return load_scene_text(
      testing::lit_scene_head(37, 23) +
      octa_sphere_entry(6,
                        "    transform: [{scale: 1.2}, {translate: [0, 0.5, 0]}]\n"
                        "    material: clay\n"));
}

Scene mixed_scene() {
  // Two meshes (one small, in front of the glass), then a glass sphere partly behind the mirror
  // mesh: rays meet objects later in the walk beyond an earlier hit.
  return load_scene_text(
      testing::lit_scene_head(37, 23) +
      "  - {plane: {normal: [0, 1, 0], point: [0, -0.6, 0]}, material: floor}\n" +
      octa_sphere_entry(6, "    transform: [{translate: [-0.5, 0.4, 0]}]\n    material: mirror\n") +
      octa_sphere_entry(3,
                        "    transform: [{scale: 0.4}, {translate: [0.9, 1.2, -0.8]}]\n"
                        "    material: clay\n") +
      "  - {sphere: {center: [0.6, 0.5, 1.4], radius: 1.0}, material: glass}\n");
}

void expect_same_render(const Scene& scene, RenderOptions options, const std::string& what) {
  options.progress = false;
  RenderStats single_stats, packet_stats;
  options.camera_packets = false;
  const Image single = render(scene, options, &single_stats);
  options.camera_packets = true;
  const Image packets = render(scene, options, &packet_stats);
  ASSERT_EQ(single.width, packets.width) << what;
  ASSERT_EQ(single.height, packets.height) << what;
  EXPECT_EQ(single.rgb, packets.rgb) << what;  // bit-identical
  EXPECT_EQ(single_stats.rays, packet_stats.rays) << what;
  EXPECT_EQ(single_stats.samples, packet_stats.samples) << what;
}

TEST(CameraPackets, ScenesWithMeshesUsePackets) {
  EXPECT_TRUE(ScenePackets(mesh_scene()).usable());
  EXPECT_TRUE(ScenePackets(mixed_scene()).usable());
}

TEST(CameraPackets, OneSample_ImageEqualsSingleRays) {
  const Scene mesh = mesh_scene(), mixed = mixed_scene();
  for (int threads : {1, 2}) {
    RenderOptions options;
    options.threads = threads;
    // 37 x 23: the last tile's blocks are partial in both directions.
    expect_same_render(mesh, options, "mesh " + std::to_string(threads));
    expect_same_render(mixed, options, "mixed " + std::to_string(threads));
  }
}

TEST(CameraPackets, SeveralSamples_ImageEqualsSingleRays) {
  const Scene mixed = mixed_scene();
  for (int spp : {2, 3, 4}) {
    RenderOptions options;
    options.spp = spp;
    options.width = 21;
    options.height = 18;
    expect_same_render(mixed, options, "spp " + std::to_string(spp));
  }
}

TEST(CameraPackets, Regions_ImageEqualsSingleRays) {
  const Scene mixed = mixed_scene();
  RenderOptions options;
  options.width = 40;
  options.height = 30;
  for (const PixelRect rect : {PixelRect{3, 5, 30, 22}, PixelRect{17, 1, 18, 29},
                               PixelRect{0, 29, 40, 30}, PixelRect{13, 7, 39, 14}}) {
    options.region = rect;
    expect_same_render(mixed, options,
                       "region " + std::to_string(rect.x0) + "," + std::to_string(rect.y0));
  }
}

TEST(CameraPackets, DiagnosticIntegrators_ImageEqualsSingleRays) {
  const Scene mixed = mixed_scene();
  for (RenderMode mode :
       {RenderMode::kRaycast, RenderMode::kDepth, RenderMode::kNormal, RenderMode::kId}) {
    RenderOptions options;
    options.integrator = mode;
    expect_same_render(mixed, options, "mode " + std::to_string(int(mode)));
  }
  RenderOptions options;
  options.aov = RenderMode::kAlbedo;
  expect_same_render(mixed, options, "albedo");
}

}  // namespace
}  // namespace raycast
