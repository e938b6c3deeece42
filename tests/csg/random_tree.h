#pragma once
// A random CSG tree's shape for the walks' tests (first_crossing, interval_crossing): operations
// and operand codes only, the leaves numbered in the order they are made.
#include <cstdint>
#include <random>
#include <vector>

#include "csg/span_ops.h"
#include "objects/csg_tree.h"

namespace raycast::csg_test {

// A random tree in pre-order: nodes[0] the root, operand codes as CsgNode's.
struct RandomTree {
  std::vector<CsgOp> ops;
  std::vector<std::vector<std::int32_t>> operands;
  std::size_t leaves = 0;
};

// Grows `t` by a subtree of at most `depth` levels (1-3 operands per node); returns its code.
inline std::int32_t grow(std::mt19937& rng, RandomTree& t, int depth) {
  std::uniform_int_distribution<int> coin(0, 2), op(0, 2), arity(1, 3);
  if (depth == 0 || (depth < 3 && coin(rng) == 0)) return csg_leaf_code(t.leaves++);
  const auto k = static_cast<std::int32_t>(t.ops.size());
  t.ops.push_back(static_cast<CsgOp>(op(rng)));
  t.operands.emplace_back();
  const int n = arity(rng);
  for (int i = 0; i < n; ++i) {
    const std::int32_t code = grow(rng, t, depth - 1);
    t.operands[static_cast<std::size_t>(k)].push_back(code);
  }
  return k;
}

}  // namespace raycast::csg_test
