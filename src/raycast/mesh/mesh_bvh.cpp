#include "mesh/mesh_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "mesh/split_refs.h"
#include "mesh/wide_kernels.h"

namespace raycast {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// ---- Build ------------------------------------------------------------------------------------

constexpr float kMaxFloat = std::numeric_limits<float>::max();

// Quantises the n child intervals [lo[i], hi[i]] of one axis (finite floats) to 8 bits relative
// to their union: origin = the least lo, the smallest power-of-two scale whose 255 steps span
// the union, then each lo rounded down and each hi rounded up in steps, checked against the
// float dequantisation the traversal does (so that rounding of the sum can never shrink a box).
// A scale too fine for some hi after that check is doubled and the axis redone.
void quantise_axis(const float* lo, const float* hi, int n, float& origin, std::int8_t& exponent,
                   std::uint8_t* qlo, std::uint8_t* qhi) {
  float o = lo[0];
  float top = hi[0];
  for (int i = 1; i < n; ++i) {
    o = std::min(o, lo[i]);
    top = std::max(top, hi[i]);
  }
  const double extent = double(top) - double(o);
  int e = -126;
  if (extent > 0) {
    int k = 0;
    std::frexp(extent / 255, &k);  // 2^(k-1) <= extent / 255 < 2^k
    e = std::clamp(k, -126, 127);
  }
  for (;; ++e) {
    const float s = node_scale(e);
    bool fits = true;
    for (int i = 0; i < n && fits; ++i) {
      double fl = std::floor((double(lo[i]) - o) / s);
      int ql = static_cast<int>(std::clamp(fl, 0.0, 255.0));
      while (ql > 0 && !(dequantise(o, s, static_cast<std::uint8_t>(ql)) <= lo[i])) --ql;
      double ch = std::ceil((double(hi[i]) - o) / s);
      int qh = static_cast<int>(std::clamp(ch, 0.0, 256.0));
      while (qh <= 255 && !(dequantise(o, s, static_cast<std::uint8_t>(qh)) >= hi[i])) ++qh;
      if (qh > 255) {
        fits = false;
        break;
      }
      qlo[i] = static_cast<std::uint8_t>(ql);
      qhi[i] = static_cast<std::uint8_t>(qh);
    }
    // At 2^127 every q >= 2 dequantises to infinity, so the loop ends there at the latest.
    if (fits || e >= 127) break;
  }
  for (int i = n; i < kNodeWidth; ++i) qlo[i] = qhi[i] = 0;
  origin = o;
  exponent = static_cast<std::int8_t>(e);
}

double half_area(const BvhFloatNode& n) {
  const double x = double(n.hi[0]) - n.lo[0], y = double(n.hi[1]) - n.lo[1],
               z = double(n.hi[2]) - n.lo[2];
  return x * y + y * z + z * x;
}

class Collapser {
 public:
  Collapser(const FloatBvh& bin, std::span<const Vec3f> positions,
            std::span<const std::array<std::uint32_t, 3>> triangles,
            std::span<const std::uint32_t> source, MeshBvh& out)
      : bin_(bin), positions_(positions), triangles_(triangles), source_(source), out_(out) {}

  void run() {
    // Triangles under each binary node, bottom up (a node's children have larger indices).
    tris_.resize(bin_.nodes.size());
    for (std::size_t i = bin_.nodes.size(); i-- > 0;) {
      const BvhFloatNode& n = bin_.nodes[i];
      tris_[i] = n.is_leaf() ? n.count : tris_[n.first] + tris_[n.first + 1];
    }
    // The leaves' groups in depth-first order of the binary tree, first child first (serial):
    // the order of the splits, so that neighbouring leaves sit next to each other in memory, the
    // same for any thread count (the binary builder numbers its nodes as its tasks run).
    leaf_group_.assign(bin_.nodes.size(), 0);
    std::vector<std::uint32_t> todo{0};
    while (!todo.empty()) {
      const std::uint32_t i = todo.back();
      todo.pop_back();
      const BvhFloatNode& n = bin_.nodes[i];
      if (n.is_leaf()) {
        place_leaf(i);
      } else {
        todo.push_back(n.first + 1);
        todo.push_back(n.first);
      }
    }
    if (bin_.nodes[0].is_leaf()) {
      out_.root = leaf_ref(0);
      out_.depth = 0;
    } else {
      if (out_.quantised)
        out_.qnodes.reserve(bin_.nodes.size() / 2 + 1);
      else
        out_.nodes.reserve(bin_.nodes.size() / 2 + 1);
      out_.root = collapse(0, 1);
    }
    out_.groups.resize(next_group_);
    tbb::parallel_for(std::size_t(0), leaf_order_.size(), [&](std::size_t i) {
      fill_leaf(bin_.nodes[leaf_order_[i]], leaf_group_[leaf_order_[i]]);
    });
  }

