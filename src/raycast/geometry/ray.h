#pragma once
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

/// A ray is usable when o is finite, d is finite and non-zero, and tmin <= tmax with neither NaN.
inline bool is_valid(const Ray& r) {
  return is_finite(r.o) && is_finite(r.d) && length_squared(r.d) > 0 && !(r.tmin > r.tmax) &&
         r.tmin == r.tmin && r.tmax == r.tmax;
}

}  // namespace raycast
