#pragma once
// The two compilations of the lane kernel (math/formula_lanes.inl): 2 lanes for any x86-64
// (math/formula_lanes_sse2.cpp) and 4 lanes for AVX2 (math/formula_lanes_avx2.cpp). Each evaluates
// the lanes [t[k], t[k + 1]], k < its width; run_lanes (math/formula_lanes.h) picks one.
#include "math/formula.h"
#include "math/formula_lanes.h"

namespace raycast {

namespace lanes_w2 {
void lanes_kernel(const Formula& f, const double o[3], const double d[3], const double* t,
                  bool last_known, double* const s_of[3], double* const c_of[3], double* out_lo,
                  double* out_hi, double* out_dlo, double* out_dhi);
void sin_cos_point(double x, double* s, double* c);
}  // namespace lanes_w2
namespace lanes_w4 {
void lanes_kernel(const Formula& f, const double o[3], const double d[3], const double* t,
                  bool last_known, double* const s_of[3], double* const c_of[3], double* out_lo,
                  double* out_hi, double* out_dlo, double* out_dhi);
void sin_cos_point(double x, double* s, double* c);
}  // namespace lanes_w4

}  // namespace raycast
