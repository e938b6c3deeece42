#pragma once
// A bounding volume hierarchy that knows no primitives: boxes and centres in, nodes and a
// permutation out; traversal calls back at the leaves (see bvh_traverse.h).
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/aabb.h"

namespace raycast {

struct BvhBuildConfig {
  int bins = 16;              // SAH bins per axis (Wald 2007)
  int max_leaf_size = 8;      // a leaf never holds more, whatever the SAH says
  int min_leaf_size = 1;      // below this a node is always a leaf
  double traversal_cost = 1;  // cost of visiting a node, relative to one primitive test
  double primitive_cost = 1;
  int leaf_block = 1;  // leaves are tested in blocks of this many primitives: the SAH
                       // charges ceil(count / leaf_block) blocks (4 for SIMD triangle groups)
  std::size_t parallel_binning_threshold = 65536;  // nodes this large bin in parallel
  std::size_t parallel_threshold = 4096;           // subtrees this large build as separate tasks
};

/// A node of the binary tree. Children are stored as a pair: `first` and `first + 1`.
/// A leaf (count > 0) holds prims[first .. first + count).
struct BvhNode {
  Aabb box;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  bool is_leaf() const { return count > 0; }
};

struct Bvh {
  std::vector<BvhNode> nodes;        // nodes[0] is the root (absent when there are no primitives)
  std::vector<std::uint32_t> prims;  // permutation of primitive indices, grouped by leaf

  bool empty() const { return nodes.empty(); }
  std::size_t memory_bytes() const {
    return nodes.capacity() * sizeof(BvhNode) + prims.capacity() * sizeof(std::uint32_t);
  }
};

/// Binned SAH build (Wald 2007) over primitives given by their boxes and centres (same length,
/// all finite). Large subtrees build in parallel with oneTBB; the result does not depend on the
/// thread count.
Bvh build_bvh(std::span<const Aabb> boxes, std::span<const Vec3> centres,
              const BvhBuildConfig& config = {});

}  // namespace raycast