 private:
  // Gives binary leaf `node` the next groups in memory.
  void place_leaf(std::uint32_t node) {
    leaf_group_[node] = next_group_;
    next_group_ += (bin_.nodes[node].count + 3) / 4;
    leaf_order_.push_back(node);
  }

  std::uint32_t leaf_ref(std::uint32_t node) const {
    const BvhFloatNode& n = bin_.nodes[node];
    const std::uint32_t count = (n.count + 3) / 4;
    return kLeafBit | ((count - 1) << 29) | leaf_group_[node];
  }

  void fill_leaf(const BvhFloatNode& n, std::uint32_t first_group) {
    for (std::uint32_t k = 0; k < (n.count + 3) / 4; ++k) {
      TriangleGroup& g = out_.groups[first_group + k];
      for (int lane = 0; lane < 4; ++lane) {
        const std::uint32_t i = k * 4 + lane;
        if (i >= n.count) {
          for (auto& vertex : g.v)
            for (auto& axis : vertex) axis[lane] = kNaN;
          g.id[lane] = kNoTriangle;
          g.source[lane] = kNoTriangle;
          continue;
        }
        const std::uint32_t tri = bin_.prims[n.first + i];
        for (int vtx = 0; vtx < 3; ++vtx) {
          const Vec3f& p = positions_[triangles_[tri][vtx]];
          g.v[vtx][0][lane] = p.x;
          g.v[vtx][1][lane] = p.y;
          g.v[vtx][2][lane] = p.z;
        }
        g.id[lane] = tri;
        g.source[lane] = source_.empty() ? tri : source_[tri];
      }
    }
  }

  // Makes the wide node for binary inner node `node`: its children are the binary descendants
  // found by repeatedly opening the inner child of largest surface area (up to kNodeWidth): under
  // the SAH the child of largest area is the one most likely to be visited, so replacing it by
  // its two children saves the most expected node visits.
  // The children are then ordered by the triangles under them, most first (Embree's order "for
  // faster shadow ray traversal"): the any-hit walk enters the first hit child and pushes the
  // others, so it descends the larger subtrees while the pushed leaves' prefetches land, and a
  // blocked ray meets its blocker sooner. The nearest-hit walks order by distance (ties in t go
  // to the smaller triangle index), so their hits do not depend on it.
  // The nodes are numbered depth first (this node, then its inner children's subtrees in the
  // order they were opened).
  std::uint32_t collapse(std::uint32_t node, int depth) {
    out_.depth = std::max(out_.depth, depth);
    std::uint32_t kids[kNodeWidth] = {bin_.nodes[node].first, bin_.nodes[node].first + 1};
    int n = 2;
    while (n < kNodeWidth) {
      int best = -1;
      double best_area = -1;
      for (int i = 0; i < n; ++i) {
        const BvhFloatNode& c = bin_.nodes[kids[i]];
        if (!c.is_leaf() && half_area(c) > best_area) {
          best_area = half_area(c);
          best = i;
        }
      }
      if (best < 0) break;
      const std::uint32_t opened = kids[best];
      kids[best] = bin_.nodes[opened].first;
      kids[n++] = bin_.nodes[opened].first + 1;
    }
    const std::uint32_t index =
        static_cast<std::uint32_t>(out_.quantised ? out_.qnodes.size() : out_.nodes.size());
    if (out_.quantised)
      out_.qnodes.emplace_back();
    else
      out_.nodes.emplace_back();
    std::uint32_t refs[kNodeWidth] = {};
    for (int i = 0; i < n; ++i)
      refs[i] = bin_.nodes[kids[i]].is_leaf() ? leaf_ref(kids[i]) : collapse(kids[i], depth + 1);
    int order[kNodeWidth];
    for (int i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order, order + n,
                     [&](int a, int b) { return tris_[kids[a]] > tris_[kids[b]]; });
    {
      std::uint32_t k[kNodeWidth], r[kNodeWidth];
      for (int i = 0; i < n; ++i) k[i] = kids[order[i]], r[i] = refs[order[i]];
      std::copy(k, k + n, kids);
      std::copy(r, r + n, refs);
    }
    float lo[3][kNodeWidth], hi[3][kNodeWidth];
    for (int i = 0; i < n; ++i) {
      // Binary node boxes are unions of float vertex coordinates; a side at the builder's clamp
      // (coordinates beyond it) becomes the largest float, which still holds every finite vertex.
      const BvhFloatNode& b = bin_.nodes[kids[i]];
      for (int a = 0; a < 3; ++a) {
        lo[a][i] = b.lo[a] <= -kBuildRefLimit ? -kMaxFloat : b.lo[a];
        hi[a][i] = b.hi[a] >= kBuildRefLimit ? kMaxFloat : b.hi[a];
      }
    }
    const auto used = static_cast<std::uint8_t>((1u << n) - 1);
    if (out_.quantised) {
      QuantisedNode& w = out_.qnodes[index];
      for (int a = 0; a < 3; ++a)
        quantise_axis(lo[a], hi[a], n, w.origin[a], w.exponent[a], w.q[2 * a], w.q[2 * a + 1]);
      w.used = used;
      for (int i = 0; i < kNodeWidth; ++i) {
        w.child[i] = i < n ? refs[i] : 0;
        w.pad[i] = 0;
      }
      return index;
    }
    WideNode& w = out_.nodes[index];
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < kNodeWidth; ++i) {
        w.box[a][i] = i < n ? lo[a][i] : 0.0f;
        w.box[a][kNodeWidth + i] = i < n ? hi[a][i] : 0.0f;
      }
    w.used = used;
    for (int i = 0; i < kNodeWidth; ++i) w.child[i] = i < n ? refs[i] : 0;
    for (std::uint8_t& b : w.pad) b = 0;
    return index;
  }

