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

}  // namespace raycast
