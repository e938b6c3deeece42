#include "math/transform.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "math/float_error.h"

namespace raycast {

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Mat4 transpose(const Mat4& a) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

std::optional<Mat4> inverse(const Mat4& a) {
  // Relative singularity threshold: a pivot this small against the largest entry means the
  // matrix cannot be inverted to any useful precision.
  constexpr double kSingularRelative = 1e-300;
  Mat4 l = a;
  Mat4 r = Mat4::identity();
  double scale = 0;
  for (const auto& row : a.m)
    for (double v : row) {
      if (!std::isfinite(v)) return std::nullopt;
      scale = std::max(scale, std::abs(v));
    }
  if (scale == 0) return std::nullopt;
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int i = c + 1; i < 4; ++i)
      if (std::abs(l.m[i][c]) > std::abs(l.m[pivot][c])) pivot = i;
    if (std::abs(l.m[pivot][c]) <= kSingularRelative * scale) return std::nullopt;
    std::swap(l.m[c], l.m[pivot]);
    std::swap(r.m[c], r.m[pivot]);
    const double inv_p = 1.0 / l.m[c][c];
    for (int j = 0; j < 4; ++j) {
      l.m[c][j] *= inv_p;
      r.m[c][j] *= inv_p;
    }
    for (int i = 0; i < 4; ++i) {
      if (i == c) continue;
      const double f = l.m[i][c];
      if (f == 0) continue;
      for (int j = 0; j < 4; ++j) {
        l.m[i][j] -= f * l.m[c][j];
        r.m[i][j] -= f * r.m[c][j];
      }
    }
  }
  for (const auto& row : r.m)
    for (double v : row)
      if (!std::isfinite(v)) return std::nullopt;
  return r;
}

std::optional<Transform> Transform::from_matrix(const Mat4& m) {
  if (m.m[3][0] != 0 || m.m[3][1] != 0 || m.m[3][2] != 0 || m.m[3][3] != 1) return std::nullopt;
  auto inv = raycast::inverse(m);
  if (!inv) return std::nullopt;
  // Exact affine last row for the inverse too (elimination may leave tiny residues).
  inv->m[3] = {0, 0, 0, 1};
  return Transform(m, *inv);
}

Transform Transform::translate(const Vec3& t) {
  Mat4 m = Mat4::identity(), inv = Mat4::identity();
  m.m[0][3] = t.x, m.m[1][3] = t.y, m.m[2][3] = t.z;
  inv.m[0][3] = -t.x, inv.m[1][3] = -t.y, inv.m[2][3] = -t.z;
  return Transform(m, inv);
}

Transform Transform::scale(const Vec3& s) {
  Mat4 m = Mat4::identity(), inv = Mat4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][i] = s[i];
    inv.m[i][i] = 1.0 / s[i];
  }
  return Transform(m, inv);
}

Transform Transform::rotate(const Vec3& axis, double degrees) {
  const Vec3 a = normalize(axis);
  const double theta = degrees * std::numbers::pi / 180.0;
  const double s = std::sin(theta), c = std::cos(theta);
  Mat4 m = Mat4::identity();
  // Rodrigues' rotation formula as a matrix.
  m.m[0][0] = a.x * a.x + (1 - a.x * a.x) * c;
  m.m[0][1] = a.x * a.y * (1 - c) - a.z * s;
  m.m[0][2] = a.x * a.z * (1 - c) + a.y * s;
  m.m[1][0] = a.x * a.y * (1 - c) + a.z * s;
  m.m[1][1] = a.y * a.y + (1 - a.y * a.y) * c;
  m.m[1][2] = a.y * a.z * (1 - c) - a.x * s;
  m.m[2][0] = a.x * a.z * (1 - c) - a.y * s;
  m.m[2][1] = a.y * a.z * (1 - c) + a.x * s;
  m.m[2][2] = a.z * a.z + (1 - a.z * a.z) * c;
  return Transform(m, transpose(m));
}

bool Transform::flips_handedness() const {
  const auto& a = m_.m;
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  return det < 0;
}

}  // namespace raycast