  const FloatBvh& bin_;
  std::span<const Vec3f> positions_;
  std::span<const std::array<std::uint32_t, 3>> triangles_;
  std::span<const std::uint32_t> source_;
  MeshBvh& out_;
  std::vector<std::uint32_t> tris_;        // triangles under each binary node
  std::vector<std::uint32_t> leaf_group_;  // first group of each binary leaf
  std::vector<std::uint32_t> leaf_order_;  // binary leaves in the order of their groups
  std::uint32_t next_group_ = 0;
};

}  // namespace

MeshBvh build_mesh_bvh(std::span<const Vec3f> positions,
                       std::span<const std::array<std::uint32_t, 3>> triangles,
                       const MeshBvhConfig& config, std::span<const std::uint32_t> source) {
  MeshBvh out;
  if (!source.empty() && source.size() != triangles.size())
    throw std::invalid_argument("build_mesh_bvh: one source index per triangle expected");
  const std::size_t n = triangles.size();
  if (n == 0) return out;
  // Triangle boxes go straight into the builder's 32-byte references (exact: float vertices).
  BvhBuildRefs refs(n);  // uninitialised: filled in parallel below
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          const Vec3f& a = positions[triangles[i][0]];
          const Vec3f& b = positions[triangles[i][1]];
          const Vec3f& c = positions[triangles[i][2]];
          refs[i] = {
              {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})},
              static_cast<std::uint32_t>(i),
              {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})},
              0};
        }
      });
  if (config.split_budget > 0) {
    split_triangle_refs(positions, triangles, config.split_budget, config.split_min_ratio, refs);
    out.split = refs.size() > n;
  }
  BvhBuildConfig bc;
  bc.bins = config.bins;
  bc.max_leaf_size = std::clamp(config.max_leaf_size, 1, 4 * kMaxGroupsPerLeaf);
  bc.leaf_block = std::max(config.leaf_block, 1);
  bc.traversal_cost = config.traversal_cost;
  const FloatBvh binary = build_float_bvh_from_refs(std::move(refs), bc);
  out.quantised = n > config.quantise_above;
  Collapser(binary, positions, triangles, source, out).run();
  return out;
}

namespace {

[[gnu::always_inline]] inline const MeshKernels& kernels() { return kernels_in_use(); }

}  // namespace

