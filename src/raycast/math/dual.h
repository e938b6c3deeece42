#pragma once
// Forward-mode automatic differentiation: a value and N partial derivatives, over double or
// Interval, for gradients of formulas (normals) and derivatives along a ray (Newton, monotonicity).
#include <cmath>

#include "math/interval.h"

namespace raycast {

/// a^n for a whole n, by repeated multiplication.
inline double pow_int(double a, int n) {
  double r = 1;
  const bool neg = n < 0;
  for (int i = 0; i < (neg ? -n : n); ++i) r *= a;
  return neg ? 1 / r : r;
}

template <class T, int N>
struct Dual {
  T v{};
  T d[N]{};

  Dual() = default;
  Dual(const T& value) : v(value) {  // NOLINT: constants have zero derivatives
    for (int i = 0; i < N; ++i) d[i] = T(0.0);
  }
};

namespace dual_detail {
inline double sign_of(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }
template <class T, int N>
Dual<T, N> chain(const Dual<T, N>& a, const T& value, const T& slope) {
  Dual<T, N> r;
  r.v = value;
  for (int i = 0; i < N; ++i) r.d[i] = slope * a.d[i];
  return r;
}
}  // namespace dual_detail

template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a) {
  Dual<T, N> r;
  r.v = -a.v;
  for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator+(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v + b.v;
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v - b.v;
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator*(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v * b.v;
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator/(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v / b.v;
  for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) / b.v;
  return r;
}
template <class T, int N>
Dual<T, N> sqrt(const Dual<T, N>& a) {
  using std::sqrt;
  const T s = sqrt(a.v);
  return dual_detail::chain(a, s, T(1.0) / (T(2.0) * s));
}
template <class T, int N>
Dual<T, N> exp(const Dual<T, N>& a) {
  using std::exp;
  const T e = exp(a.v);
  return dual_detail::chain(a, e, e);
}
template <class T, int N>
Dual<T, N> log(const Dual<T, N>& a) {
  using std::log;
  return dual_detail::chain(a, log(a.v), T(1.0) / a.v);
}
template <class T, int N>
Dual<T, N> sin(const Dual<T, N>& a) {
  using std::cos;
  using std::sin;
  return dual_detail::chain(a, sin(a.v), cos(a.v));
}
template <class T, int N>
Dual<T, N> cos(const Dual<T, N>& a) {
  using std::cos;
  using std::sin;
  return dual_detail::chain(a, cos(a.v), -sin(a.v));
}
// Over intervals, sin and cos of the value come from one sin_cos call.
template <int N>
Dual<Interval, N> sin(const Dual<Interval, N>& a) {
  Interval s, c;
  sin_cos(a.v, &s, &c);
  return dual_detail::chain(a, s, c);
}
template <int N>
Dual<Interval, N> cos(const Dual<Interval, N>& a) {
  Interval s, c;
  sin_cos(a.v, &s, &c);
  return dual_detail::chain(a, c, -s);
}
template <class T, int N>
Dual<T, N> tan(const Dual<T, N>& a) {
  using std::tan;
  const T t = tan(a.v);
  return dual_detail::chain(a, t, T(1.0) + t * t);
}
template <class T, int N>
Dual<T, N> abs(const Dual<T, N>& a) {
  using dual_detail::sign_of;
  using std::abs;
  return dual_detail::chain(a, abs(a.v), T(sign_of(a.v)));
}
/// a^n for a whole n.
template <class T, int N>
Dual<T, N> pow_int(const Dual<T, N>& a, int n) {
  if (n == 0) return Dual<T, N>(T(1.0));
  return dual_detail::chain(a, pow_int(a.v, n), T(double(n)) * pow_int(a.v, n - 1));
}
/// a^b = exp(b log a).
template <class T, int N>
Dual<T, N> pow(const Dual<T, N>& a, const Dual<T, N>& b) {
  return exp(b * log(a));
}

/// atan2(y, x): the angle of the point (x, y), d = (x dy - y dx) / (x^2 + y^2).
template <class T, int N>
Dual<T, N> atan2(const Dual<T, N>& y, const Dual<T, N>& x) {
  using std::atan2;
  Dual<T, N> r;
  r.v = atan2(y.v, x.v);
  const T r2 = x.v * x.v + y.v * y.v;
  for (int i = 0; i < N; ++i) r.d[i] = (x.v * y.d[i] - y.v * x.d[i]) / r2;
  return r;
}
/// floor: flat between its steps. Over an interval that holds a step the slope is unbounded.
template <int N>
Dual<double, N> floor(const Dual<double, N>& a) {
  return Dual<double, N>(std::floor(a.v));
}
template <int N>
Dual<Interval, N> floor(const Dual<Interval, N>& a) {
  Dual<Interval, N> r(floor(a.v));
  if (!(r.v.lo == r.v.hi))
    for (int i = 0; i < N; ++i) r.d[i] = Interval::entire();
  return r;
}

// min and max pick the smaller (larger) operand with its derivatives; over intervals, where the
// operands overlap, the hull of both.
template <int N>
Dual<double, N> min(const Dual<double, N>& a, const Dual<double, N>& b) {
  return b.v < a.v ? b : a;
}
template <int N>
Dual<double, N> max(const Dual<double, N>& a, const Dual<double, N>& b) {
  return b.v > a.v ? b : a;
}
template <int N>
Dual<Interval, N> min(const Dual<Interval, N>& a, const Dual<Interval, N>& b) {
  if (a.v.hi <= b.v.lo) return a;
  if (b.v.hi <= a.v.lo) return b;
  Dual<Interval, N> r;
  r.v = min(a.v, b.v);
  for (int i = 0; i < N; ++i) r.d[i] = hull(a.d[i], b.d[i]);
  return r;
}
template <int N>
Dual<Interval, N> max(const Dual<Interval, N>& a, const Dual<Interval, N>& b) {
  if (a.v.lo >= b.v.hi) return a;
  if (b.v.lo >= a.v.hi) return b;
  Dual<Interval, N> r;
  r.v = max(a.v, b.v);
  for (int i = 0; i < N; ++i) r.d[i] = hull(a.d[i], b.d[i]);
  return r;
}

}  // namespace raycast
