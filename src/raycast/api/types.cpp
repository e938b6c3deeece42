// The public value types' helpers (include/raycast/api/types.h).
#include <cmath>

#include "api/impl.h"
#include "io/scene_error.h"

namespace raycast::api {

namespace {

Transform from_engine(const raycast::Transform& t) {
  Transform r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[4 * i + j] = t.matrix().m[i][j];
  return r;
}

}  // namespace

RayArray RayArray::interleaved(const double* rays, std::size_t n) {
  return {rays, Type::kFloat64, n, 6 * sizeof(double), sizeof(double)};
}

RayArray RayArray::interleaved(const float* rays, std::size_t n) {
  return {rays, Type::kFloat32, n, 6 * sizeof(float), sizeof(float)};
}

RayArray RayArray::soa(const double* components, std::size_t n) {
  return {components, Type::kFloat64, n, sizeof(double),
          static_cast<std::ptrdiff_t>(n * sizeof(double))};
}

Transform Transform::translate(const Vec3d& t) {
  return from_engine(raycast::Transform::translate(to_engine(t)));
}

Transform Transform::scale(const Vec3d& s) {
  return from_engine(raycast::Transform::scale(to_engine(s)));
}

Transform Transform::rotate(const Vec3d& axis, double degrees) {
  return from_engine(raycast::Transform::rotate(to_engine(axis), degrees));
}

Transform operator*(const Transform& a, const Transform& b) {
  Transform r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[4 * i + k] * b.m[4 * k + j];
      r.m[4 * i + j] = s;
    }
  return r;
}

raycast::Transform to_engine(const Transform& t, const std::string& call) {
  raycast::Mat4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m.m[i][j] = t.m[4 * i + j];
  const auto xf = raycast::Transform::from_matrix(m);
  if (!xf)
    throw SceneError(call + ": the transform must be a finite, invertible affine matrix", call, 0,
                     0, "the transform must be a finite, invertible affine matrix");
  return *xf;
}

void rethrow_scene_error(const raycast::SceneError& e) {
  throw SceneError(e.what(), e.file(), e.line(), e.column(), e.message());
}

}  // namespace raycast::api
