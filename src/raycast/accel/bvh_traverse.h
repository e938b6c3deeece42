#pragma once
// Ordered traversal of a Bvh with callbacks at the leaves: one template for the nearest, any and
// all-hit queries (the shape of madmann91/bvh's intersect<IsAnyHit>), over a stack that grows
// instead of dropping children.
#include <cstdint>
#include <vector>

#include "accel/bvh.h"
#include "geometry/aabb.h"

namespace raycast {

/// A traversal stack of (node, entry distance): 128 entries on the C stack, which the depth bound
/// of the build (SAH splits to depth 64, object-median splits below) makes enough for one
/// traversal of any tree; should a tree ever be deeper it moves to the heap rather than drop a
/// child.
class BvhStack {
 public:
  struct Entry {
    std::uint32_t node;
    double t_enter;
  };
  bool empty() const { return top_ == 0; }
  void push(std::uint32_t node, double t_enter) {
    if (top_ == capacity_) grow();
    data_[top_++] = {node, t_enter};
  }
  Entry pop() { return data_[--top_]; }

 private:
  static constexpr int kLocal = 128;
  void grow() {
    std::vector<Entry> bigger(data_, data_ + top_);
    bigger.resize(static_cast<std::size_t>(capacity_) * 2);
    heap_ = std::move(bigger);
    data_ = heap_.data();
    capacity_ *= 2;
  }
  Entry local_[kLocal];
  std::vector<Entry> heap_;
  Entry* data_ = local_;
  int top_ = 0;
  int capacity_ = kLocal;
};

enum class BvhQuery { kNearest, kAny };

/// The one traversal. kNearest: children nearest first, `leaf(prim, tmax)` may lower tmax, and
/// stacked nodes whose entry lies beyond the lowered tmax are skipped. kAny: `leaf(prim, tmax)`
/// returns true to stop (tmax is not changed). Returns whether a leaf stopped the traversal.
template <BvhQuery Q, class Leaf>
bool traverse_bvh(const Bvh& bvh, const Vec3& o, const Vec3& d, double tmin, double& tmax,
                  Leaf&& leaf) {
  if (bvh.empty()) return false;
  const Vec3 inv_d = reciprocal(d);
  BvhStack stack;
  double t_enter;
  if (!intersect_slabs(bvh.nodes[0].box, o, inv_d, tmin, tmax, t_enter)) return false;
  std::uint32_t index = 0;
  for (;;) {
    const BvhNode& node = bvh.nodes[index];
    if (node.is_leaf()) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if constexpr (Q == BvhQuery::kAny) {
          if (leaf(bvh.prims[i], tmax)) return true;
        } else {
          leaf(bvh.prims[i], tmax);
        }
      }
    } else {
      double t0, t1;
      const bool h0 = intersect_slabs(bvh.nodes[node.first].box, o, inv_d, tmin, tmax, t0);
      const bool h1 = intersect_slabs(bvh.nodes[node.first + 1].box, o, inv_d, tmin, tmax, t1);
      if (h0 && h1) {
        std::uint32_t near = node.first, far = node.first + 1;
        if (Q == BvhQuery::kNearest && t1 < t0) {
          std::swap(near, far);
          std::swap(t0, t1);
        }
        stack.push(far, t1);  // t1: the farther child's entry once swapped
        index = near;
        continue;
      }
      if (h0 || h1) {
        index = h0 ? node.first : node.first + 1;
        continue;
      }
    }
    // Pop, skipping nodes that a lowered tmax has ruled out.
    for (;;) {
      if (stack.empty()) return false;
      const BvhStack::Entry e = stack.pop();
      if (Q == BvhQuery::kAny || e.t_enter <= tmax) {
        index = e.node;
        break;
      }
    }
  }
}

/// Nearest-first traversal. `leaf(prim, tmax)` tests one primitive against the ray restricted to
/// [tmin, tmax] and lowers tmax when it finds a nearer hit. Returns when every node that could hold
/// a hit below the final tmax has been visited.
template <class Leaf>
void traverse_nearest(const Bvh& bvh, const Vec3& o, const Vec3& d, double tmin, double& tmax,
                      Leaf&& leaf) {
  traverse_bvh<BvhQuery::kNearest>(bvh, o, d, tmin, tmax, leaf);
}

/// Any-hit traversal: `leaf(prim)` returns true to stop (something blocks the segment).
/// Returns whether some leaf stopped it.
template <class Leaf>
bool traverse_any(const Bvh& bvh, const Vec3& o, const Vec3& d, double tmin, double tmax,
                  Leaf&& leaf) {
  return traverse_bvh<BvhQuery::kAny>(bvh, o, d, tmin, tmax,
                                      [&](std::uint32_t prim, double) { return leaf(prim); });
}

/// Visits every leaf primitive whose node boxes the line o + t d meets within [tmin, tmax].
template <class Leaf>
void traverse_all(const Bvh& bvh, const Vec3& o, const Vec3& d, double tmin, double tmax,
                  Leaf&& leaf) {
  traverse_any(bvh, o, d, tmin, tmax, [&](std::uint32_t prim) {
    leaf(prim);
    return false;
  });
}

}  // namespace raycast
