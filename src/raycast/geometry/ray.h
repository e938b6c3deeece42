#pragma once
#include <limits>

#include "math/float_error.h"
#include "math/vec3.h"

namespace raycast {

/// The ray o + t d with t in the closed interval [tmin, tmax]. d need not be unit length and is
/// never renormalised: t is always measured in units of d, in every space the ray visits.
struct Ray {
  Vec3 o;
  Vec3 d;
  double tmin = 0;
  double tmax = kInfinity;

  Vec3 at(double t) const { return o + t * d; }
};

/// is_valid's condition on o and d alone, from o2 = |o|^2 and d2 = |d|^2 (for callers that use
/// the squares themselves).
inline bool is_valid_extent(double o2, double d2) {
  return o2 <= std::numeric_limits<double>::max() && d2 >= std::numeric_limits<double>::min() &&
         d2 <= std::numeric_limits<double>::max();
}

/// A ray is usable when |o|^2 is finite (|o| below about 1.3e154), |d|^2 is a finite normal
/// double (|d| roughly within [1.5e-154, 1.3e154]) and tmin <= tmax with neither NaN. The shapes
/// square o and d: outside that range t under- or overflows (a subnormal d put hits at t = inf, a
/// huge d or o hits at t = 0 or with NaN normals). Scene queries answer "nothing" for other rays.
inline bool is_valid(const Ray& r) {
  return is_valid_extent(length_squared(r.o), length_squared(r.d)) && !(r.tmin > r.tmax) &&
         r.tmin == r.tmin && r.tmax == r.tmax;
}

}  // namespace raycast
