#include "math/formula_lanes.h"
#include "math/formula_lanes_kernels.h"
#include "math/isa.h"

namespace raycast {

namespace {

// The 4-lane kernel needs AVX2: taken when the engine's ISA (math/isa.h, which honours
// RAYCAST_ISA) is AVX2 or wider; both kernels give the same bits, only the speed differs.
bool use_avx2() {
  static const bool wide = active_isa() >= Isa::kAvx2;
  return wide;
}

}  // namespace

void run_lanes(const Formula& f, const double o[3], const double d[3],
               const double t[kFormulaLanes + 1], FormulaLanes& out, LaneTrig* trig) {
  static_assert(kFormulaLanes == 4, "the kernels are 4 lanes, or 2 passes of 2");
  double* s[3] = {trig->s[0], trig->s[1], trig->s[2]};
  double* c[3] = {trig->c[0], trig->c[1], trig->c[2]};
  const bool known = trig->ends_known;
  if (use_avx2()) {
    lanes_w4::lanes_kernel(f, o, d, t, known, s, c, out.lo, out.hi, out.dlo, out.dhi);
    return;
  }
  lanes_w2::lanes_kernel(f, o, d, t, false, s, c, out.lo, out.hi, out.dlo, out.dhi);
  double* s2[3] = {s[0] + 2, s[1] + 2, s[2] + 2};
  double* c2[3] = {c[0] + 2, c[1] + 2, c[2] + 2};
  lanes_w2::lanes_kernel(f, o, d, t + 2, known, s2, c2, out.lo + 2, out.hi + 2, out.dlo + 2,
                         out.dhi + 2);
}

bool run_lanes_avx2() { return use_avx2(); }

void lane_sin_cos(double x, double* s, double* c) { lanes_w2::sin_cos_point(x, s, c); }

}  // namespace raycast
