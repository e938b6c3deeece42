#pragma once
// The inside of a CsgShape: leaves flattened into one array, operations over operand codes.
#include <cstdint>
#include <memory>
#include <vector>

#include "csg/csg_formula.h"
#include "csg/span_ops.h"
#include "objects/object.h"

namespace raycast {

/// One operation. An operand code >= 0 is a node index, < 0 is the leaf -code - 1.
struct CsgNode {
  CsgOp op = CsgOp::kUnion;
  std::vector<std::int32_t> operands;  // at least one
  Aabb box;                            // set by finish_csg_tree
};

/// nodes[0] is the root; every operand of a node has a larger index (pre-order), and leaves'
/// transforms are relative to the CSG object. A leaf's material -1 means the CSG object's.
struct CsgTree {
  std::vector<Object> leaves;
  std::vector<Aabb> leaf_boxes;    // set by finish_csg_tree
  std::vector<char> leaf_flipped;  // set by finish_csg_tree: hits of the leaf start flipped
  // Per leaf, given by the builder (shorter or empty: the rest 0). Inverse: the leaf stands for
  // its complement over the whole line (POV-Ray's `inverse`), its normals flipped. Hidden: the
  // leaf's crossings are no surface (part kNoSurface): a `clipped_by` object, which cuts the
  // tree's solid but is never drawn, so the object is open where it is cut.
  std::vector<char> leaf_inverse, leaf_hidden;
  std::vector<CsgNode> nodes;
  std::size_t depth = 0;  // operation levels below the root; set by finish_csg_tree
  // Largest |coordinate| per axis over the finite sides of every node and leaf box, for the
  // culling test's rounding slack; set by finish_csg_tree.
  double box_magnitude[3] = {0, 0, 0};
  // The tree as a function of its leaves, for nearest-hit queries; set by finish_csg_tree.
  CsgFormula formula;
  // For the nearest-hit walk, set by finish_csg_tree: each leaf's kind (its intervals computed
  // without a span list when not kGeneric), and whether a leaf's or node's box is worth testing
  // (not when the test is as dear as the leaf's own, nor when it always passes).
  // A half-space (kPlane) gives its span list to the gather, as kGeneric, and its one interval
  // to the interval walk.
  enum class LeafKind : std::uint8_t { kGeneric, kSphere, kBox, kFrustum, kPlane };
  std::vector<LeafKind> leaf_kind;
  std::vector<char> leaf_cull, node_cull;
  // Whether the interval walk (csg/interval_crossing.h) answers nearest-hit queries: a tree of
  // at most kIntervalLeaves leaves, each a whole sphere, a box, a closed frustum or a half-space
  // (at most one interval on any line). `required`: the leaves without which the tree is empty
  // (bit per leaf). Set by finish_csg_tree.
  static constexpr std::size_t kIntervalLeaves = 16;
  bool interval_leaves = false;
  std::uint64_t required = 0;
  // A ball around the tree in its own space (objects/bounding_ball.h, widened), tested before the
  // walk: radius squared infinite when there is none to test. Set by finish_csg_tree.
  Vec3 ball_centre;
  double ball_radius2 = kInfinity;
};

inline std::int32_t csg_leaf_code(std::size_t leaf) { return -static_cast<std::int32_t>(leaf) - 1; }

/// Computes the boxes (union: merge; intersection: overlap; difference: the first operand's) and
/// freezes the tree. Throws std::invalid_argument when a node has no operand, a code is out of
/// range or not below its node, or a leaf is itself a CSG object or an instance (leaves are
/// primitives: nested operations are nodes of the same tree).
std::shared_ptr<const CsgTree> finish_csg_tree(CsgTree tree);

/// The material of the leaf that made `hit` (-1: the CSG object's own).
int csg_material(const CsgShape& s, const LocalHit& hit);

}  // namespace raycast
