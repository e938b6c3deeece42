#include "csg/first_crossing.h"

namespace raycast {

namespace {

// Stable insertion sort by t: the lists are short (a few ends per leaf) and each leaf's ends are
// already in order. NaN ends stay where they are and do not stop the sort.
void sort_by_t(std::span<LeafEnd> ends) {
  for (std::size_t i = 1; i < ends.size(); ++i) {
    if (!(ends[i].t < ends[i - 1].t)) continue;
    const LeafEnd e = ends[i];
    std::size_t j = i;
    do {
      ends[j] = ends[j - 1];
      --j;
    } while (j > 0 && e.t < ends[j - 1].t);
    ends[j] = e;
  }
}

// What one operand (a leaf or a node's result) does at one t, as combine_spans's Step: its state
// in the gaps before and after t, and when it changes, the end responsible and its flip.
struct Change {
  bool before = false;
  bool after = false;
  const LeafEnd* crossing = nullptr;
  bool flip = false;
  bool changed() const { return before != after; }
};

// combine_spans's rule for the crossing at a t where several leaves have ends, applied node by
// node as the nested merges apply it. `group` is every end at that t.
Change resolve(const CsgFormula& f, std::int32_t code, std::uint64_t before, std::uint64_t after,
               std::span<const LeafEnd> group) {
  if (code < 0) {
    const std::uint32_t leaf = static_cast<std::uint32_t>(-code - 1);  // < kMaxLeaves
    Change c{((before >> leaf) & 1) != 0, ((after >> leaf) & 1) != 0, nullptr,
             f.leaf_flipped(leaf)};
    if (c.changed())  // the last entry (now inside) or the last exit (now outside) at t
      for (const LeafEnd& e : group)
        if (e.leaf == leaf && e.exit != c.after) c.crossing = &e;
    return c;
  }
  const CsgFormula::Node& n = f.node(static_cast<std::size_t>(code));
  Change a = resolve(f, f.operand(n, 0), before, after, group);
  for (std::size_t i = 1; i < n.count; ++i) {
    const Change b = resolve(f, f.operand(n, i), before, after, group);
    Change r{csg_inside(n.op, a.before, b.before), csg_inside(n.op, a.after, b.after)};
    if (r.changed()) {
      // The responsible operand: one whose change alone turns the result; else any that changed.
      bool from_a;
      if (a.changed() && csg_inside(n.op, a.after, b.before) == r.after)
        from_a = true;
      else if (b.changed() && csg_inside(n.op, a.before, b.after) == r.after)
        from_a = false;
      else
        from_a = a.changed();
      r.crossing = from_a ? a.crossing : b.crossing;
      r.flip = from_a ? a.flip : b.flip != (n.op == CsgOp::kDifference);
    }
    a = r;
  }
  return a;
}

// Reports end `e` as the crossing (flipped by `flip`) when it is a surface.
bool report(const LeafEnd& e, bool flip, LocalHit& hit) {
  if (e.part == kNoSurface) return false;
  hit = e.hit ? *e.hit : LocalHit{.t = e.t, .part = e.part};
  hit.leaf = static_cast<std::int32_t>(e.leaf);
  hit.flip = flip;
  return true;
}

// The walk below for one interval of one leaf, in then out, t0 < t1 (no sort, no tie, no NaN):
// the same steps unrolled.
bool one_interval(const CsgFormula& f, const LeafEnd& in, const LeafEnd& out, double tmin,
                  double tmax, LocalHit& hit) {
  if (in.t > tmax) return false;
  const bool inside = f.inside(std::uint64_t{1} << in.leaf);
  const bool flip = f.leaf_flip(in.leaf);
  if (inside && in.t >= tmin && report(in, flip, hit)) return true;
  if (out.t > tmax || f.inside(0) == inside || out.t < tmin) return false;
  return report(out, flip, hit);
}

}  // namespace

bool first_crossing(const CsgFormula& f, std::span<LeafEnd> ends, double tmin, double tmax,
                    LocalHit& hit) {
  if (ends.size() == 2 && ends[0].t < ends[1].t && ends[0].leaf == ends[1].leaf && !ends[0].exit &&
      ends[1].exit)
    return one_interval(f, ends[0], ends[1], tmin, tmax, hit);
  sort_by_t(ends);
  std::uint64_t mask = 0;
  bool inside = false;
  const std::size_t n = ends.size();
  for (std::size_t i = 0; i < n;) {
    const double t = ends[i].t;
    if (t > tmax) return false;
    // Every end at exactly t (at least the first, so that a NaN cannot stall the walk).
    const std::uint64_t before = mask;
    bool one_leaf = true;
    std::size_t j = i;
    do {
      const std::uint64_t bit = std::uint64_t{1} << ends[j].leaf;
      mask = ends[j].exit ? mask & ~bit : mask | bit;
      one_leaf = one_leaf && ends[j].leaf == ends[i].leaf;
      ++j;
    } while (j < n && ends[j].t == t);
    const bool now = f.inside(mask);
    if (now != inside) {
      inside = now;
      if (t >= tmin) {
        const LeafEnd* crossing = nullptr;
        bool flip = false;
        if (one_leaf) {
          // The leaf alone changed the tree: its last end of the kind that leaves it in its new
          // state, flipped by each difference that subtracts it.
          const bool leaf_in = (mask >> ends[i].leaf) & 1;
          for (std::size_t k = i; k < j; ++k)
            if (ends[k].exit != leaf_in) crossing = &ends[k];
          flip = f.leaf_flip(ends[i].leaf);
        } else {
          const Change c = resolve(f, 0, before, mask, ends.subspan(i, j - i));
          crossing = c.crossing;
          flip = c.flip;
        }
        if (crossing && report(*crossing, flip, hit)) return true;
      }
    }
    i = j;
  }
  return false;
}

}  // namespace raycast
