#pragma once
// 3-vectors of double (geometry, analytic shapes) and float (mesh storage).
#include <cmath>
#include <cstddef>

namespace raycast {

template <class T>
struct Vec3T {
  T x = 0, y = 0, z = 0;

  constexpr Vec3T() = default;
  constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <class U>
  constexpr explicit Vec3T(const Vec3T<U>& o) : x(T(o.x)), y(T(o.y)), z(T(o.z)) {}

  constexpr T operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3T operator-() const { return {-x, -y, -z}; }
  constexpr Vec3T& operator+=(const Vec3T& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr Vec3T& operator-=(const Vec3T& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  constexpr Vec3T& operator*=(T s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr Vec3T& operator/=(T s) {
    x /= s;
    y /= s;
    z /= s;
    return *this;
  }
  friend constexpr bool operator==(const Vec3T&, const Vec3T&) = default;
};

using Vec3 = Vec3T<double>;
using Vec3f = Vec3T<float>;

template <class T>
constexpr Vec3T<T> operator+(Vec3T<T> a, const Vec3T<T>& b) {
  return a += b;
}
template <class T>
constexpr Vec3T<T> operator-(Vec3T<T> a, const Vec3T<T>& b) {
  return a -= b;
}
template <class T>
constexpr Vec3T<T> operator*(Vec3T<T> a, T s) {
  return a *= s;
}
template <class T>
constexpr Vec3T<T> operator*(T s, Vec3T<T> a) {
  return a *= s;
}
template <class T>
constexpr Vec3T<T> operator/(Vec3T<T> a, T s) {
  return a /= s;
}

/// Component-wise product and quotient.
template <class T>
constexpr Vec3T<T> mul(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <class T>
constexpr Vec3T<T> div(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.x / b.x, a.y / b.y, a.z / b.z};
}

template <class T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
constexpr T length_squared(const Vec3T<T>& a) {
  return dot(a, a);
}
template <class T>
inline T length(const Vec3T<T>& a) {
  return std::sqrt(dot(a, a));
}
/// The unit vector along a; a zero vector gives NaNs (callers validate first).
template <class T>
inline Vec3T<T> normalize(const Vec3T<T>& a) {
  return a / length(a);
}
/// |a| per component by std::abs: clearing the sign bit, no compare and branch per component
/// (error bounds call it on every hit).
template <class T>
inline Vec3T<T> abs(const Vec3T<T>& a) {
  return {std::abs(a.x), std::abs(a.y), std::abs(a.z)};
}
template <class T>
constexpr Vec3T<T> min(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
template <class T>
constexpr Vec3T<T> max(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
template <class T>
constexpr T max_component(const Vec3T<T>& a) {
  return a.x > a.y ? (a.x > a.z ? a.x : a.z) : (a.y > a.z ? a.y : a.z);
}
/// Index (0, 1, 2) of the largest component.
template <class T>
constexpr int max_dimension(const Vec3T<T>& a) {
  return a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
}
template <class T>
inline bool is_finite(const Vec3T<T>& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// Two unit vectors (s, t) with (s, t, n) a right-handed orthonormal frame; n must be unit.
/// Duff et al. 2017, "Building an Orthonormal Basis, Revisited".
inline void make_frame(const Vec3& n, Vec3& s, Vec3& t) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  s = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  t = {b, sign + n.y * n.y * a, -n.y};
}

}  // namespace raycast
