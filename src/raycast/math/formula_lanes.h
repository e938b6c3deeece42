#pragma once
// A formula's value and derivative along a ray over several consecutive t-intervals in one pass of
// its bytecode: the interval search of implicit surfaces splits a piece in kFormulaLanes at once.
#include "math/formula.h"

namespace raycast {

/// How many t-intervals one call evaluates: one pass of 4 lanes where the CPU has AVX2 (the
/// kernel of math/formula_lanes_avx2.cpp), else two passes of 2 (math/formula_lanes_sse2.cpp);
/// RAYCAST_ISA=scalar or sse4 forces the latter. Both give the same bits.
inline constexpr int kFormulaLanes = 4;

/// Inclusions of f and of df/dt over kFormulaLanes t-intervals, structure of arrays (lane k in
/// element k), so that the compiler runs the lanes of + - * side by side in SIMD registers.
struct FormulaLanes {
  double lo[kFormulaLanes], hi[kFormulaLanes];    // f
  double dlo[kFormulaLanes], dhi[kFormulaLanes];  // df/dt
};

/// sin and cos of each variable at the kFormulaLanes + 1 points o + t[j] d (computed there
/// exactly so, by lane_sin_cos), for formulas with sin or cos of a bare variable: a caller that
/// splits pieces passes the values at a piece's ends on to its parts (ends_known), so that a pass
/// computes only the interior points' (and the first point's again, with the same bits, where that
/// is cheaper than skipping it).
struct LaneTrig {
  double s[3][kFormulaLanes + 1], c[3][kFormulaLanes + 1];
  bool ends_known = false;
};

/// How far the lanes' own sin and cos of a point (lane_sin_cos) may lie from the exact values, in
/// absolute terms. Derivation: the reduced argument r = x - n pi/2 (|n| < 2^19) is off by at most
/// two roundings of |r| <= 0.786 (2^-53 each: 1.8e-16), the rounding of n times the third part
/// of pi/2 (below 1e-31) and n times the 1e-37 by which the three parts miss pi/2; the Taylor
/// remainders are below 5.1e-17 (sin, r^17 / 17!) and 2.2e-18 (cos); coefficient rounding and
/// Horner's roundings add below 1.5e-16. So below 4e-16; the bound allows 5 times that. Lanes with
/// |x| > 2^19 use libm instead.
inline constexpr double kLaneSinCosError = 2e-15;

/// sin x and cos x as the lanes compute them (within kLaneSinCosError; for the tests).
void lane_sin_cos(double x, double* s, double* c);

/// f(o + t d) and its t-derivative over the intervals [t[k], t[k + 1]], k < kFormulaLanes
/// (t increasing). Each lane is the inclusion run<Dual<Interval, 1>> gives for that interval
/// (bit for bit for + - * and the other operations), except sin and cos of a bare variable: their
/// ends come from one sincos per distinct t (kFormulaLanes + 1 instead of 2 kFormulaLanes), each
/// lane's enclosure then widened by the distance between its interval's ends and those points
/// (|sin'|, |cos'| <= 1), so it still holds every value.
void run_lanes(const Formula& f, const double o[3], const double d[3],
               const double t[kFormulaLanes + 1], FormulaLanes& out, LaneTrig* trig);

/// Whether run_lanes uses the AVX2 kernel (for `raycast info` and the tests).
bool run_lanes_avx2();

}  // namespace raycast
