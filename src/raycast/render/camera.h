#pragma once
// Primary rays (docs/rendering.md "Camera", docs/scene-format.md "Cameras"): a pinhole
// perspective camera, an orthographic one, and POV-Ray's lenses (fisheye, ultra-wide-angle,
// omnimax, panoramic, cylinder 1 to 4, spherical).
#include "geometry/ray.h"
#include "scene/render_settings.h"

namespace raycast {

class Camera {
 public:
  /// A camera for a width x height image (both >= 1). The desc must be valid (the loader checks):
  /// look_at != position, up not parallel to the viewing direction, fov in (0, 180), height > 0,
  /// angle in (0, 360]; or a frame of non-zero vectors, right and up not parallel.
  Camera(const CameraDesc& desc, int width, int height);

  /// The ray through the raster position (x, y): x from 0 (left edge) to width, y from 0 (top
  /// edge) to height, so pixel (i, j) covers [i, i+1] x [j, j+1]. The direction is unit length, so
  /// t is the distance from the origin; tmin = 0, tmax = inf. Where a lens sees nothing (outside
  /// a fisheye's circle) the ray is empty: tmax < tmin, and the pixel is black.
  Ray ray(double x, double y) const;  // inline below: called once per sample

  const Vec3& forward() const { return w_; }

 private:
  /// The lenses' rays, from screen coordinates in [-1, 1] (+sx right, +sy up).
  Ray lens_ray(double sx, double sy) const;

  CameraType type_;
  Vec3 origin_;
  Vec3 d_;          // the image plane's centre from the origin (perspective)
  Vec3 u_, v_, w_;  // unit right, up and forward (an orthonormal right-handed frame unless a
                    // CameraDesc::frame gives them otherwise)
  double half_width_, half_height_;  // of the image plane at d_ (perspective) or in units
  double width_, height_;
  double angle_, vertical_angle_;  // the lenses' fields, radians
  int cylinder_;
};

inline Ray Camera::ray(double x, double y) const {
  // Screen coordinates in [-1, 1], +sx to the right and +sy up.
  const double sx = 2 * x / width_ - 1;
  const double sy = 1 - 2 * y / height_;
  if (type_ != CameraType::kPerspective && type_ != CameraType::kOrthographic)
    return lens_ray(sx, sy);
  const Vec3 offset = (sx * half_width_) * u_ + (sy * half_height_) * v_;
  if (type_ == CameraType::kOrthographic) return {origin_ + offset, w_, 0, kInfinity};
  return {origin_, normalize(d_ + offset), 0, kInfinity};
}

}  // namespace raycast
