#include "objects/csg_shape.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "csg/first_crossing.h"
#include "csg/interval_crossing.h"
#include "objects/ball_list.h"
#include "objects/bounding_ball.h"
#include "objects/csg_tree.h"

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
  CullRay() = default;  // filled in before use
  CullRay(const CsgTree& tree, const Ray& ray) : o(ray.o), inv_d(reciprocal(ray.d)) {
    for (int a = 0; a < 3; ++a) {
      const double s =
          kCullSlack * (2 * tree.box_magnitude[a] + std::abs(o[a])) * std::abs(inv_d[a]);
      slack[a] = std::isfinite(s) ? s : 0;
      negative[a] = std::signbit(inv_d[a]);
    }
  }
};

// A cylinder's or cone's frustum (null for other shapes).
// A leaf's spans as the tree sees them: complemented for an inverse leaf, without surfaces for a
// hidden one (CsgTree::leaf_inverse, leaf_hidden).
void mark_leaf_spans(const CsgTree& tree, std::size_t leaf, SpanList& list) {
  if (tree.leaf_inverse[leaf]) complement_spans(list);
  if (tree.leaf_hidden[leaf])
    for (Span& s : list) s.in.part = s.out.part = kNoSurface;
}

const Frustum* leaf_frustum(const ShapeVariant& shape) {
  if (const auto* c = std::get_if<Cylinder>(&shape)) return &c->f;
  if (const auto* c = std::get_if<Cone>(&shape)) return &c->f;
  return nullptr;
}

// Whether the line through the ray may meet the tree's ball: |v|^2 |d|^2 - (v . d)^2 (|d|^2 times
// the distance squared of the centre from the line, v = centre - o) against radius^2 |d|^2, with
// |v|^2 shrunk by kBallSlack (far beyond the products' rounding, a few ulps of |v|^2 |d|^2).
// Outside [1e-280, 1e300] for |v|^2 |d|^2 the rounding is not relative: no test (kUntested).
// Inside it |v|^2 and |d|^2 are finite, so o and d are: the interval walk takes only such rays
// (scene queries pass no others: geometry/ray.h is_valid), the gather the rest.
enum class BallTest { kMiss, kMeets, kUntested };
BallTest line_meets_ball(const CsgTree& tree, const Ray& ray) {
  const Vec3 v = tree.ball_centre - ray.o;
  const double dd = dot(ray.d, ray.d), k = dot(v, ray.d);
  const double vvdd = dot(v, v) * dd;
  if (!(vvdd >= 1e-280 && vvdd <= 1e300)) return BallTest::kUntested;
  return vvdd * (1 - kBallSlack) - k * k > tree.ball_radius2 * dd ? BallTest::kMiss
                                                                  : BallTest::kMeets;
}

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
      mark_leaf_spans(tree, leaf, out);
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
    if (code < 0) {
      const auto leaf = static_cast<std::size_t>(-code - 1);
      return raycast::contains(tree.leaves[leaf], p) != (tree.leaf_inverse[leaf] != 0);
    }
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

// The leaves' span ends for first_crossing: each operand's spans where they may matter, with the
// evaluator's short cuts (boxes, an intersection with an empty operand is empty, operands after
// the first of an intersection or difference only matter where the first is) but no span lists
// combined. A leaf left out is empty where the walk needs it, so the walk stays exact there.
struct Gather {
  static constexpr std::size_t kMaxEnds = 64;

  const CsgTree& tree;
  const Ray& ray;
  std::optional<CullRay> cull;  // made on the first box test
  SpanList* lists = nullptr;    // one per leaf, fetched by the first generic leaf
  LeafEnd ends[kMaxEnds];       // left uninitialised: [0, count) is written before it is read
  std::size_t count = 0;
  bool overflow = false;  // more ends than kMaxEnds: the caller falls back to the evaluator

  Gather(const CsgTree& t, const Ray& r) : tree(t), ray(r) {}

  bool meets(const Aabb& box, double lo, double hi) {
    if (!cull) cull.emplace(tree, ray);
    return box_meets(box, *cull, lo, hi);
  }

  // Appends one interval of `leaf`; false when it misses [lo, hi] (NaN ends count as meeting),
  // else grows the hull [elo, ehi] of the intervals that meet it.
  bool add(std::uint16_t leaf, double t0, int part0, const LocalHit* h0, double t1, int part1,
           const LocalHit* h1, double lo, double hi, double& elo, double& ehi) {
    ends[count++] = {t0, h0, part0, leaf, false};
    ends[count++] = {t1, h1, part1, leaf, true};
    if (t1 < lo || t0 > hi) return false;
    elo = t0 < elo ? t0 : elo;
    ehi = t1 > ehi ? t1 : ehi;
    return true;
  }

