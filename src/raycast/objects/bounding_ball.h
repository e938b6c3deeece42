#pragma once
// A ball around an object, often much tighter than the ball around its box: a rotated object's
// world box grows with the rotation, a CSG intersection's box is the overlap of its operands'
// boxes (a lens of two spheres: a flat slab), and a sphere's box corners lie outside it. Culling
// tests that use it (ObjectSet::any_along) stay conservative: every point of the object is in
// the ball, with a margin far beyond the rounding of its computation.
#include "math/vec3.h"
#include "objects/object.h"

namespace raycast {

struct Ball {
  Vec3 centre;
  double radius = kInfinity;  // infinite: unbounded; negative: empty

  bool is_empty() const { return radius < 0; }
  bool is_bounded() const { return radius < kInfinity; }
};

/// A ball that contains the object (in the space its transform maps to), the smaller of the
/// ball around its box and one built from its shape: spheres, boxes, closed or open cylinders and
/// cones, tori, ellipsoids by their own geometry, CSG trees by their operations (union: the ball
/// around the operands' balls; intersection: the ball around the lens of two balls; difference:
/// the first operand's), instances by their prototype's objects. Widened by a relative 1e-9 of
/// its scale. Empty for an empty object; unbounded (radius infinite) for an unbounded one.
Ball bounding_ball(const Object& o);

/// The smallest ball around both balls (unbounded if either is).
Ball merge_balls(const Ball& a, const Ball& b);
/// A ball around the intersection of the two balls (empty when they do not meet).
Ball overlap_balls(const Ball& a, const Ball& b);

}  // namespace raycast
