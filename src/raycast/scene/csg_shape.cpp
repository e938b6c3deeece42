#include "scene/csg_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/csg_tree.h"

namespace raycast {

namespace {

// Relative slack of the culling box test: the box and the leaf's own crossings are computed in
// different spaces, so a few dozen roundings of the coordinates' magnitude separate them.
constexpr double kCullSlack = gamma(16);

// The ray as the culling test uses it: the slab planes chosen by the sign of d, and per axis the
// rounding slack of the test, kCullSlack (2 M + |o|) |1 / d| with M the tree's largest
// |coordinate| on that axis (a bound on every box's |lo| + |hi| + |o| term), made once per ray
// instead of per box; not finite (d = 0 on that axis): no slack, as before.
struct CullRay {
  Vec3 o, inv_d;
  double slack[3];
  bool negative[3];
  CullRay(const CsgTree& tree, const Ray& ray) : o(ray.o), inv_d(reciprocal(ray.d)) {
    for (int a = 0; a < 3; ++a) {
      const double s =
          kCullSlack * (2 * tree.box_magnitude[a] + std::abs(o[a])) * std::abs(inv_d[a]);
      slack[a] = std::isfinite(s) ? s : 0;
      negative[a] = std::signbit(inv_d[a]);
    }
  }
};

// Whether the line o + t d may meet box b for some t in [lo, hi] (either may be infinite).
// Conservative: each slab interval is widened by the rounding of its terms; a NaN from 0 * inf
// leaves that axis unconstrained.
bool box_meets(const Aabb& b, const CullRay& r, double lo, double hi) {
  if (b.is_empty()) return false;
  double t0 = lo, t1 = hi;
  for (int a = 0; a < 3; ++a) {
    const double near = ((r.negative[a] ? b.hi[a] : b.lo[a]) - r.o[a]) * r.inv_d[a] - r.slack[a];
    const double far = ((r.negative[a] ? b.lo[a] : b.hi[a]) - r.o[a]) * r.inv_d[a] + r.slack[a];
    t0 = near > t0 ? near : t0;
    t1 = far < t1 ? far : t1;
    if (t0 > t1) return false;
  }
  return true;
}

// Scratch span lists, two per tree level and one for the result, kept per thread so that building
// a SpanList (whose inline storage is sizeable) is not paid on every node of every ray. Grows on a
// thread's first evaluation of a deeper tree, never afterwards. Evaluations do not nest (leaves
// are primitives), so one pool per thread suffices.
SpanList* scratch(std::size_t lists) {
  thread_local std::vector<SpanList> pool;
  if (pool.size() < lists) pool.resize(lists);
  return pool.data();
}

struct Evaluator {
  const CsgTree& tree;
  const Ray& ray;
  CullRay cull;
  SpanList* pool = nullptr;  // level L uses pool[2 L] and pool[2 L + 1]

  // The spans of operand `code` at tree level `level`, correct within [lo, hi] (and possibly
  // wrong outside it).
  void operand(std::int32_t code, double lo, double hi, SpanList& out,
               std::size_t level = 0) const {
    out.clear();
    if (code < 0) {
      const std::size_t leaf = static_cast<std::size_t>(-code - 1);
      if (!box_meets(tree.leaf_boxes[leaf], cull, lo, hi)) return;
      spans(tree.leaves[leaf], ray, out);
      const bool flip = tree.leaf_flipped[leaf] != 0;
      for (Span& s : out) {
        s.in.leaf = s.out.leaf = static_cast<std::int32_t>(leaf);
        s.in.flip = s.out.flip = flip;
      }
      return;
    }
    const CsgNode& node = tree.nodes[static_cast<std::size_t>(code)];
    if (!box_meets(node.box, cull, lo, hi)) return;
    operand(node.operands[0], lo, hi, out, level + 1);
    SpanList& child = pool[2 * level];
    SpanList& merged = pool[2 * level + 1];
    for (std::size_t i = 1; i < node.operands.size(); ++i) {
      double wlo = lo, whi = hi;
      if (node.op != CsgOp::kUnion) {
        // Early stop: nothing can come back once the accumulated solid is empty, and the rest
        // only matters where it is not.
        if (out.empty()) return;
        wlo = std::max(lo, out[0].in.t);
        whi = std::min(hi, out.back().out.t);
      }
      operand(node.operands[i], wlo, whi, child, level + 1);
      if (child.empty()) {
        if (node.op != CsgOp::kIntersection) continue;  // a union or difference keeps `out`
        out.clear();
        return;
      }
      combine_spans(node.op, out, child, merged);
      out = merged;
    }
  }