  // The ends of leaf `leaf`; false when it is empty in [lo, hi], else [lo, hi] narrowed to the
  // hull of its intervals there.
  bool leaf_ends(std::size_t leaf, double& lo, double& hi) {
    const Object& object = tree.leaves[leaf];
    const auto index = static_cast<std::uint16_t>(leaf);
    double elo = kInfinity, ehi = -kInfinity;
    bool any = false;
    // The leaf's ray for the kinds below (a generic leaf's spans() moves it itself); most leaves
    // have no transform of their own: no copy then.
    const CsgTree::LeafKind kind = tree.leaf_kind[leaf];
    const bool typed = kind != CsgTree::LeafKind::kGeneric && kind != CsgTree::LeafKind::kPlane;
    std::optional<Ray> moved;  // not a Ray: its default members would be stored on every call
    const Ray& local = typed && object.xf ? moved.emplace(to_object_space(object, ray)) : ray;
    if (typed && count + 4 > kMaxEnds) {
      overflow = true;  // a leaf of these kinds adds at most 4 ends
      return true;
    }
    switch (kind) {
      case CsgTree::LeafKind::kSphere: {
        const Sphere& s = *std::get_if<Sphere>(&object.shape);
        const Vec3 o = local.o - s.center;
        // Outside and moving away: both roots are negative (exact signs, see intersect(Sphere)),
        // so a window from t >= 0 sees nothing.
        if (lo >= 0 && dot(o, o) > s.radius * s.radius && dot(o, local.d) > 0) return false;
        double t0, t1;
        if (!sphere_line_roots(o, local.d, s.radius, t0, t1)) return false;
        any = add(index, t0, 0, nullptr, t1, 1, nullptr, lo, hi, elo, ehi);
        break;
      }
      case CsgTree::LeafKind::kBox: {
        double t0, t1;
        int f0, f1;
        if (!box_line_interval(*std::get_if<Box>(&object.shape), local, t0, f0, t1, f1))
          return false;
        any = add(index, t0, f0, nullptr, t1, f1, nullptr, lo, hi, elo, ehi);
        break;
      }
      case CsgTree::LeafKind::kFrustum: {
        const Frustum& f = *leaf_frustum(object.shape);
        LineInterval iv[2];
        const int n = frustum_solid_intervals(f, local, iv);
        for (int i = 0; i < n; ++i)
          any |= add(index, iv[i].in.t, iv[i].in.part, nullptr, iv[i].out.t, iv[i].out.part,
                     nullptr, lo, hi, elo, ehi);
        break;
      }
      case CsgTree::LeafKind::kPlane:
      case CsgTree::LeafKind::kGeneric: {
        if (!lists) lists = scratch(tree.leaves.size());
        SpanList& list = lists[leaf];
        list.clear();
        spans(object, ray, list);
        mark_leaf_spans(tree, leaf, list);
        if (count + 2 * list.size() > kMaxEnds) {
          overflow = true;
          return true;
        }
        for (const Span& span : list)
          any |= add(index, span.in.t, span.in.part, &span.in, span.out.t, span.out.part, &span.out,
                     lo, hi, elo, ehi);
        break;
      }
    }
    if (!any) return false;
    if (elo <= ehi) {
      lo = elo > lo ? elo : lo;
      hi = ehi < hi ? ehi : hi;
    }
    return true;
  }

