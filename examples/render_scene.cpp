// Builds a small scene in code (a sphere minus a box on a plane, a light, a camera) and writes a
// binary PPM image.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <raycast/raycast.h>

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "scene.ppm";
  raycast::Scene scene;
  const raycast::ObjectId floor = scene.add_plane({0, 1, 0}, {0, -1, 0});
  raycast::Material checker;
  checker.checker = true;
  scene.set_material(floor, scene.add_material(checker));

  const raycast::ObjectId ball = scene.add_sphere({0, 0, 0}, 1);
  const raycast::ObjectId cut = scene.add_box({0, 0, -2}, {2, 2, 0});
  const raycast::ObjectId operands[] = {ball, cut};
  const raycast::ObjectId solid = scene.add_csg(raycast::CsgOp::kDifference, operands);
  raycast::Material red;
  red.color = {0.8, 0.2, 0.2};
  red.specular = 0.5;
  scene.set_material(solid, scene.add_material(red));
  scene.set_transform(solid, raycast::Transform::rotate({0, 1, 0}, 30));

  raycast::Light light;
  light.position = {3, 5, -4};
  scene.add_light(light);
  raycast::Camera camera;
  camera.position = {0, 1.5, -5};
  scene.set_camera(camera);
  scene.commit();

  raycast::RenderOptions options;
  options.width = 320;
  options.height = 240;
  options.samples = 4;
  const raycast::Image image = scene.render(nullptr, options);

  std::FILE* f = std::fopen(path, "wb");
  if (!f) return 1;
  std::fprintf(f, "P6\n%d %d\n255\n", image.width, image.height);
  for (const float v : image.rgb) {
    const float encoded = std::pow(std::clamp(v, 0.f, 1.f), 1 / 2.2f);  // approximate sRGB
    std::fputc(static_cast<int>(std::lround(255 * encoded)), f);
  }
  std::fclose(f);
  std::printf("wrote %s (%dx%d)\n", path, image.width, image.height);
  return 0;
}
