#pragma once
// A CSG tree seen as a boolean function of its leaves' insides: which combinations of "inside
// leaf k" make a point inside the tree. The first-crossing walk (csg/first_crossing.h) evaluates
// it at every end of the leaves' spans instead of merging span lists node by node.
#include <cstdint>
#include <span>
#include <vector>

#include "csg/span_ops.h"

namespace raycast {

class CsgFormula {
 public:
  /// Trees of more leaves are not represented (the walk's leaf masks are 64 bits wide).
  static constexpr std::size_t kMaxLeaves = 64;
  /// Up to this many leaves the function is a table of 2^leaves bits (512 bytes at most).
  static constexpr std::size_t kTableLeaves = 12;

  struct Node {
    CsgOp op = CsgOp::kUnion;
    std::uint32_t first = 0;  // operands_[first, first + count)
    std::uint32_t count = 0;
  };

  /// Appends an operation. Node 0 is the root; operand codes are CsgNode's (>= 0 a node with a
  /// larger index than this one, < 0 the leaf -code - 1); the caller has validated them.
  void add(CsgOp op, std::span<const std::int32_t> operands);
  /// Fixes the leaf count (at most kMaxLeaves) and each leaf's starting flip (1: its hits start
  /// flipped, as LocalHit::flip), then builds the table and the leaves' flip parities.
  void finish(std::size_t leaves, std::span<const char> leaf_flipped);

  /// Whether the nodes form a tree over every leaf (each node but the root and each leaf used
  /// exactly once) of at most kMaxLeaves leaves; the rest of the class needs it.
  bool is_tree() const { return is_tree_; }
  std::size_t leaves() const { return leaves_; }
  const Node& node(std::size_t k) const { return nodes_[k]; }
  std::int32_t operand(const Node& n, std::size_t i) const { return operands_[n.first + i]; }

  /// Whether a point inside exactly the leaves whose bits are set in `mask` is inside the tree.
  bool inside(std::uint64_t mask) const {
    if (!table_.empty()) return (table_[mask >> 6] >> (mask & 63)) & 1;
    return evaluate(0, mask);
  }
  /// The flip a hit of `leaf` has once it is a crossing of the whole tree: its starting flip,
  /// toggled by every difference that subtracts it (as combine_spans toggles it level by level).
  bool leaf_flip(std::size_t leaf) const { return leaf_flip_[leaf] != 0; }
  bool leaf_flipped(std::size_t leaf) const { return leaf_flipped_[leaf] != 0; }
  /// The leaves subtracted an odd number of times (bit per leaf): the tree's membership grows
  /// with each other leaf's and shrinks with each of these.
  std::uint64_t subtracted() const { return subtracted_; }

 private:
  bool evaluate(std::int32_t code, std::uint64_t mask) const;

  std::vector<Node> nodes_;
  std::vector<std::int32_t> operands_;
  std::vector<std::uint64_t> table_;
  std::vector<char> leaf_flip_, leaf_flipped_;
  std::uint64_t subtracted_ = 0;
  std::size_t leaves_ = 0;
  bool is_tree_ = false;
};

}  // namespace raycast