  // Gathers operand `code` for the window [lo, hi]; false when it is empty there, else [lo, hi]
  // is narrowed to a hull of where it may be non-empty.
  bool operand(std::int32_t code, double& lo, double& hi) {
    if (code < 0) {
      const std::size_t leaf = static_cast<std::size_t>(-code - 1);
      if (tree.leaf_cull[leaf] && !meets(tree.leaf_boxes[leaf], lo, hi)) return false;
      return leaf_ends(leaf, lo, hi);
    }
    const std::size_t k = static_cast<std::size_t>(code);
    const CsgNode& node = tree.nodes[k];
    if (tree.node_cull[k] && !meets(node.box, lo, hi)) return false;
    if (node.op == CsgOp::kUnion) {
      double ulo = kInfinity, uhi = -kInfinity;
      bool any = false;
      for (const std::int32_t c : node.operands) {
        double wlo = lo, whi = hi;
        if (!operand(c, wlo, whi)) continue;
        any = true;
        ulo = wlo < ulo ? wlo : ulo;
        uhi = whi > uhi ? whi : uhi;
      }
      if (any && ulo <= uhi) {
        lo = ulo;
        hi = uhi;
      }
      return any;
    }
    if (!operand(node.operands[0], lo, hi)) return false;
    for (std::size_t i = 1; i < node.operands.size() && !overflow; ++i) {
      double wlo = lo, whi = hi;
      const bool some = operand(node.operands[i], wlo, whi);
      if (node.op == CsgOp::kIntersection) {
        if (!some) return false;
        lo = wlo;
        hi = whi;
      }
    }
    return true;
  }
};

// One leaf's interval on its own space's ray `local`: 1 when it has one, 0 when it is empty,
// -1 when it has two (a cone, by rounding).
int leaf_interval(CsgTree::LeafKind kind, const Object& object, const Ray& local, LeafInterval& v) {
  switch (kind) {
    case CsgTree::LeafKind::kSphere: {
      const Sphere& s = *std::get_if<Sphere>(&object.shape);
      const Vec3 o = local.o - s.center;
      const double oo = dot(o, o);
      // Outside and moving away: both roots negative (see intersect(Sphere)), before a tmin
      // >= 0, as the gather skips it.
      if (local.tmin >= 0 && oo > s.radius * s.radius && dot(o, local.d) > 0) return 0;
      v.part0 = 0;
      v.part1 = 1;
      return sphere_line_roots(o, local.d, oo, s.radius, v.t0, v.t1);
    }
    case CsgTree::LeafKind::kBox:
      return box_line_interval(*std::get_if<Box>(&object.shape), local, v.t0, v.part0, v.t1,
                               v.part1);
    case CsgTree::LeafKind::kFrustum: {
      LineInterval two[2];
      const int k = frustum_solid_intervals(*leaf_frustum(object.shape), local, two);
      v = {two[0].in.t, two[0].out.t, two[0].in.part, two[0].out.part};
      return k == 2 ? -1 : k;
    }
    case CsgTree::LeafKind::kPlane: {
      // spans(Plane)'s interval: the half-space behind the normal.
      const Plane& p = *std::get_if<Plane>(&object.shape);
      const double dn = dot(p.n, local.d), on = dot(p.n, local.o);
      const double t = (p.offset - on) / dn;
      if (dn == 0 || !std::isfinite(t)) {
        v = {-kInfinity, kInfinity, kNoSurface, kNoSurface};
        return on <= p.offset;
      }
      v = dn > 0 ? LeafInterval{-kInfinity, t, kNoSurface, 0}
                 : LeafInterval{t, kInfinity, 0, kNoSurface};
      return 1;
    }
    case CsgTree::LeafKind::kGeneric:
      break;  // not taken: finish_csg_tree sets interval_leaves only without these
  }
  return -1;
}

// The leaves' intervals for interval_crossing (every leaf one of the kinds it takes), into
// iv[0, leaves) with `present` marking the non-empty ones. Returns 1 when filled, 0 when the tree
// is outside all along [tmin, tmax] (a leaf it needs misses the segment), -1 when a leaf gave two
// intervals: the gather answers then.
int leaf_intervals(const CsgTree& tree, const Ray& ray, LeafInterval* iv, std::uint64_t& present) {
  present = 0;
  const std::size_t n = tree.leaves.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Object& object = tree.leaves[i];
    LeafInterval& v = iv[i];
    const CsgTree::LeafKind kind = tree.leaf_kind[i];
    // No ray copy for leaves without a transform of their own (most); one call site, so that
    // leaf_interval is inlined.
    std::optional<Ray> moved;
    if (object.xf) moved.emplace(to_object_space(object, ray));
    const int some = leaf_interval(kind, object, moved ? *moved : ray, v);
    if (some < 0) return -1;
    const bool needed = (tree.required >> i) & 1;
    if (some == 0) {
      if (needed) return 0;
      continue;
    }
    if (needed && (v.t1 < ray.tmin || v.t0 > ray.tmax)) return 0;
    present |= std::uint64_t{1} << i;
  }
  return 1;
}

}  // namespace

