// The Whitted shading takes the material of the part hit (Scene::material_of): for CSG objects and
// instances whose parts all resolve to one material the integrator knows it per object, for the
// others it asks per hit (render/integrator.cpp). Lit by its ambient term alone, a hit shows its
// material's colour, which must be the albedo mode's (material_of per hit) at every pixel.
#include <gtest/gtest.h>

#include "load/loader.h"
#include "render/camera.h"
#include "render/integrator.h"

namespace raycast {
namespace {

constexpr const char* kScene = R"(
camera: {position: [0, 2, -9], look_at: [0, 0.5, 0], up: [0, 1, 0], fov: 50}
image: {width: 64, height: 48, samples: 1}
render: {ambient: [1, 1, 1], background: [0, 0, 0]}
materials:
  a: {color: [0.9, 0.1, 0.1], ambient: 1, diffuse: 0, specular: 0}
  b: {color: [0.1, 0.8, 0.2], ambient: 1, diffuse: 0, specular: 0}
  c: {color: [0.2, 0.3, 0.9], ambient: 1, diffuse: 0, specular: 0}
library:
  plain:
    difference:
      - sphere: {radius: 0.5}
      - box: {min: [-0.2, -1, -0.2], max: [0.2, 1, 0.2]}
  mixed:
    difference:
      - sphere: {radius: 0.5}
      - box: {min: [-0.2, -1, -0.2], max: [0.2, 1, 0.2]}
        material: c
objects:
  # Parts without materials: the object's.
  - difference:
      - box: {min: [-1, -1, -1], max: [1, 1, 1]}
      - sphere: {radius: 1.3}
    transform: [{translate: [-3, 1, 1]}]
    material: a
  # A part with the object's own material named again: still one material.
  - intersection:
      - sphere: {center: [0, 0, -0.6], radius: 1}
      - sphere: {center: [0, 0, 0.6], radius: 1}
        material: a
    transform: [{translate: [0, 1, 1]}]
    material: a
  # A part with another material: per hit.
  - difference:
      - sphere: {radius: 1}
      - sphere: {center: [0, 0, -0.8], radius: 0.6}
        material: b
    transform: [{translate: [3, 1, 1]}]
    material: a
  # No material anywhere: the default material (index 0).
  - union:
      - sphere: {center: [-1.5, 0, -2], radius: 0.4}
      - sphere: {center: [-1.5, 0.5, -2], radius: 0.3}
  # Instances: parts without materials, and with one of their own.
  - {use: plain, transform: [{translate: [0.5, 0.5, -2.5]}], material: b}
  - {use: mixed, transform: [{translate: [1.6, 0.5, -2.5]}], material: b}
  - {use: mixed, transform: [{translate: [2.7, 0.5, -2.5]}], material: c}
  - {plane: {normal: [0, 1, 0], point: [0, -0.01, 0]}, material: b}
)";

TEST(CompositeMaterial, AmbientShadingShowsTheMaterialOfThePartHit) {
  const Scene scene = load_scene_text(kScene);
  const Integrator whitted(scene, RenderMode::kWhitted), albedo(scene, RenderMode::kAlbedo);
  const Camera camera(*scene.camera, 64, 48);
  int hits = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      const Ray ray = camera.ray(x + 0.5, y + 0.5);
      SampleState sw{Rng(1), 0}, sa{Rng(1), 0};
      const Color shaded = whitted.li(ray, sw), colour = albedo.li(ray, sa);
      ASSERT_EQ(shaded.x, colour.x) << x << ", " << y;
      ASSERT_EQ(shaded.y, colour.y) << x << ", " << y;
      ASSERT_EQ(shaded.z, colour.z) << x << ", " << y;
      hits += colour.x + colour.y + colour.z > 0;
    }
  }
  EXPECT_GT(hits, 64 * 48 / 2);
}

}  // namespace
}  // namespace raycast
