#include "render/camera.h"

#include <cmath>
#include <numbers>

namespace raycast {

Camera::Camera(const CameraDesc& desc, int width, int height)
    : type_(desc.type), origin_(desc.position), width_(width), height_(height) {
  w_ = normalize(desc.look_at - desc.position);
  u_ = normalize(cross(w_, desc.up));
  v_ = cross(u_, w_);
  const double aspect = double(width) / double(height);
  half_height_ = type_ == CameraType::kPerspective
                     ? std::tan(0.5 * desc.fov * std::numbers::pi / 180)
                     : 0.5 * desc.height;
  half_width_ = aspect * half_height_;
}

Ray Camera::ray(double x, double y) const {
  // Screen coordinates in [-1, 1], +sx to the right and +sy up.
  const double sx = 2 * x / width_ - 1;
  const double sy = 1 - 2 * y / height_;
  const Vec3 offset = (sx * half_width_) * u_ + (sy * half_height_) * v_;
  if (type_ == CameraType::kOrthographic) return {origin_ + offset, w_, 0, kInfinity};
  return {origin_, normalize(w_ + offset), 0, kInfinity};
}

}  // namespace raycast
