#include "math/quadratic.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

namespace raycast {

int solve_quadratic(double a, double b, double c, double& t0, double& t1) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return 0;
  if (a == 0) {
    if (b == 0) return 0;
    t0 = t1 = -c / b;
    return std::isfinite(t0) ? 1 : 0;
  }
  // Scale by a power of two (exact, roots unchanged) so the largest coefficient is in [0.5, 1):
  // then b^2 and 4ac cannot overflow, which would turn the discriminant into NaN.
  const double m = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (m >= 0x1p-1000 && m < 0x1p1000) {
    // The same scaling without the libm calls: frexp's exponent read from m's bits, and one
    // multiplication by the exact power of two 2^-e (correctly rounded, as ldexp is).
    const int e = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7ff) - 1022;
    const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - e) << 52);
    a *= scale;
    b *= scale;
    c *= scale;
  } else {
    int e;
    std::frexp(m, &e);
    a = std::ldexp(a, -e);
    b = std::ldexp(b, -e);
    c = std::ldexp(c, -e);
  }
  // The discriminant with an fma keeps b^2 - 4ac accurate when the two terms nearly cancel.
  const double four_ac = 4 * a * c;
  const double err = std::fma(-4 * a, c, four_ac);  // rounding error of 4ac
  const double disc = std::fma(b, b, -four_ac) + err;
  if (disc < 0) return 0;
  const double root = std::sqrt(disc);
  const double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
  if (q == 0) {  // b == 0 and c == 0: a double root at 0
    t0 = t1 = 0;
    return 2;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return 2;
}

}  // namespace raycast
