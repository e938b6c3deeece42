#pragma once
// The nearest boundary of a CSG tree on a ray without building its span list: the leaves' span
// ends are sorted by t and walked in order, keeping which leaves the line is inside, and the walk
// stops at the first end in [tmin, tmax] where the tree's membership (csg/csg_formula.h) changes.
// The answer is the crossing that combining the leaves' lists node by node with combine_spans
// (csg/span_ops.h) reports there: the same end, leaf and flip.
#include <cstdint>
#include <span>

#include "csg/csg_formula.h"
#include "geometry/hit.h"

namespace raycast {

/// One end of one span of one leaf (no default values: arrays of them are scratch space).
struct LeafEnd {
  double t;
  const LocalHit* hit;  // the leaf's own record of the crossing; null: LocalHit{.t, .part}
  std::int32_t part;    // the record's part (kNoSurface at an unbounded end)
  std::uint16_t leaf;
  bool exit;  // the span's out end (else its in end)
};

/// `ends` holds every end of every leaf that may be inside the tree in [tmin, tmax] (a leaf left
/// out counts as empty), each leaf's ends consecutive and in its list's order (in0, out0, in1,
/// ...); it is sorted here, stably by t. Returns the first t in [tmin, tmax] where the tree's
/// membership changes and whose crossing is a surface (part != kNoSurface): `hit` is the
/// responsible leaf's record with `leaf` and `flip` set, as combine_spans would combine it
/// (ties between leaves at one t are resolved by its rule, node by node). The result is exact
/// in [tmin, tmax] when every leaf left out is empty there. NaN ends are never reported.
bool first_crossing(const CsgFormula& f, std::span<LeafEnd> ends, double tmin, double tmax,
                    LocalHit& hit);

}  // namespace raycast
