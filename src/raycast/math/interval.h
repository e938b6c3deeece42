#pragma once
// Interval arithmetic with outward rounding, for inclusion functions of formulas over t-intervals.
// Every result contains the exact result of the operation over every point of its operands: the
// basic operations are widened by one ulp each side (round-to-nearest is off by at most half an
// ulp), the library's transcendental functions by kLibmUlps (glibc documents errors of a few ulps).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace raycast {

/// Error allowance of libm's transcendental functions, in ulps.
inline constexpr int kLibmUlps = 4;

/// The closed interval [lo, hi]; empty (lo > hi, or NaN) stands for "undefined here" (sqrt or log
/// of negative numbers) and propagates through every operation.
struct Interval {
  double lo = 0, hi = 0;

  Interval() = default;
  constexpr Interval(double v) : lo(v), hi(v) {}  // NOLINT: a point is an interval
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  static constexpr Interval entire() {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  static constexpr Interval empty() {
    return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  }
  bool is_empty() const { return !(lo <= hi); }
  bool contains(double v) const { return lo <= v && v <= hi; }
  double mid() const { return 0.5 * (lo + hi); }
};

namespace interval_detail {
// x moved ulps representable doubles towards +infinity, as ulps calls of std::nextafter(x, +inf)
// would (zero counts once; the largest finite double goes to +inf; NaN stays NaN), by stepping
// the bit pattern: among doubles of one sign the order of magnitudes is the order of patterns.
inline double up(double x, int ulps = 1) {
  constexpr std::uint64_t kSign = 0x8000000000000000ull, kInf = 0x7ff0000000000000ull;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const std::uint64_t magnitude = bits & ~kSign, n = static_cast<std::uint64_t>(ulps);
  if (magnitude > kInf) return x;         // NaN
  if (!(bits & kSign) || magnitude == 0)  // +x or a zero: the magnitude grows, up to +inf
    return std::bit_cast<double>(std::min(magnitude + n, kInf));
  if (magnitude >= n) return std::bit_cast<double>(kSign | (magnitude - n));  // -x shrinks
  return std::bit_cast<double>(n - magnitude);  // through zero to the positive side
}
inline double down(double x, int ulps = 1) { return -up(-x, ulps); }
inline Interval widen(double lo, double hi, int ulps) {
  if (std::isnan(lo) || std::isnan(hi)) return Interval::entire();
  return {down(lo, ulps), up(hi, ulps)};
}
// [lo, hi] widened by at least one ulp each side, without branches on the common path: for a
// double x with 2^e <= |x| < 2^(e+1), |x| 2^-52 >= 2^(e-52) = ulp(x) (2^-1074 covers zero and
// subnormals), so x -+ (|x| 2^-52 + 2^-1074) rounds (monotonely) to at or beyond x's neighbour.
// Infinite or NaN ends take the exact ulp-stepping path above.
inline Interval widen(double lo, double hi) {
  constexpr double kRel = 0x1p-52, kAbs = 0x1p-1074;
  const double l = lo - (std::abs(lo) * kRel + kAbs), h = hi + (std::abs(hi) * kRel + kAbs);
  if (l <= h && h - l < std::numeric_limits<double>::infinity()) return {l, h};
  return widen(lo, hi, 1);
}
// sin x and cos x from one libm call where the library has sincos (glibc), which costs about
// as much as one of them. Declared under another name bound to the same symbol: GCC knows
// ::sincos as a builtin and splits it back into sin and cos calls when it inlines the caller.
#if defined(__GLIBC__)
extern "C" void raycast_libm_sincos(double x, double* s, double* c) __asm__("sincos");
#endif
inline void sincos(double x, double* s, double* c) {
#if defined(__GLIBC__)
  raycast_libm_sincos(x, s, c);
#else
  *s = std::sin(x);
  *c = std::cos(x);
#endif
}
// 0 * inf is 0 for interval bounds.
inline double mul0(double a, double b) { return (a == 0 || b == 0) ? 0.0 : a * b; }
// Whether some c + k period lies in [lo, hi] (conservatively: a little slack says yes).
inline bool hits_phase(double lo, double hi, double c, double period) {
  const double k = std::ceil((lo - c) / period - 1e-9);
  return c + k * period <= hi + 1e-9 * (1 + std::abs(hi));
}
}  // namespace interval_detail

inline Interval hull(const Interval& a, const Interval& b) {
  if (a.is_empty()) return b;
  if (b.is_empty()) return a;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator+(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return interval_detail::widen(a.lo + b.lo, a.hi + b.hi);
}
inline Interval operator-(const Interval& a, const Interval& b) { return a + (-b); }
inline Interval operator*(const Interval& a, const Interval& b) {
  using interval_detail::mul0;
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  const double p[4] = {mul0(a.lo, b.lo), mul0(a.lo, b.hi), mul0(a.hi, b.lo), mul0(a.hi, b.hi)};
  return interval_detail::widen(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
}
inline Interval operator/(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  if (b.contains(0)) return Interval::entire();
  return a * interval_detail::widen(1 / b.hi, 1 / b.lo);
}

inline Interval sqrt(const Interval& a) {
  if (a.is_empty() || a.hi < 0) return Interval::empty();
  return interval_detail::widen(std::sqrt(std::max(a.lo, 0.0)), std::sqrt(a.hi));
}
inline Interval exp(const Interval& a) {
  if (a.is_empty()) return a;
  const Interval r = interval_detail::widen(std::exp(a.lo), std::exp(a.hi), kLibmUlps);
  return {std::max(r.lo, 0.0), r.hi};
}
inline Interval log(const Interval& a) {
  if (a.is_empty() || a.hi <= 0) return Interval::empty();
  const double lo = a.lo <= 0 ? -std::numeric_limits<double>::infinity() : std::log(a.lo);
  return interval_detail::widen(lo, std::log(a.hi), kLibmUlps);
}
/// sin(a) and cos(a) together, from one sincos of each end (either output may be null).
inline void sin_cos(const Interval& a, Interval* sin_a, Interval* cos_a) {
  using interval_detail::hits_phase;
  if (a.is_empty()) {
    if (sin_a) *sin_a = a;
    if (cos_a) *cos_a = a;
    return;
  }
  constexpr double kTwoPi = 2 * std::numbers::pi;
  if (!(a.hi - a.lo < kTwoPi) || std::abs(a.lo) > 1e15 || std::abs(a.hi) > 1e15) {
    if (sin_a) *sin_a = {-1, 1};
    if (cos_a) *cos_a = {-1, 1};
    return;
  }
  double s0, c0, s1, c1;
  interval_detail::sincos(a.lo, &s0, &c0);
  interval_detail::sincos(a.hi, &s1, &c1);
  auto clamp = [](const Interval& r) {
    return Interval{std::max(r.lo, -1.0), std::min(r.hi, 1.0)};
  };
  if (sin_a) {
    double lo = std::min(s0, s1), hi = std::max(s0, s1);
    if (hits_phase(a.lo, a.hi, std::numbers::pi / 2, kTwoPi)) hi = 1;
    if (hits_phase(a.lo, a.hi, -std::numbers::pi / 2, kTwoPi)) lo = -1;
    *sin_a = clamp(interval_detail::widen(lo, hi, kLibmUlps));
  }
  if (cos_a) {
    double lo = std::min(c0, c1), hi = std::max(c0, c1);
    if (hits_phase(a.lo, a.hi, 0, kTwoPi)) hi = 1;
    if (hits_phase(a.lo, a.hi, std::numbers::pi, kTwoPi)) lo = -1;
    *cos_a = clamp(interval_detail::widen(lo, hi, kLibmUlps));
  }
}
inline Interval cos(const Interval& a) {
  Interval c;
  sin_cos(a, nullptr, &c);
  return c;
}
inline Interval sin(const Interval& a) {
  Interval s;
  sin_cos(a, &s, nullptr);
  return s;
}
inline Interval tan(const Interval& a) {
  if (a.is_empty()) return a;
  if (!(a.hi - a.lo < std::numbers::pi) || std::abs(a.lo) > 1e15 ||
      interval_detail::hits_phase(a.lo, a.hi, std::numbers::pi / 2, std::numbers::pi))
    return Interval::entire();
  return interval_detail::widen(std::tan(a.lo), std::tan(a.hi), kLibmUlps);
}
inline Interval abs(const Interval& a) {
  if (a.is_empty() || a.lo >= 0) return a;
  if (a.hi <= 0) return -a;
  return {0, std::max(-a.lo, a.hi)};
}
inline Interval min(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}
inline Interval max(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}
/// floor is exact: the steps of the ends.
inline Interval floor(const Interval& a) {
  if (a.is_empty()) return a;
  return {std::floor(a.lo), std::floor(a.hi)};
}
/// atan2(y, x): the angles of the points of the box y x x. A box that touches the cut (x <= 0,
/// y = 0) or the origin takes the whole range; any other box is convex and sees the origin under
/// less than pi, so its angles are those between its corners' angles.
inline Interval atan2(const Interval& y, const Interval& x) {
  if (y.is_empty() || x.is_empty()) return Interval::empty();
  if (x.lo <= 0 && y.contains(0))
    return interval_detail::widen(-std::numbers::pi, std::numbers::pi, kLibmUlps);
  const double c[4] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi), std::atan2(y.hi, x.lo),
                       std::atan2(y.hi, x.hi)};
  return interval_detail::widen(*std::min_element(c, c + 4), *std::max_element(c, c + 4),
                                kLibmUlps);
}
/// a^n for a whole n (negative n through the reciprocal).
inline Interval pow_int(const Interval& a, int n) {
  if (a.is_empty()) return a;
  if (n < 0) return Interval(1.0) / pow_int(a, -n);
  if (n == 0) return Interval(1.0);
  double lo = a.lo, hi = a.hi;
  if (n % 2 == 0) {
    const double m = std::max(std::abs(lo), std::abs(hi));
    const double l = a.contains(0) ? 0 : std::min(std::abs(lo), std::abs(hi));
    lo = l;
    hi = m;
  }
  // Each power is exact to one ulp per multiplication.
  const Interval r = interval_detail::widen(std::pow(lo, n), std::pow(hi, n), n + kLibmUlps);
  return n % 2 == 0 ? Interval{std::max(r.lo, 0.0), r.hi} : r;
}
/// a^b for real b: exp(b log a), defined for a > 0.
inline Interval pow(const Interval& a, const Interval& b) { return exp(b * log(a)); }

/// The sign of a as an interval: [-1, 1] when a contains 0.
inline Interval sign_of(const Interval& a) {
  if (a.lo > 0) return Interval(1.0);
  if (a.hi < 0) return Interval(-1.0);
  return {-1, 1};
}

}  // namespace raycast