namespace {

// Checks the leaves (primitive shapes only) and records their boxes and whether their hits start
// flipped: a closed mesh wound inside out reports its winding's (inward) normals, and in CSG
// every surface's normal points out of the solid.
void finish_leaves(CsgTree& tree) {
  tree.leaf_boxes.clear();
  tree.leaf_flipped.clear();
  tree.leaf_inverse.resize(tree.leaves.size(), 0);
  tree.leaf_hidden.resize(tree.leaves.size(), 0);
  for (std::size_t i = 0; i < tree.leaves.size(); ++i) {
    const Object& leaf = tree.leaves[i];
    if (std::holds_alternative<CsgShape>(leaf.shape) ||
        std::holds_alternative<InstanceShape>(leaf.shape))
      throw std::invalid_argument("a CSG leaf must be a primitive shape");
    const bool inverse = tree.leaf_inverse[i] != 0;
    tree.leaf_boxes.push_back(inverse ? Aabb::everything() : bounds(leaf));
    const auto* mesh = std::get_if<MeshShape>(&leaf.shape);
    tree.leaf_flipped.push_back((mesh && mesh->mesh->orientation() < 0) != inverse);
  }
}

// Each node's box from its operands', bottom-up (operands are leaves or later nodes), checking
// the references.
void finish_node_boxes(CsgTree& tree) {
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
}

// The tree's depth in levels, top-down (operands have larger indices than their node), to size
// the scratch lists.
std::size_t tree_depth(const CsgTree& tree) {
  std::vector<std::size_t> level(tree.nodes.size(), 0);
  std::size_t depth = 0;
  for (std::size_t k = 0; k < tree.nodes.size(); ++k) {
    depth = std::max(depth, level[k]);
    for (const std::int32_t code : tree.nodes[k].operands)
      if (code >= 0)
        level[static_cast<std::size_t>(code)] =
            std::max(level[static_cast<std::size_t>(code)], level[k] + 1);
  }
  return depth;
}

bool contains_box(const Aabb& outer, const Aabb& inner) {
  for (int a = 0; a < 3; ++a)
    if (!(outer.lo[a] <= inner.lo[a] && outer.hi[a] >= inner.hi[a])) return false;
  return true;
}

// Which boxes the walk tests. A leaf whose own interval test is as cheap as a box test is not
// culled; nor is an operand that gets its node's window and whose box contains its node's
// (the node's test passing implies its own), nor the root (the object's box is tested above).
void choose_culls(CsgTree& tree) {
  tree.leaf_kind.assign(tree.leaves.size(), CsgTree::LeafKind::kGeneric);
  for (std::size_t i = 0; i < tree.leaves.size(); ++i) {
    const ShapeVariant& shape = tree.leaves[i].shape;
    if (tree.leaf_inverse[i] || tree.leaf_hidden[i]) continue;  // spans changed: kGeneric
    if (const auto* s = std::get_if<Sphere>(&shape); s && !s->is_partial())
      tree.leaf_kind[i] = CsgTree::LeafKind::kSphere;
    else if (std::holds_alternative<Box>(shape))
      tree.leaf_kind[i] = CsgTree::LeafKind::kBox;
    else if (const Frustum* f = leaf_frustum(shape); f && f->is_closed())
      tree.leaf_kind[i] = CsgTree::LeafKind::kFrustum;
    else if (std::holds_alternative<Plane>(shape))
      tree.leaf_kind[i] = CsgTree::LeafKind::kPlane;
  }
  tree.leaf_cull.assign(tree.leaves.size(), 1);
  tree.node_cull.assign(tree.nodes.size(), 1);
  tree.node_cull[0] = 0;
  for (std::size_t i = 0; i < tree.leaves.size(); ++i)
    if (tree.leaf_kind[i] == CsgTree::LeafKind::kSphere ||
        tree.leaf_kind[i] == CsgTree::LeafKind::kBox)
      tree.leaf_cull[i] = 0;
  for (const CsgNode& node : tree.nodes) {
    for (std::size_t i = 0; i < node.operands.size(); ++i) {
      if (i > 0 && node.op != CsgOp::kUnion) continue;  // a narrower window than the node's
      const std::int32_t code = node.operands[i];
      const bool leaf = code < 0;
      const std::size_t index =
          leaf ? static_cast<std::size_t>(-code - 1) : static_cast<std::size_t>(code);
      if (contains_box(leaf ? tree.leaf_boxes[index] : tree.nodes[index].box, node.box))
        (leaf ? tree.leaf_cull : tree.node_cull)[index] = 0;
    }
  }
}

// The tree as a boolean formula of its leaves, and whether the one-interval walk
// (csg/interval_crossing.h) serves it, with the leaves it cannot do without.
void finish_formula(CsgTree& tree) {
  tree.formula = CsgFormula{};
  for (const CsgNode& node : tree.nodes) tree.formula.add(node.op, node.operands);
  tree.formula.finish(tree.leaves.size(), tree.leaf_flipped);
  tree.interval_leaves = tree.formula.is_tree() && tree.leaves.size() <= CsgTree::kIntervalLeaves;
  for (const CsgTree::LeafKind kind : tree.leaf_kind)
    tree.interval_leaves = tree.interval_leaves && kind != CsgTree::LeafKind::kGeneric;
  tree.required = 0;
  if (tree.interval_leaves) {
    // Leaf i is needed when the tree is empty without it even with every leaf it grows by.
    const std::uint64_t all = (std::uint64_t{1} << tree.leaves.size()) - 1;
    const std::uint64_t grow = all & ~tree.formula.subtracted();
    for (std::size_t i = 0; i < tree.leaves.size(); ++i)
      if (!tree.formula.inside(grow & ~(std::uint64_t{1} << i)))
        tree.required |= std::uint64_t{1} << i;
  }
}

}  // namespace

