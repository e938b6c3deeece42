#pragma once
// Surface appearance for the Whitted integrator (docs/rendering.md "Shading").
#include <memory>
#include <string>

#include "math/vec3.h"

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
  bool fresnel = false;
};

}  // namespace raycast
