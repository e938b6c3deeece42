#pragma once
// The azimuth conventions of the partial shapes (phi_max): angles in [0, 2 pi).
#include <cmath>
#include <numbers>

namespace raycast {

inline constexpr double kTwoPi = 2 * std::numbers::pi;

/// The angle of the offset (x, y) from the axis, in [0, 2 pi).
inline double phi_of(double x, double y) {
  double phi = std::atan2(y, x);
  if (phi < 0) phi += kTwoPi;
  return phi;
}

}  // namespace raycast
