#pragma once
// Surface appearance for the Whitted integrator (docs/rendering.md "Shading").
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
  bool fresnel = false;
  // A patterned or layered texture with POV-Ray's finish (docs/textures.md): when set, it gives
  // the colour, normal and finish of every hit and the fields above other than ior are not used.
  // Null: the plain path above, which pays nothing for textures.
  std::shared_ptr<const texture::TextureStack> texture;
  Transform texture_transform;  // object space -> texture space
};

}  // namespace raycast
