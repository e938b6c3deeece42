#pragma once
// Rays that stress a slab test: aimed at a box's corner, sometimes sliding along a face.
#include "geometry/aabb.h"
#include "geometry/ray.h"
#include "support/random.h"

namespace raycast::testing {

/// A ray from a random point (within 30 of the corner) at corner c of `box` (bit 0: hi x, bit 1:
/// hi y, bit 2: hi z). For n % 5 == 0 it slides along a face instead (one direction component
/// +0 or -0, the origin on that face's plane); for n % 7 == 0 it ends on the corner (tmax 1).
inline Ray corner_ray(const Aabb& box, int c, int n, Rng& rng) {
  const Vec3 corner{c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y,
                    c & 4 ? box.hi.z : box.lo.z};
  Ray ray;
  ray.o = corner + rng.in_box(30);
  ray.d = corner - ray.o;
  if (n % 5 == 0) {
    const int axis = n / 5 % 3;
    ray.o[axis] = corner[axis];
    ray.d[axis] = n % 2 ? 0.0 : -0.0;
  }
  if (n % 7 == 0) ray.tmax = 1;
  return ray;
}

}  // namespace raycast::testing
