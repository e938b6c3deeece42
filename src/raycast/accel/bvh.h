#pragma once
// A bounding volume hierarchy that knows no primitives: boxes in, nodes and a permutation out;
// traversal calls back at the leaves (see bvh_traverse.h). Binned SAH (Wald 2007), parallel over
// subtrees with oneTBB; docs/performance.md gives its speed beside Embree's.
#include <cstdint>
#include <span>
#include <vector>

#include "accel/build_memory.h"
#include "geometry/aabb.h"

namespace raycast {

struct BvhBuildConfig {
  int bins = 16;              // SAH bins per axis (Wald 2007), 2 to 32
  int max_leaf_size = 8;      // a leaf never holds more, whatever the SAH says
  int min_leaf_size = 1;      // below this a node is always a leaf
  double traversal_cost = 1;  // cost of visiting a node, relative to one primitive test
  double primitive_cost = 1;
  int leaf_block = 1;  // leaves are tested in blocks of this many primitives: the SAH
                       // charges ceil(count / leaf_block) blocks (4 for SIMD triangle groups)
  std::size_t parallel_binning_threshold = 65536;  // nodes this large bin and partition in parallel
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
  BuildVector<BvhNode> nodes;        // nodes[0] is the root (absent when there are no primitives)
  BuildVector<std::uint32_t> prims;  // permutation of primitive indices, grouped by leaf

  bool empty() const { return nodes.empty(); }
  std::size_t memory_bytes() const {
    return nodes.capacity() * sizeof(BvhNode) + prims.capacity() * sizeof(std::uint32_t);
  }
};

/// A primitive as the builder sees it (32 bytes): its box in float, rounded outwards, and its
/// index. Coordinates beyond +-kBuildRefLimit are clamped to it; node boxes that reach the limit
/// come out infinite on that side, so that every node box holds its primitives' double boxes.
struct alignas(16) BvhBuildRef {
  float lo[3];
  std::uint32_t index;
  float hi[3];
  std::uint32_t unused;
};
static_assert(sizeof(BvhBuildRef) == 32);

/// The builder's input: resize(n) leaves the references uninitialised for a parallel fill.
using BvhBuildRefs = BuildVector<BvhBuildRef>;

inline constexpr float kBuildRefLimit = 0x1p125f;

/// The reference of a finite box (rounded outwards to float, clamped to +-kBuildRefLimit).
BvhBuildRef make_build_ref(const Aabb& box, std::uint32_t index);

/// A node of the builder's own tree (32 bytes): the box in float, exact unions of the references'
/// float boxes (a side at +-kBuildRefLimit is unbounded), and the same first/count as BvhNode.
struct BvhFloatNode {
  float lo[3];
  std::uint32_t first;
  float hi[3];
  std::uint32_t count;
  bool is_leaf() const { return count > 0; }
};

/// The tree as the builder makes it, before conversion to double boxes: for callers that consume
/// the tree once (the mesh BVH's collapse), which saves a pass over 56-byte nodes.
struct FloatBvh {
  BuildVector<BvhFloatNode> nodes;   // nodes[0] is the root (absent when there are no primitives)
  BuildVector<std::uint32_t> prims;  // permutation of primitive indices, grouped by leaf
  bool empty() const { return nodes.empty(); }
};

/// The build of build_bvh_from_refs, returning the float tree.
FloatBvh build_float_bvh_from_refs(BvhBuildRefs refs, const BvhBuildConfig& config = {});

/// Binned SAH build (Wald 2007) over primitive references (boxes not empty; the indices need not
/// be distinct, they are copied to Bvh::prims). Consumes `refs` (the build partitions them in
/// place). Parallel with oneTBB at every level (binning and partitioning of large nodes, subtrees
/// as tasks); the tree and the permutation do not depend on the number of threads, only node
/// numbering may.
Bvh build_bvh_from_refs(BvhBuildRefs refs, const BvhBuildConfig& config = {});

/// The same over double boxes (finite, not empty): primitive i has box boxes[i]. The builder
/// bins the centres of the float boxes it derives from them.
Bvh build_bvh(std::span<const Aabb> boxes, const BvhBuildConfig& config = {});

/// The SAH cost of a tree (MacDonald and Booth 1990), with the config's costs and leaf blocks:
/// the sum over inner nodes of traversal_cost * area and over leaves of primitive_cost *
/// blocks * area, areas relative to the root's. 0 for an empty tree. For comparing builds.
double sah_cost(const Bvh& bvh, const BvhBuildConfig& config = {});

}  // namespace raycast
