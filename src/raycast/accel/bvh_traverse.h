#pragma once
// Ordered traversal of a Bvh with callbacks at the leaves.
#include <cstdint>

#include "accel/bvh.h"
#include "geometry/aabb.h"

namespace raycast {

/// Nearest-first traversal. `leaf(prim, tmax)` tests one primitive against the ray restricted to
/// [tmin, tmax] and lowers tmax when it finds a nearer hit. Returns when every node that could hold
/// a hit below the final tmax has been visited.
template <class Leaf>
void traverse_nearest(const Bvh& bvh, const Vec3& o, const Vec3& d, double tmin, double& tmax,
                      Leaf&& leaf) {
  if (bvh.empty()) return;
  const Vec3 inv_d = reciprocal(d);
  constexpr int kStackSize = 128;
  std::uint32_t stack[kStackSize];
  int top = 0;
  double t_enter;
  if (!intersect_slabs(bvh.nodes[0].box, o, inv_d, tmin, tmax, t_enter)) return;
  std::uint32_t index = 0;
  for (;;) {
    const BvhNode& node = bvh.nodes[index];
    if (node.is_leaf()) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) leaf(bvh.prims[i], tmax);
    } else {
      double t0, t1;
      const bool h0 = intersect_slabs(bvh.nodes[node.first].box, o, inv_d, tmin, tmax, t0);
      const bool h1 = intersect_slabs(bvh.nodes[node.first + 1].box, o, inv_d, tmin, tmax, t1);
      if (h0 && h1) {
        std::uint32_t near = node.first, far = node.first + 1;
        if (t1 < t0) std::swap(near, far);
        if (top < kStackSize) stack[top++] = far;
        index = near;
        continue;
      }
      if (h0 || h1) {
        index = h0 ? node.first : node.first + 1;
        continue;
      }
    }
    // Pop, skipping nodes that the shrunken tmax has ruled out.
    for (;;) {
      if (top == 0) return;
      index = stack[--top];
      if (intersect_slabs(bvh.nodes[index].box, o, inv_d, tmin, tmax, t_enter)) break;
    }
  }
}

/// Any-hit traversal: `leaf(prim)` returns true to stop (something blocks the segment).
/// Returns whether some leaf stopped it.
template <class Leaf>
bool traverse_any(const Bvh& bvh, const Vec3& o, const Vec3& d, double tmin, double tmax,
                  Leaf&& leaf) {
  if (bvh.empty()) return false;
  const Vec3 inv_d = reciprocal(d);
  constexpr int kStackSize = 128;
  std::uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = bvh.nodes[stack[--top]];
    double t;
    if (!intersect_slabs(node.box, o, inv_d, tmin, tmax, t)) continue;
    if (node.is_leaf()) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        if (leaf(bvh.prims[i])) return true;
    } else if (top + 2 <= kStackSize) {
      stack[top++] = node.first + 1;
      stack[top++] = node.first;
    }
  }
  return false;
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