  bool contains(std::int32_t code, const Vec3& p) const {
    if (code < 0) return raycast::contains(tree.leaves[static_cast<std::size_t>(-code - 1)], p);
    const CsgNode& node = tree.nodes[static_cast<std::size_t>(code)];
    bool inside = contains(node.operands[0], p);
    for (std::size_t i = 1; i < node.operands.size(); ++i) {
      if (node.op == CsgOp::kUnion && inside) return true;
      if (node.op != CsgOp::kUnion && !inside) return false;
      inside = csg_inside(node.op, inside, contains(node.operands[i], p));
    }
    return inside;
  }
};

}  // namespace

std::shared_ptr<const CsgTree> finish_csg_tree(CsgTree tree) {
  if (tree.nodes.empty()) throw std::invalid_argument("a CSG tree needs a root operation");
  tree.leaf_boxes.clear();
  tree.leaf_flipped.clear();
  for (const Object& leaf : tree.leaves) {
    if (std::holds_alternative<CsgShape>(leaf.shape) ||
        std::holds_alternative<InstanceShape>(leaf.shape))
      throw std::invalid_argument("a CSG leaf must be a primitive shape");
    tree.leaf_boxes.push_back(bounds(leaf));
    // A closed mesh wound inside out reports its winding's (inward) normals; in CSG every
    // surface's normal points out of the solid, so its hits start flipped.
    const auto* mesh = std::get_if<MeshShape>(&leaf.shape);
    tree.leaf_flipped.push_back(mesh && mesh->mesh->orientation() < 0);
  }
  for (std::size_t k = tree.nodes.size(); k-- > 0;) {
    CsgNode& node = tree.nodes[k];
    if (node.operands.empty()) throw std::invalid_argument("a CSG operation needs an operand");
    Aabb box;
    for (std::size_t i = 0; i < node.operands.size(); ++i) {
      const std::int32_t code = node.operands[i];
      Aabb b;
      if (code < 0) {
        const std::size_t leaf = static_cast<std::size_t>(-static_cast<std::int64_t>(code) - 1);
        if (leaf >= tree.leaves.size()) throw std::invalid_argument("CSG leaf out of range");
        b = tree.leaf_boxes[leaf];
      } else {
        if (static_cast<std::size_t>(code) <= k ||
            static_cast<std::size_t>(code) >= tree.nodes.size())
          throw std::invalid_argument("CSG operand must be a later node");
        b = tree.nodes[static_cast<std::size_t>(code)].box;
      }
      if (i == 0)
        box = b;
      else if (node.op == CsgOp::kUnion)
        box = merge(box, b);
      else if (node.op == CsgOp::kIntersection)
        box = overlap(box, b);
    }
    node.box = box;
  }
  for (int a = 0; a < 3; ++a) {
    double m = 0;
    auto grow = [&](const Aabb& b) {
      for (double c : {b.lo[a], b.hi[a]})
        if (std::isfinite(c)) m = std::max(m, std::abs(c));
    };
    for (const Aabb& b : tree.leaf_boxes) grow(b);
    for (const CsgNode& node : tree.nodes) grow(node.box);
    tree.box_magnitude[a] = m;
  }
  // Levels, top-down (operands have larger indices than their node), to size the scratch lists.
  std::vector<std::size_t> level(tree.nodes.size(), 0);
  tree.depth = 0;
  for (std::size_t k = 0; k < tree.nodes.size(); ++k) {
    tree.depth = std::max(tree.depth, level[k]);
    for (const std::int32_t code : tree.nodes[k].operands)
      if (code >= 0)
        level[static_cast<std::size_t>(code)] =
            std::max(level[static_cast<std::size_t>(code)], level[k] + 1);
  }
  return std::make_shared<const CsgTree>(std::move(tree));
}

Aabb bounds(const CsgShape& s) { return s.tree->nodes[0].box; }

bool intersect(const CsgShape& s, const Ray& ray, LocalHit& hit) {
  SpanList* pool = scratch(2 * s.tree->depth + 3);
  SpanList& list = pool[2 * s.tree->depth + 2];
  Evaluator{*s.tree, ray, CullRay(*s.tree, ray), pool}.operand(0, ray.tmin, ray.tmax, list);
  for (const Span& span : list) {
    for (const LocalHit* end : {&span.in, &span.out}) {
      if (end->part != kNoSurface && end->t >= ray.tmin && end->t <= ray.tmax) {
        hit = *end;
        return true;
      }
    }
    if (span.out.t > ray.tmax) break;
  }
  return false;
}

bool occluded(const CsgShape& s, const Ray& ray) {
  LocalHit hit;
  return intersect(s, ray, hit);
}

void spans(const CsgShape& s, const Ray& ray, SpanList& out) {
  SpanList* pool = scratch(2 * s.tree->depth + 3);
  SpanList& list = pool[2 * s.tree->depth + 2];
  Evaluator{*s.tree, ray, CullRay(*s.tree, ray), pool}.operand(0, -kInfinity, kInfinity, list);
  for (const Span& span : list) out.push_back(span);
}

SurfaceInfo surface(const CsgShape& s, const Ray& ray, const LocalHit& hit) {
  LocalHit h = hit;
  h.flip = false;
  return surface(s.tree->leaves[static_cast<std::size_t>(hit.leaf)], ray, h);
}

bool contains(const CsgShape& s, const Vec3& p) {
  const Ray unused{};
  return Evaluator{*s.tree, unused, CullRay(*s.tree, unused)}.contains(0, p);
}

int csg_material(const CsgShape& s, const LocalHit& hit) {
  if (hit.leaf < 0 || static_cast<std::size_t>(hit.leaf) >= s.tree->leaves.size()) return -1;
  return material_of(s.tree->leaves[static_cast<std::size_t>(hit.leaf)], hit);
}

}  // namespace raycast
