// What the renderer sees of CSG and instances: the albedo of a hit is the material of the part
// hit (the subtracted sphere's own, the library entry's own), not the enclosing object's.
#include <gtest/gtest.h>

#include "load/loader.h"
#include "render/texture.h"

namespace raycast {
namespace {

const char* kScene =
    "materials:\n"
    "  gold: {color: [0.9, 0.7, 0.2]}\n"
    "  blue: {color: [0.2, 0.3, 0.8]}\n"
    "library:\n"
    "  nut:\n"
    "    difference:\n"
    "      - sphere: {radius: 0.45}\n"
    "      - box: {min: [-0.2, -1, -0.2], max: [0.2, 1, 0.2]}\n"
    "        material: gold\n"
    "objects:\n"
    "  - difference:\n"
    "      - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
    "      - sphere: {center: [0, 0, -1], radius: 0.8}\n"
    "        material: gold\n"
    "    material: blue\n"
    "  - use: nut\n"
    "    transform: [{translate: [5, 0, 0]}]\n"
    "    material: blue\n";

Color albedo_at(const Scene& scene, const Ray& ray) {
  SceneHit hit;
  EXPECT_TRUE(scene.intersect(ray, hit));
  return albedo(scene, {}, ray, hit, scene.surface(ray, hit));
}

TEST(CsgRender, AlbedoIsThePartsMaterial) {
  const Scene scene = load_scene_text(kScene);
  // The cavity left by the gold sphere, then the blue box's face.
  EXPECT_EQ(albedo_at(scene, Ray{{0, 0, -5}, {0, 0, 1}}).x, 0.9);
  EXPECT_EQ(albedo_at(scene, Ray{{0.9, 0.9, -5}, {0, 0, 1}}).x, 0.2);
  // The instance's cut (gold in every use) from inside the hole, and its body (the use's blue).
  EXPECT_EQ(albedo_at(scene, Ray{{5, 0, 0}, {1, 0, 0}}).x, 0.9);
  EXPECT_EQ(albedo_at(scene, Ray{{5, 0, -5}, {0, 0, 1}}).x, 0.2);
}

}  // namespace
}  // namespace raycast
