#pragma once
// An independent reference for the roots of f(o + t d) along a ray: dense sampling of the sign of
// f in long double, each sign change bisected in long double. Misses pairs of roots closer than
// the sampling step, which callers account for.
#include <cmath>
#include <functional>
#include <vector>

namespace raycast::testing_reference {

using LongFn = std::function<long double(long double t)>;

inline std::vector<long double> sign_change_roots(const LongFn& f, long double lo, long double hi,
                                                  int samples) {
  std::vector<long double> roots;
  long double a = lo, fa = f(lo);
  for (int i = 1; i <= samples; ++i) {
    const long double b = lo + (hi - lo) * i / samples;
    const long double fb = f(b);
    if ((fa < 0) != (fb < 0)) {
      long double x0 = a, x1 = b, f0 = fa;
      for (int k = 0; k < 200 && x1 - x0 > 0; ++k) {
        const long double m = 0.5L * (x0 + x1);
        if (m <= x0 || m >= x1) break;
        const long double fm = f(m);
        if ((fm < 0) == (f0 < 0)) {
          x0 = m;
          f0 = fm;
        } else {
          x1 = m;
        }
      }
      roots.push_back(0.5L * (x0 + x1));
    }
    a = b;
    fa = fb;
  }
  return roots;
}

}  // namespace raycast::testing_reference
