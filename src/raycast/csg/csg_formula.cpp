#include "csg/csg_formula.h"

namespace raycast {

void CsgFormula::add(CsgOp op, std::span<const std::int32_t> operands) {
  nodes_.push_back({op, static_cast<std::uint32_t>(operands_.size()),
                    static_cast<std::uint32_t>(operands.size())});
  operands_.insert(operands_.end(), operands.begin(), operands.end());
}

bool CsgFormula::evaluate(std::int32_t code, std::uint64_t mask) const {
  if (code < 0) return (mask >> (-code - 1)) & 1;
  const Node& n = nodes_[static_cast<std::size_t>(code)];
  bool in = evaluate(operand(n, 0), mask);
  for (std::size_t i = 1; i < n.count; ++i) {
    if (n.op == CsgOp::kUnion ? in : !in) return in;  // decided whatever the rest is
    in = csg_inside(n.op, in, evaluate(operand(n, i), mask));
  }
  return in;
}

void CsgFormula::finish(std::size_t leaves, std::span<const char> leaf_flipped) {
  leaves_ = leaves;
  leaf_flipped_.assign(leaf_flipped.begin(), leaf_flipped.end());
  // A tree: every node but the root and every leaf is an operand exactly once.
  std::vector<int> uses(nodes_.size() + leaves_, 0);
  for (const std::int32_t code : operands_)
    ++uses[code >= 0 ? static_cast<std::size_t>(code) : nodes_.size() + (-code - 1)];
  is_tree_ = leaves_ <= kMaxLeaves && !nodes_.empty() && uses[0] == 0;
  for (std::size_t k = 1; k < uses.size(); ++k) is_tree_ = is_tree_ && uses[k] == 1;
  table_.clear();
  subtracted_ = 0;
  if (!is_tree_) return;
  // Flip parities, top-down: operands have larger indices than their node.
  std::vector<char> node_flip(nodes_.size(), 0);
  leaf_flip_ = leaf_flipped_;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Node& n = nodes_[k];
    for (std::size_t i = 0; i < n.count; ++i) {
      const char f = node_flip[k] ^ (n.op == CsgOp::kDifference && i > 0 ? 1 : 0);
      const std::int32_t code = operand(n, i);
      if (code >= 0)
        node_flip[static_cast<std::size_t>(code)] = f;
      else
        leaf_flip_[static_cast<std::size_t>(-code - 1)] ^= f;
    }
  }
  subtracted_ = 0;
  for (std::size_t i = 0; i < leaves_; ++i)
    if (leaf_flip_[i] != leaf_flipped_[i]) subtracted_ |= std::uint64_t{1} << i;
  if (leaves_ > kTableLeaves) return;
  const std::uint64_t masks = std::uint64_t{1} << leaves_;
  table_.assign((masks + 63) / 64, 0);
  for (std::uint64_t m = 0; m < masks; ++m)
    if (evaluate(0, m)) table_[m >> 6] |= std::uint64_t{1} << (m & 63);
}

}  // namespace raycast
