#pragma once
// POV-Ray's image maps (docs/textures.md "Image maps"): an image wrapped onto the pattern's space
// by a projection (map_type), repeated or shown once, sampled at the nearest pixel or
// bilinearly; image_map pigments take its colours, image_pattern its grey.
#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace raycast::texture {

/// The projections of POV-Ray's map_type: 0 planar (the image on the unit square of the xy
/// plane, seen along z), 1 spherical (longitude and latitude about the y axis), 2 cylindrical
/// (the angle about y, and y).
enum class ImageProjection : std::uint8_t { kPlanar, kSpherical, kCylindrical };

struct ImagePixel {
  float r = 0, g = 0, b = 0, filter = 0, transmit = 0;
};

struct ImageMap {
  int width = 0, height = 0;
  std::vector<ImagePixel> pixels;  // linear colours, row-major, the top row first
  ImageProjection projection = ImageProjection::kPlanar;
  bool once = false;         // outside the image's one copy: clear (transmit 1)
  bool interpolate = false;  // bilinear between pixel centres, else the nearest pixel
  bool transmits = false;    // some pixel has filter or transmit above 0
};

/// The image's (u, v) in [0, 1)² at a point of the pattern's space; false where the image does
/// not reach (`once` outside its copy, the projection's centre).
bool image_uv(const ImageMap& map, const Vec3& p, double& u, double& v);

/// The image's colour at (u, v) (v = 0 the bottom row).
ImagePixel image_sample(const ImageMap& map, double u, double v);

/// POV-Ray's grey of a colour: the weights of its `gray` (0.297, 0.589, 0.114).
inline double image_grey(const ImagePixel& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

}  // namespace raycast::texture
