#include "render/camera.h"

#include <cmath>
#include <numbers>

namespace raycast {

namespace {
constexpr double kRadians = std::numbers::pi / 180;
}  // namespace

Camera::Camera(const CameraDesc& desc, int width, int height)
    : type_(desc.type),
      origin_(desc.position),
      width_(width),
      height_(height),
      angle_(desc.angle * kRadians),
      vertical_angle_((desc.vertical_angle > 0 ? desc.vertical_angle : 0.5 * desc.angle) *
                      kRadians),
      cylinder_(desc.cylinder) {
  if (desc.frame) {
    // POV-Ray's vectors as they are: the image spans right x up at direction, whatever the
    // image's own aspect.
    const CameraFrame& f = *desc.frame;
    d_ = f.direction;
    w_ = normalize(f.direction);
    u_ = normalize(f.right);
    v_ = normalize(f.up);
    half_width_ = 0.5 * length(f.right);
    half_height_ = 0.5 * length(f.up);
    return;
  }
  w_ = normalize(desc.look_at - desc.position);
  u_ = normalize(cross(w_, desc.up));
  v_ = cross(u_, w_);
  d_ = w_;
  const double aspect = double(width) / double(height);
  // The lenses read right and up as POV-Ray's default camera has them: up of length 1, right
  // of the image's aspect.
  half_height_ = type_ == CameraType::kPerspective    ? std::tan(0.5 * desc.fov * kRadians)
                 : type_ == CameraType::kOrthographic ? 0.5 * desc.height
                                                      : 0.5;
  half_width_ = aspect * half_height_;
}

Ray Camera::lens_ray(double sx, double sy) const {
  // x and y in [-0.5, 0.5] across the image, as POV-Ray measures its screen.
  const double x = 0.5 * sx, y = 0.5 * sy;
  const double aspect = half_width_ / half_height_;
  Vec3 origin = origin_, dir;
  switch (type_) {
    case CameraType::kFisheye:
    case CameraType::kOmnimax: {
      // Polar: the distance from the centre (in units of the image's height) is the angle from
      // the view direction, the circle of diameter 1 spanning `angle` (omnimax: drawn as a
      // fisheye of 180 degrees).
      const double px = x * aspect, py = y;
      const double r = std::hypot(px, py);
      if (r > 0.5) return {origin_, w_, 1, 0};  // outside the circle: no ray
      const double theta = r * (type_ == CameraType::kOmnimax ? std::numbers::pi : angle_);
      const double phi = std::atan2(py, px);
      dir = std::cos(theta) * w_ + std::sin(theta) * (std::cos(phi) * u_ + std::sin(phi) * v_);
      break;
    }
    case CameraType::kUltraWideAngle: {
      const double xa = x * angle_, ya = y * angle_ / aspect;
      dir = std::sin(xa) * u_ + std::sin(ya) * v_ + std::cos(xa) * std::cos(ya) * w_;
      break;
    }
    case CameraType::kPanoramic: {
      // Longitude and latitude across 180 degrees each, on the ellipsoid whose axes are right, up
      // and direction with their lengths (with equal lengths: a sphere).
      const double lon = x * std::numbers::pi, lat = y * std::numbers::pi;
      dir = (std::cos(lat) * std::sin(lon) * 2 * half_width_) * u_ +
            (std::sin(lat) * 2 * half_height_) * v_ + (std::cos(lat) * std::cos(lon)) * d_;
      break;
    }
    case CameraType::kCylinder: {
      const bool vertical = cylinder_ == 1 || cylinder_ == 3;
      const bool moving = cylinder_ == 3 || cylinder_ == 4;
      // Around the cylinder's axis by the angle; along it by the image's other side.
      const double a = (vertical ? x : y) * angle_;
      const Vec3& across = vertical ? u_ : v_;
      const Vec3 along = vertical ? (y * 2 * half_height_) * v_ : (x * 2 * half_width_) * u_;
      dir = std::sin(a) * across + std::cos(a) * w_;
      if (moving)
        origin = origin_ + along;
      else
        dir = dir + along;
      break;
    }
    case CameraType::kSpherical: {
      const double lon = x * angle_, lat = y * vertical_angle_;
      dir = std::cos(lat) * (std::sin(lon) * u_ + std::cos(lon) * w_) + std::sin(lat) * v_;
      break;
    }
    default:
      dir = w_;
  }
  return {origin, normalize(dir), 0, kInfinity};
}

}  // namespace raycast
