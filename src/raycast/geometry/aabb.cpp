#include "geometry/aabb.h"

namespace raycast {

Aabb transform_bounds(const Transform& xf, const Aabb& b) {
  if (b.is_empty()) return b;
  const auto& m = xf.matrix().m;
  Aabb r;
  // Arvo 1990: each output axis is the translation plus the sum over input axes of the smaller
  // and the larger of m[i][j] * lo[j] and m[i][j] * hi[j]; 0 * inf terms are 0 (axis unused).
  for (int i = 0; i < 3; ++i) {
    double lo = m[i][3], hi = m[i][3];
    for (int j = 0; j < 3; ++j) {
      if (m[i][j] == 0) continue;
      const double a = m[i][j] * b.lo[j], c = m[i][j] * b.hi[j];
      lo += std::min(a, c);
      hi += std::max(a, c);
    }
    r.lo[i] = lo;
    r.hi[i] = hi;
  }
  // Widen by the rounding error of the transform (gamma(3) of the largest term per row).
  for (int i = 0; i < 3; ++i) {
    double e = std::abs(m[i][3]);
    for (int j = 0; j < 3; ++j)
      if (m[i][j] != 0) e += std::abs(m[i][j]) * std::max(std::abs(b.lo[j]), std::abs(b.hi[j]));
    e *= gamma(3);
    r.lo[i] -= e;
    r.hi[i] += e;
  }
  return r;
}

}  // namespace raycast