std::shared_ptr<const CsgTree> finish_csg_tree(CsgTree tree) {
  if (tree.nodes.empty()) throw std::invalid_argument("a CSG tree needs a root operation");
  finish_leaves(tree);
  finish_node_boxes(tree);
  tree.depth = tree_depth(tree);
  choose_culls(tree);
  finish_formula(tree);
  auto out = std::make_shared<CsgTree>(std::move(tree));
  Object whole;  // the tree as an object of its own space
  whole.shape = CsgShape{out};
  const Ball ball = bounding_ball(whole);
  if (ball.is_bounded() && !ball.is_empty() &&
      max_component(abs(ball.centre)) + ball.radius <= kBallLimit) {
    out->ball_centre = ball.centre;
    out->ball_radius2 = widened_radius2(ball.radius);
  }
  return out;
}

Aabb bounds(const CsgShape& s) { return s.tree->nodes[0].box; }

bool intersect_by_spans(const CsgShape& s, const Ray& ray, LocalHit& hit) {
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

namespace {

// intersect() after the ball test, by the gather.
bool gather_walk(const CsgShape& s, const Ray& ray, LocalHit& hit) {
  const CsgTree& tree = *s.tree;
  if (tree.formula.is_tree()) {
    Gather g(tree, ray);
    double lo = ray.tmin, hi = ray.tmax;
    if (!g.operand(0, lo, hi)) return false;
    if (!g.overflow)
      return first_crossing(tree.formula, std::span(g.ends, g.count), ray.tmin, ray.tmax, hit);
  }
  return intersect_by_spans(s, ray, hit);
}

}  // namespace

bool intersect_by_gather(const CsgShape& s, const Ray& ray, LocalHit& hit) {
  return line_meets_ball(*s.tree, ray) != BallTest::kMiss && gather_walk(s, ray, hit);
}

bool intersect(const CsgShape& s, const Ray& ray, LocalHit& hit) {
  const CsgTree& tree = *s.tree;
  // The tree's ball first: a ray that misses it misses every leaf, and rays that pass the
  // object's box (in world space, loose for turned objects) often miss it.
  const BallTest ball = line_meets_ball(tree, ray);
  if (ball == BallTest::kMiss) return false;
  if (tree.interval_leaves && ball == BallTest::kMeets) {
    LeafInterval iv[CsgTree::kIntervalLeaves];
    std::uint64_t present;
    const int filled = leaf_intervals(tree, ray, iv, present);
    if (filled == 0) return false;
    if (filled > 0)
      return interval_crossing(tree.formula, std::span(iv, tree.leaves.size()), present, ray.tmin,
                               ray.tmax, hit);
  }
  return gather_walk(s, ray, hit);
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
  return part_surface(s.tree->leaves[static_cast<std::size_t>(hit.leaf)], ray, hit,
                      SurfaceNeeds::kAll);
}

SurfaceInfo surface_geometry(const CsgShape& s, const Ray& ray, const LocalHit& hit) {
  return part_surface(s.tree->leaves[static_cast<std::size_t>(hit.leaf)], ray, hit,
                      SurfaceNeeds::kGeometry);
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
