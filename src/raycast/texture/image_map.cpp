#include "texture/image_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace raycast::texture {

namespace {

// The angle about y from +x towards +z, in turns [0, 1) (POV-Ray's map_pos).
double turns_about_y(double x, double z) {
  const double len = std::sqrt(x * x + z * z);
  if (len == 0) return 0;
  double theta = std::acos(std::clamp(x / len, -1.0, 1.0));
  if (z < 0) theta = 2 * std::numbers::pi - theta;
  return theta / (2 * std::numbers::pi);
}

ImagePixel lerp(const ImagePixel& a, const ImagePixel& b, float t) {
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b),
          a.filter + t * (b.filter - a.filter), a.transmit + t * (b.transmit - a.transmit)};
}

}  // namespace

bool image_uv(const ImageMap& map, const Vec3& p, double& u, double& v) {
  switch (map.projection) {
    case ImageProjection::kPlanar:
      u = p.x, v = p.y;
      break;
    case ImageProjection::kSpherical: {
      const double len = length(p);
      if (!(len > 0)) return false;
      u = turns_about_y(p.x, p.z);
      v = 0.5 + std::asin(std::clamp(p.y / len, -1.0, 1.0)) / std::numbers::pi;
      break;
    }
    case ImageProjection::kCylindrical:
      u = turns_about_y(p.x, p.z);
      v = p.y;
      break;
  }
  if (!std::isfinite(u) || !std::isfinite(v)) return false;
  if (map.once) return u >= 0 && u <= 1 && v >= 0 && v <= 1;
  u -= std::floor(u);
  v -= std::floor(v);
  return true;
}

ImagePixel image_sample(const ImageMap& map, double u, double v) {
  if (map.width <= 0 || map.height <= 0) return {};
  const int w = map.width, h = map.height;
  auto at = [&](int x, int y) -> const ImagePixel& {
    // Repeated images wrap at their edges, a single copy stops at them.
    x = map.once ? std::clamp(x, 0, w - 1) : ((x % w) + w) % w;
    y = map.once ? std::clamp(y, 0, h - 1) : ((y % h) + h) % h;
    return map.pixels[std::size_t(y) * std::size_t(w) + std::size_t(x)];
  };
  // Column from the left, row from the top (v = 0 is the bottom edge).
  const double x = u * w, y = (1 - v) * h;
  if (!map.interpolate) {
    const int ix = std::clamp(int(std::floor(x)), 0, w - 1);
    const int iy = std::clamp(int(std::floor(y)), 0, h - 1);
    return at(ix, iy);
  }
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const auto tx = float(fx - x0), ty = float(fy - y0);
  return lerp(lerp(at(x0, y0), at(x0 + 1, y0), tx), lerp(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx),
              ty);
}

}  // namespace raycast::texture
