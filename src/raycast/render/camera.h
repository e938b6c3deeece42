#pragma once
// Primary rays (docs/rendering.md "Camera"): a pinhole perspective camera with a vertical field of
// view, or an orthographic one whose `height` is the full view height in scene units.
#include "geometry/ray.h"
#include "scene/render_settings.h"

namespace raycast {

class Camera {
 public:
  /// A camera for a width x height image (both >= 1). The desc must be valid (the loader checks):
  /// look_at != position, up not parallel to the viewing direction, fov in (0, 180), height > 0.
  Camera(const CameraDesc& desc, int width, int height);

  /// The ray through the raster position (x, y): x from 0 (left edge) to width, y from 0 (top
  /// edge) to height, so pixel (i, j) covers [i, i+1] x [j, j+1]. The direction is unit length, so
  /// t is the distance from the origin; tmin = 0, tmax = inf.
  Ray ray(double x, double y) const;  // inline below: called once per sample

  const Vec3& forward() const { return w_; }

 private:
  CameraType type_;
  Vec3 origin_;
  Vec3 u_, v_, w_;  // right, up, forward: an orthonormal right-handed frame (u x v = -w)
  double half_width_, half_height_;  // of the image plane at distance 1 (perspective) or in units
  double width_, height_;
};

inline Ray Camera::ray(double x, double y) const {
  // Screen coordinates in [-1, 1], +sx to the right and +sy up.
  const double sx = 2 * x / width_ - 1;
  const double sy = 1 - 2 * y / height_;
  const Vec3 offset = (sx * half_width_) * u_ + (sy * half_height_) * v_;
  if (type_ == CameraType::kOrthographic) return {origin_ + offset, w_, 0, kInfinity};
  return {origin_, normalize(w_ + offset), 0, kInfinity};
}

}  // namespace raycast
