// The lane kernel of run_lanes over 2 lanes: baseline x86-64 (SSE2) or any other target, one SIMD
// register per vector. The kernel is math/formula_lanes.inl, included after every header
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

namespace raycast::lanes_w2 {
constexpr int W = 2;
#include "math/formula_lanes.inl"
}  // namespace raycast::lanes_w2
