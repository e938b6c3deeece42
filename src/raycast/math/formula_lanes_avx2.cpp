// The lane kernel of run_lanes over 4 lanes, compiled for AVX2 (one 256-bit register per vector);
// used only where the CPU has it. The kernel is math/formula_lanes.inl, included after every header
// (docs/architecture.md "ISA dispatch").
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include "math/formula.h"
#include "math/formula_lanes_kernels.h"

// The lane helpers pass vectors by value inside this file only: no ABI is involved.
#pragma GCC diagnostic ignored "-Wpsabi"
#if defined(__x86_64__)
#pragma GCC target("avx2")
#endif

namespace raycast::lanes_w4 {
constexpr int W = 4;
// (GCC's target pragma does not define __AVX__: the kernel is told so here.)
#define RAYCAST_LANES_AVX 1
#include "math/formula_lanes.inl"
#undef RAYCAST_LANES_AVX
}  // namespace raycast::lanes_w4
