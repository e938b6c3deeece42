#pragma once
// The first crossing of a CSG tree whose leaves each meet the line in at most one interval
// (whole spheres, boxes, capped cylinders and cones, half-spaces): first_crossing's answer
// (csg/first_crossing.h) over those intervals' ends, found without building, sorting and walking
// the end records. Leaf i is inside exactly on [t0, t1], so the walk's state before the ends at
// t is {i : t0 < t <= t1} and after them {i : t0 <= t < t1}; the walk steps from one end value
// to the next by a scan of the leaves. Where first_crossing's own rules are needed (several
// leaves with an end at one crossing t, NaN ends) it answers by first_crossing itself.
#include <cstdint>
#include <span>

#include "csg/csg_formula.h"
#include "geometry/hit.h"

namespace raycast {

/// One leaf's interval of the whole line, with the parts of its ends (kNoSurface at +-inf).
struct LeafInterval {
  double t0, t1;
  std::int32_t part0, part1;
};

/// `iv[i]` is leaf i's interval where bit i of `present` is set (t0 <= t1); other leaves are
/// empty. Returns what first_crossing returns for the ends of the present leaves (each leaf's
/// in and out end, in leaf order): the first surface crossing of the tree in [tmin, tmax], its
/// record LocalHit{.t, .part} with `leaf` and `flip` set. Needs f.is_tree().
bool interval_crossing(const CsgFormula& f, std::span<const LeafInterval> iv, std::uint64_t present,
                       double tmin, double tmax, LocalHit& hit);

}  // namespace raycast