const TriangleGroup kEmptyTriangleGroup = [] {
  TriangleGroup g;
  for (auto& vertex : g.v)
    for (auto& axis : vertex)
      for (float& f : axis) f = kNaN;
  for (auto& id : g.id) id = kNoTriangle;
  for (auto& s : g.source) s = kNoTriangle;
  return g;
}();

const MeshKernels* mesh_kernels(Isa isa) {
  if (!isa_supported(isa)) return nullptr;
  switch (isa) {
    case Isa::kScalar:
      return &kMeshKernelsScalar;
#if defined(__x86_64__)
    case Isa::kSse4:
      return &kMeshKernelsSse4;
    case Isa::kAvx2:
      return &kMeshKernelsAvx2;
    case Isa::kAvx512:
      return &kMeshKernelsAvx512;
#endif
    default:
      return nullptr;
  }
}

const MeshKernels& active_mesh_kernels() {
  const MeshKernels* k = mesh_kernels(active_isa());
  return k ? *k : kMeshKernelsScalar;
}

void append_mesh_hit(std::vector<MeshBvhHit>& out, const MeshBvhHit& hit) { out.push_back(hit); }

bool intersect_closest(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit& hit) {
  return with_traversal_stack(
      bvh, [&](TraversalEntry* stack) { return kernels().closest(bvh, ray, hit, stack); });
}

std::unique_ptr<TraversalEntry[]> deep_traversal_stack(const MeshBvh& bvh) {
  // Uninitialised (the kernels write before they read).
  return std::make_unique_for_overwrite<TraversalEntry[]>(traversal_stack_size(bvh));
}

namespace {

// The packet stack (on the C++ stack up to depth 128) and the single-ray one of closest8.
template <class F>
int with_packet_stacks(const MeshBvh& bvh, F&& trace) {
  constexpr std::size_t kLocal = 128 * (kNodeWidth - 1) + 2;  // depth 128 without the heap
  std::vector<PacketEntry> heap;
  PacketEntry local[kLocal];
  PacketEntry* packet_stack = local;
  if (traversal_stack_size(bvh) > kLocal) {
    heap.resize(traversal_stack_size(bvh));
    packet_stack = heap.data();
  }
  return with_traversal_stack(bvh,
                              [&](TraversalEntry* stack) { return trace(packet_stack, stack); });
}

}  // namespace

int intersect_closest8(const MeshBvh& bvh, const MeshRay* rays, int mask, MeshBvhHit* hits) {
  if (bvh.empty()) return 0;
  return with_packet_stacks(bvh, [&](PacketEntry* packet_stack, TraversalEntry* single_stack) {
    return kernels().closest8(bvh, rays, mask, hits, packet_stack, single_stack);
  });
}

int intersect_closest8(const MeshBvh& bvh, const Ray* rays, int mask, MeshBvhHit* hits,
                       double* scale) {
  return with_packet_stacks(bvh, [&](PacketEntry* packet_stack, TraversalEntry* single_stack) {
    return kernels().closest8_rays(bvh, rays, mask, hits, scale, packet_stack, single_stack);
  });
}

bool intersect_any(const MeshBvh& bvh, const MeshRay& ray) {
  // The kernel tests bvh.empty() itself.
  return with_traversal_stack(
      bvh, [&](TraversalEntry* stack) { return kernels().any(bvh, ray, stack); });
}

void intersect_every(const MeshBvh& bvh, const MeshRay& ray, std::vector<MeshBvhHit>& out) {
  if (bvh.empty()) return;
  const std::size_t first = out.size();
  with_traversal_stack(bvh, [&](TraversalEntry* stack) {
    kernels().every(bvh, ray, out, stack);
    return 0;
  });
  // A split triangle sits in several leaves: keep its first hit only (the same t and
  // barycentrics in each, the same vertices tested).
  if (bvh.split && out.size() - first > 1) {
    const auto begin = out.begin() + static_cast<std::ptrdiff_t>(first);
    std::stable_sort(begin, out.end(), [](const MeshBvhHit& a, const MeshBvhHit& b) {
      return a.triangle < b.triangle;
    });
    out.erase(std::unique(begin, out.end(),
                          [](const MeshBvhHit& a, const MeshBvhHit& b) {
                            return a.triangle == b.triangle;
                          }),
              out.end());
  }
}

}  // namespace raycast
