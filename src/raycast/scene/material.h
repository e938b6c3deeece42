#pragma once
// Surface appearance for the Whitted integrator (docs/rendering.md "Shading").
#include <cmath>
#include <memory>
#include <string>

#include "math/transform.h"
#include "math/vec3.h"
#include "texture/texture_stack.h"

namespace raycast {

using Color = Vec3;  // linear RGB

struct CheckerTexture {
  Color c0{0.9, 0.9, 0.9};
  Color c1{0.2, 0.2, 0.2};
  double scale = 1;  // cell size in object-space units, > 0
};

struct ImageTexture;  // io/image.h: loaded with the scene, looked up through (u, v)

struct Material {
  std::string name;
  Color color{0.8, 0.8, 0.8};
  bool has_checker = false;
  CheckerTexture checker;
  std::shared_ptr<const ImageTexture> image;  // set when the material uses `texture: {image: ...}`
  std::string image_file;
  double ambient = 1;
  double diffuse = 0.8;
  double specular = 0;
  double shininess = 32;
  double reflection = 0;
  double transmission = 0;
  double ior = 1;
  // The ratio of violet's index of refraction to red's (1: none), and the bands a refracted ray
  // is split into (render/dispersion.h).
  double dispersion = 1;
  int dispersion_samples = 7;
  bool fresnel = false;
  // Light travelling inside the object is attenuated with the distance (POV-Ray's interior
  // fade, interior_fade below); fade_distance or fade_power 0: no attenuation.
  double fade_distance = 0, fade_power = 0;
  Color fade_color{0, 0, 0};
  // A patterned or layered texture with POV-Ray's finish (docs/textures.md): when set, it gives
  // the colour, normal and finish of every hit and the fields above other than ior are not used.
  // Null: the plain path above, which pays nothing for textures.
  std::shared_ptr<const texture::TextureStack> texture;
  Transform texture_transform;  // object space -> texture space
};

/// Whether light inside a material with m's interior fades with distance.
inline bool fades(const Material& m) { return m.fade_distance > 0 && m.fade_power > 0; }

/// What is left of light after `distance` inside m (per channel, 1 when m does not fade):
/// POV-Ray's a = 1 / (1 + (distance / fade_distance)^fade_power) blended towards fade_color,
/// fade_color + (1 - fade_color) a; with fade_power 1000 or more, the exponential
/// exp(-(1 - fade_color) distance / fade_distance). An infinite distance (a ray that leaves
/// through an open surface and meets nothing) leaves fade_color (0 in the exponential form).
inline Color interior_fade(const Material& m, double distance) {
  if (!fades(m)) return {1, 1, 1};
  const double x = distance / m.fade_distance;
  if (m.fade_power >= 1000) {
    auto channel = [&](double c) { return c >= 1 ? 1.0 : std::exp(-(1 - c) * x); };
    return {channel(m.fade_color.x), channel(m.fade_color.y), channel(m.fade_color.z)};
  }
  const double a = 1 / (1 + std::pow(x, m.fade_power));
  return m.fade_color + a * (Color{1, 1, 1} - m.fade_color);
}

}  // namespace raycast
