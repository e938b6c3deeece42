#pragma once
// Surface colours: the material's colour, a checkerboard in object space, or an image through
// (u, v) (docs/scene-format.md "Materials").
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "io/image.h"
#include "scene/scene.h"

namespace raycast {

/// The texture colour at (u, v): u to the right, v up (v = 0 is the image's bottom row), repeated
/// outside [0, 1), bilinear between texel centres.
Color lookup(const ImageTexture& texture, double u, double v);

/// checker() for cells (x, y, z) = p / s not all within 2^51 of the origin (and NaN): the floors'
/// sum in double, c0 when it is not finite or at least 2^53.
Color checker_far(const CheckerTexture& texture, double x, double y, double z);

/// c0 where floor(x/s) + floor(y/s) + floor(z/s) is even, c1 where it is odd; p in object space.
inline Color checker(const CheckerTexture& texture, const Vec3& p) {
  const double s = texture.scale;
  const double x = p.x / s, y = p.y / s, z = p.z / s;
  // Cells within 2^51 of the origin (all of any real scene): the floors as integers, which are
  // exact there, and the parity of their sum (exact too: below 2^53, as the double sum is).
  constexpr double kNear = 0x1p51;
  if (!(std::abs(x) < kNear && std::abs(y) < kNear && std::abs(z) < kNear))
    return checker_far(texture, x, y, z);
  auto floor_int = [](double v) {
    const auto k = static_cast<std::int64_t>(v);  // towards zero
    return k - (v < static_cast<double>(k));
  };
  return ((floor_int(x) + floor_int(y) + floor_int(z)) & 1) == 0 ? texture.c0 : texture.c1;
}

/// Every material's image texture (nullptr where it has none), by material index: the one already
/// attached to the material, else loaded from its `image_file`. Throws SceneError naming the
/// scene when a file cannot be read.
std::vector<std::shared_ptr<const ImageTexture>> load_textures(const Scene& scene);

/// The colour a textured material (Material::texture) shows at a hit (texture::pigment_color).
Color textured_albedo(const Object& object, const Material& m, const Ray& ray, const SceneHit& hit);

/// The albedo C of a hit: its material's checker (at the object-space hit point), image texture
/// (at the surface's (u, v)) or colour. `ray` is the world ray that made the hit.
Color albedo(const Scene& scene, const std::vector<std::shared_ptr<const ImageTexture>>& textures,
             const Ray& ray, const SceneHit& hit, const SurfaceInfo& si);
/// The same with the hit's material index already resolved (material_of, negative taken as 0).
/// Inline: once per shaded hit.
inline Color albedo(const Scene& scene,
                    const std::vector<std::shared_ptr<const ImageTexture>>& textures,
                    const Ray& ray, const SceneHit& hit, const SurfaceInfo& si,
                    std::size_t material) {
  const Material& m = scene.materials[material];
  if (m.texture) [[unlikely]]
    return textured_albedo(scene.objects[hit.object], m, ray, hit);
  if (m.has_checker) {
    // The object-space point from the object-space ray, as the shape itself computed it.
    return checker(m.checker, to_object_space(scene.objects[hit.object], ray).at(hit.local.t));
  }
  if (material < textures.size() && textures[material])
    return lookup(*textures[material], si.u, si.v);
  return m.color;
}

}  // namespace raycast
