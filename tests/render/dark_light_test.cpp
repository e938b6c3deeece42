// A light with no positive channel adds nothing and sends no shadow ray (render/integrator.cpp:
// the light's term, not its colour, is what the shading tests), in opaque and transmissive scenes.
#include <gtest/gtest.h>

#include <string>

#include "load/loader.h"
#include "render/camera.h"
#include "render/integrator.h"

namespace raycast {
namespace {

std::string scene_text(const std::string& extra_light, double transmission) {
  return R"(
camera: {position: [0, 1, 6], look_at: [0, 0, 0], up: [0, 1, 0], fov: 40}
image: {width: 24, height: 18, samples: 1}
render: {ambient: [0.1, 0.1, 0.1], background: [0.2, 0.3, 0.4]}
materials:
  m: {color: [0.5, 0.6, 0.7], specular: 0.4, shininess: 20}
  g: {color: [0.9, 0.9, 1], diffuse: 0.2, specular: 0.8, shininess: 60, transmission: )" +
         std::to_string(transmission) + R"(, ior: 1.5}
lights:
  - {type: point, position: [3, 4, 5], color: [1, 0.9, 0.8], intensity: 1}
)" + extra_light +
         R"(
objects:
  - {plane: {normal: [0, 1, 0], point: [0, -1, 0]}, material: m}
  - {sphere: {center: [-0.8, 0, 0], radius: 0.7}, material: g}
  - {sphere: {center: [0.9, 0, -0.5], radius: 0.6}, material: m}
)";
}

TEST(DarkLight, AddsNothingAndTracesNoShadowRay) {
  for (double transmission : {0.0, 0.7}) {
    for (const std::string& dark :
         {std::string("  - {type: point, position: [-3, 4, 2], color: [0, 0, 0], intensity: 1}"),
          std::string("  - {type: point, position: [-3, 4, 2], color: [1, 1, 1], intensity: 0}"),
          std::string("  - {type: point, position: [-3, 4, 2], color: [1, 1, 1], intensity: 0, "
                      "attenuation: inverse_square}")}) {
      const Scene plain = load_scene_text(scene_text("", transmission));
      const Scene with_dark = load_scene_text(scene_text(dark, transmission));
      const Integrator a(plain, RenderMode::kWhitted), b(with_dark, RenderMode::kWhitted);
      const Camera camera(*plain.camera, 24, 18);
      for (int y = 0; y < 18; ++y) {
        for (int x = 0; x < 24; ++x) {
          const Ray ray = camera.ray(x + 0.5, y + 0.5);
          SampleState sa{Rng(1), 0}, sb{Rng(1), 0};
          const Color ca = a.li(ray, sa), cb = b.li(ray, sb);
          ASSERT_EQ(ca.x, cb.x) << x << ", " << y;
          ASSERT_EQ(ca.y, cb.y) << x << ", " << y;
          ASSERT_EQ(ca.z, cb.z) << x << ", " << y;
          ASSERT_EQ(sa.rays, sb.rays) << x << ", " << y;
        }
      }
    }
  }
}

}  // namespace
}  // namespace raycast
