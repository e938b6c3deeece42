#pragma once
// Floating-point error bounds (Higham; pbrt-v4 section 6.8): gamma(n) bounds the relative error
// of n chained IEEE double operations, used to offset secondary-ray origins instead of epsilons.
#include <limits>

namespace raycast {

inline constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon() * 0.5;
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

constexpr double gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

}  // namespace raycast
