#include "csg/interval_crossing.h"

#include <bit>

#include "csg/first_crossing.h"

namespace raycast {

namespace {

// first_crossing over the present leaves' ends, for the cases its rules decide.
bool by_first_crossing(const CsgFormula& f, std::span<const LeafInterval> iv, std::uint64_t present,
                       double tmin, double tmax, LocalHit& hit) {
  LeafEnd ends[2 * CsgFormula::kMaxLeaves];
  std::size_t n = 0;
  for (std::uint64_t m = present; m != 0; m &= m - 1) {
    const auto i = static_cast<std::uint16_t>(std::countr_zero(m));
    ends[n++] = {iv[i].t0, nullptr, iv[i].part0, i, false};
    ends[n++] = {iv[i].t1, nullptr, iv[i].part1, i, true};
  }
  return first_crossing(f, std::span(ends, n), tmin, tmax, hit);
}

// The least end value above `lower` (at or above it when not kStrict) and at most tmax, with the
// end that has it; `tie` when another end has the same value. leaf < 0: none.
struct Next {
  double t;
  int leaf = -1;
  bool tie = false;
};

template <bool kStrict>
Next next_end(std::span<const LeafInterval> iv, std::uint64_t live, double lower, double tmax) {
  Next n{tmax};
  for (std::uint64_t m = live; m != 0; m &= m - 1) {
    const int i = std::countr_zero(m);
    const LeafInterval& v = iv[static_cast<std::size_t>(i)];
    for (const double e : {v.t0, v.t1}) {
      if (kStrict ? !(e > lower) : !(e >= lower)) continue;
      if (e < n.t || (e == n.t && n.leaf < 0)) {
        n.t = e;
        n.leaf = i;
        n.tie = false;
      } else if (e == n.t) {
        n.tie = true;
      }
    }
  }
  return n;
}

}  // namespace

bool interval_crossing(const CsgFormula& f, std::span<const LeafInterval> iv, std::uint64_t present,
                       double tmin, double tmax, LocalHit& hit) {
  if (!(tmin <= tmax)) return by_first_crossing(f, iv, present, tmin, tmax, hit);
  // The leaves that meet [tmin, tmax] (no other has an end there or is inside at one), and
  // those inside before the first end at or after tmin.
  std::uint64_t live = 0, before = 0;
  for (std::uint64_t m = present; m != 0; m &= m - 1) {
    const int i = std::countr_zero(m);
    const LeafInterval& v = iv[static_cast<std::size_t>(i)];
    if (!(v.t0 <= v.t1)) return by_first_crossing(f, iv, present, tmin, tmax, hit);  // NaN
    if (v.t1 < tmin || v.t0 > tmax) continue;
    live |= std::uint64_t{1} << i;
    if (v.t0 < tmin) before |= std::uint64_t{1} << i;
  }
  // The tree is monotone in each leaf (decreasing in subtracted ones): if it is outside with
  // every live leaf it grows by and none it shrinks by, it is outside all along the segment.
  if (!f.inside(live & ~f.subtracted())) return false;
  std::uint64_t mask = before;
  bool inside = f.inside(mask);
  for (Next n = next_end<false>(iv, live, tmin, tmax); n.leaf >= 0;
       n = next_end<true>(iv, live, n.t, tmax)) {
    const double t = n.t;
    // The state after every end at t: one end toggles its leaf; at a tie, which leaves have an
    // end there and where each one is after them.
    std::uint64_t after = mask ^ (std::uint64_t{1} << n.leaf), at = std::uint64_t{1} << n.leaf;
    if (n.tie) {
      after = at = 0;
      for (std::uint64_t m = live; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        const LeafInterval& v = iv[static_cast<std::size_t>(i)];
        if (v.t0 == t || v.t1 == t) at |= std::uint64_t{1} << i;
        if (v.t0 <= t && t < v.t1) after |= std::uint64_t{1} << i;
      }
    }
    mask = after;
    const bool now = f.inside(after);
    if (now == inside) continue;
    // Several leaves changing at once: combine_spans's tie rule, node by node.
    if ((at & (at - 1)) != 0) return by_first_crossing(f, iv, present, tmin, tmax, hit);
    inside = now;
    // The leaf alone changed the tree: its in end if it is now inside, else its out end.
    const int i = std::countr_zero(at);
    const LeafInterval& v = iv[static_cast<std::size_t>(i)];
    const bool leaf_in = (after >> i) & 1;
    const std::int32_t part = leaf_in ? v.part0 : v.part1;
    if (part == kNoSurface) continue;
    hit = LocalHit{.t = leaf_in ? v.t0 : v.t1, .part = part};
    hit.leaf = i;
    hit.flip = f.leaf_flip(static_cast<std::size_t>(i));
    return true;
  }
  return false;
}

}  // namespace raycast
