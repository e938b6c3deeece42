#pragma once
// Affine transforms as 4x4 row-major matrices that map points p' = M p (translation in the fourth
// column), stored with their inverse so rays go to object space and normals come back cheaply.
#include <array>
#include <cmath>
#include <optional>

#include "math/float_error.h"
#include "math/vec3.h"

namespace raycast {

struct Mat4 {
  std::array<std::array<double, 4>, 4> m{};

  static constexpr Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
  }
  friend bool operator==(const Mat4&, const Mat4&) = default;
};

Mat4 operator*(const Mat4& a, const Mat4& b);
Mat4 transpose(const Mat4& a);
/// The inverse by Gauss-Jordan elimination with partial pivoting; nullopt when singular
/// (a pivot below 1e-300 relative to the matrix's largest entry) or not finite.
std::optional<Mat4> inverse(const Mat4& a);

class Transform {
 public:
  /// The identity.
  Transform() = default;
  /// A transform from M and its inverse; the caller guarantees inv is M's inverse.
  Transform(const Mat4& m, const Mat4& inv)
      : m_(m), inv_(inv), translation_(is_translation(m) && is_translation(inv)) {}
  /// nullopt when M is singular or has a projective last row (not affine).
  static std::optional<Transform> from_matrix(const Mat4& m);

  static Transform translate(const Vec3& t);
  static Transform scale(const Vec3& s);  // every s component must be non-zero
  /// A rotation by `degrees` about `axis` (right-hand rule); axis must be non-zero.
  static Transform rotate(const Vec3& axis, double degrees);

  const Mat4& matrix() const { return m_; }
  const Mat4& inverse_matrix() const { return inv_; }
  Transform inverse() const { return Transform(inv_, m_); }
  bool is_identity() const { return m_ == Mat4::identity(); }
  /// True when the transform reverses orientation (a mirror): det < 0.
  bool flips_handedness() const;

  Vec3 point(const Vec3& p) const {
    return translation_ ? translate_point(m_, p) : apply_point(m_, p);
  }
  Vec3 vector(const Vec3& v) const { return translation_ ? unit_rows(v) : apply_vector(m_, v); }
  /// Normals map by the inverse transpose (result not normalised).
  Vec3 normal(const Vec3& n) const {
    if (translation_) return unit_rows(n);
    const auto& a = inv_.m;
    return {a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z,
            a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z,
            a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z};
  }
  Vec3 inverse_point(const Vec3& p) const {
    return translation_ ? translate_point(inv_, p) : apply_point(inv_, p);
  }
  Vec3 inverse_vector(const Vec3& v) const {
    return translation_ ? unit_rows(v) : apply_vector(inv_, v);
  }
  /// Bounds on the absolute rounding error of point(p), per component (pbrt-v4 6.8.6).
  Vec3 point_error(const Vec3& p) const {
    return translation_ ? translation_error(m_, p) : apply_point_error(m_, p);
  }
  /// The same for inverse_point(p) (no Transform copy, unlike inverse().point_error(p)).
  Vec3 inverse_point_error(const Vec3& p) const {
    return translation_ ? translation_error(inv_, p) : apply_point_error(inv_, p);
  }
  /// |M| v: v through the magnitudes of the linear part's entries (error bounds carried through
  /// point()), summed in apply_vector's order.
  Vec3 abs_vector(const Vec3& v) const {
    if (translation_) return unit_rows(v);
    const auto& r = m_.m;
    return {std::abs(r[0][0]) * v.x + std::abs(r[0][1]) * v.y + std::abs(r[0][2]) * v.z,
            std::abs(r[1][0]) * v.x + std::abs(r[1][1]) * v.y + std::abs(r[1][2]) * v.z,
            std::abs(r[2][0]) * v.x + std::abs(r[2][1]) * v.y + std::abs(r[2][2]) * v.z};
  }

  /// This transform applied after `first`: (this * first)(p) = this(first(p)).
  Transform operator*(const Transform& first) const {
    return Transform(m_ * first.m_, first.inv_ * inv_);
  }

  static Vec3 apply_point(const Mat4& a, const Vec3& p) {
    const auto& r = a.m;
    return {r[0][0] * p.x + r[0][1] * p.y + r[0][2] * p.z + r[0][3],
            r[1][0] * p.x + r[1][1] * p.y + r[1][2] * p.z + r[1][3],
            r[2][0] * p.x + r[2][1] * p.y + r[2][2] * p.z + r[2][3]};
  }
  static Vec3 apply_point_error(const Mat4& a, const Vec3& p) {
    const auto& r = a.m;
    Vec3 e;
    for (int i = 0; i < 3; ++i)
      e[i] = gamma(3) * (std::abs(r[i][0] * p.x) + std::abs(r[i][1] * p.y) +
                         std::abs(r[i][2] * p.z) + std::abs(r[i][3]));
    return e;
  }
  static Vec3 apply_vector(const Mat4& a, const Vec3& v) {
    const auto& r = a.m;
    return {r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
            r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
            r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z};
  }

 private:
  // Translations (the upper 3x3 exactly the identity, its zeros +0) skip the products by 1, and
  // share the products by +0 between the rows: the same sums in the same order as apply_point /
  // apply_vector, so the same bits (1 * x == x for every x; 0 * x keeps x's -0, inf and NaN).
  static bool is_translation(const Mat4& a) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i == j ? a.m[i][j] != 1 : (a.m[i][j] != 0 || std::signbit(a.m[i][j]))) return false;
    return true;
  }
  // apply_vector of the identity with +0 off the diagonal.
  static Vec3 unit_rows(const Vec3& v) {
    const double zx = 0.0 * v.x, zy = 0.0 * v.y, zz = 0.0 * v.z;
    return {(v.x + zy) + zz, (zx + v.y) + zz, (zx + zy) + v.z};
  }
  static Vec3 translate_point(const Mat4& a, const Vec3& p) {
    const Vec3 u = unit_rows(p);
    return {u.x + a.m[0][3], u.y + a.m[1][3], u.z + a.m[2][3]};
  }
  // apply_point_error of a translation: |r p| is |r| |p| exactly, and the magnitudes of the
  // identity with +0 off the diagonal are itself.
  static Vec3 translation_error(const Mat4& a, const Vec3& p) {
    const Vec3 u = unit_rows(abs(p));
    return gamma(3) *
           Vec3{u.x + std::abs(a.m[0][3]), u.y + std::abs(a.m[1][3]), u.z + std::abs(a.m[2][3])};
  }

  Mat4 m_ = Mat4::identity();
  Mat4 inv_ = Mat4::identity();
  bool translation_ = true;
};

}  // namespace raycast
