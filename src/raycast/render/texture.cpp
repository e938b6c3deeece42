#include "render/texture.h"

#include <cmath>
#include <cstdint>

#include "io/scene_error.h"

namespace raycast {

Color lookup(const ImageTexture& texture, double u, double v) {
  const Image& im = texture.image;
  if (im.width <= 0 || im.height <= 0) return {0, 0, 0};
  if (!std::isfinite(u) || !std::isfinite(v)) return Vec3(im.at(0, 0));
  // Continuous texel coordinates with texel centres at half-integers, rows from the top.
  const double x = (u - std::floor(u)) * im.width - 0.5;
  const double y = (1 - (v - std::floor(v))) * im.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  auto wrap = [](double i, int n) {
    const long long k = static_cast<long long>(i) % n;
    return static_cast<int>(k < 0 ? k + n : k);
  };
  const int xa = wrap(x0, im.width), xb = wrap(x0 + 1, im.width);
  const int ya = wrap(y0, im.height), yb = wrap(y0 + 1, im.height);
  const Vec3 top = (1 - fx) * Vec3(im.at(xa, ya)) + fx * Vec3(im.at(xb, ya));
  const Vec3 bottom = (1 - fx) * Vec3(im.at(xa, yb)) + fx * Vec3(im.at(xb, yb));
  return (1 - fy) * top + fy * bottom;
}

Color checker_far(const CheckerTexture& texture, double x, double y, double z) {
  const double sum = std::floor(x) + std::floor(y) + std::floor(z);
  if (!std::isfinite(sum)) return texture.c0;
  // sum is a whole number: its parity without fmod (every double from 2^53 up is even).
  const double a = std::abs(sum);
  if (a >= 0x1p53) return texture.c0;
  return (static_cast<std::int64_t>(a) & 1) == 0 ? texture.c0 : texture.c1;
}

std::vector<std::shared_ptr<const ImageTexture>> load_textures(const Scene& scene) {
  std::vector<std::shared_ptr<const ImageTexture>> textures(scene.materials.size());
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    if (m.image) {
      textures[i] = m.image;
    } else if (!m.image_file.empty()) {
      try {
        textures[i] = load_image_texture(m.image_file);
      } catch (const ImageError& e) {
        throw SceneError(scene.source, 0, 0, "material '" + m.name + "' texture: " + e.what());
      }
    }
  }
  return textures;
}

Color albedo(const Scene& scene, const std::vector<std::shared_ptr<const ImageTexture>>& textures,
             const Ray& ray, const SceneHit& hit, const SurfaceInfo& si) {
  // The material of the part hit (a CSG leaf's or an instance's own), as Scene::material_of.
  const int own = material_of(scene.objects[hit.object], hit.local);
  return albedo(scene, textures, ray, hit, si, std::size_t(own >= 0 ? own : 0));
}

}  // namespace raycast
