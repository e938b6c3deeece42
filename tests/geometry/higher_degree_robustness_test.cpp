// Bad rays (NaN, infinite, huge) never crash, hang or report a hit with a non-finite t.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/algebraic.h"
#include "geometry/implicit.h"
#include "geometry/revolution.h"
#include "geometry/torus.h"

namespace raycast {
namespace {

template <class S>
void check_bad_rays(const S& s) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Ray rays[] = {
      {{nan, 0, 0}, {1, 0, 0}},
      {{-5, 0, 0}, {nan, 0, 0}},
      {{-kInfinity, 0, 0}, {1, 0, 0}},
      {{-5, 0, 0}, {kInfinity, 0, 0}},
      {{-1e300, 0.1, 0.1}, {1, 0, 0}},
      {{-5, 0.1, 0.1}, {1e-300, 0, 0}},
      {{-5, 0.1, 0.1}, {1, 0, 0}, nan, kInfinity},
  };
  for (const Ray& r : rays) {
    LocalHit h;
    if (intersect(s, r, h)) {
      EXPECT_TRUE(std::isfinite(h.t));
    }
    occluded(s, r);
    SpanList l;
    spans(s, r, l);
  }
}

TEST(HigherDegreeShapes, BadRays_NoCrashNoHangNoNonFiniteHit) {
  const Aabb box{{-2, -2, -2}, {2, 2, 2}};
  check_bad_rays(make_torus(1, 0.3));
  check_bad_rays(make_algebraic("(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3", box));
  check_bad_rays(make_implicit("(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)", box));
  check_bad_rays(make_revolution({{0, 0}, {1, 0}, {1, 1}, {0, 2}}, ProfileCurve::kLinear));
  check_bad_rays(make_revolution({{0, 0}, {0, 0}, {1, 0}, {1, 1}, {0.5, 2}, {0.5, 2}},
                                 ProfileCurve::kBSpline));
}

}  // namespace
}  // namespace raycast
