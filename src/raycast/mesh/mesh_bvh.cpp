#include "mesh/mesh_bvh.h"

#include <xmmintrin.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "mesh/triangle.h"

namespace raycast {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
// Relative widening of a slab exit so that the float box test is conservative (pbrt-v4 6.8.2:
// 1 + 2 gamma(3) in float arithmetic).
constexpr float kSlabWiden = 1.0f + 2.0f * (3 * 0x1p-24f) / (1 - 3 * 0x1p-24f);
// The same margin for negative distances (multiplying by it moves them towards +infinity).
constexpr float kSlabNarrow = 2.0f - kSlabWiden;
// Direction components smaller than this are replaced by it (with their sign) when computing
// 1 / d, so that the box test never multiplies 0 by infinity (the ray is first scaled so that
// its largest component is in [1, 2)).
constexpr float kMinDirection = 0x1p-64f;

// ---- Build ------------------------------------------------------------------------------------

class Collapser {
 public:
  Collapser(const Bvh& bin, std::span<const Vec3f> positions,
            std::span<const std::array<std::uint32_t, 3>> triangles, MeshBvh& out)
      : bin_(bin), positions_(positions), triangles_(triangles), out_(out) {}

  void run() {
    // Leaf groups: one prefix sum over the binary leaves (in node order) gives each its groups.
    leaf_group_.assign(bin_.nodes.size(), 0);
    std::uint32_t groups = 0;
    for (std::size_t i = 0; i < bin_.nodes.size(); ++i) {
      const BvhNode& n = bin_.nodes[i];
      if (!n.is_leaf()) continue;
      leaf_group_[i] = groups;
      groups += (n.count + 3) / 4;
    }
    out_.groups.resize(groups);
    tbb::parallel_for(std::size_t(0), bin_.nodes.size(), [&](std::size_t i) {
      if (bin_.nodes[i].is_leaf()) fill_leaf(bin_.nodes[i], leaf_group_[i]);
    });
    if (bin_.nodes[0].is_leaf()) {
      out_.root = leaf_ref(0);
      out_.depth = 0;
      return;
    }
    out_.nodes.reserve(bin_.nodes.size() / 2 + 1);
    out_.root = collapse(0, 1);
  }

 private:
  std::uint32_t leaf_ref(std::uint32_t node) const {
    const BvhNode& n = bin_.nodes[node];
    const std::uint32_t count = (n.count + 3) / 4;
    return kLeafBit | ((count - 1) << 29) | leaf_group_[node];
  }

  void fill_leaf(const BvhNode& n, std::uint32_t first_group) {
    for (std::uint32_t k = 0; k < (n.count + 3) / 4; ++k) {
      TriangleGroup& g = out_.groups[first_group + k];
      for (int lane = 0; lane < 4; ++lane) {
        const std::uint32_t i = k * 4 + lane;
        if (i >= n.count) {
          for (auto& vertex : g.v)
            for (auto& axis : vertex) axis[lane] = kNaN;
          g.id[lane] = kNoTriangle;
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
      }
    }
  }

  // Makes the wide node for binary inner node `node`: its children are the binary descendants
  // found by repeatedly opening the child of largest surface area (up to 4).
  std::uint32_t collapse(std::uint32_t node, int depth) {
    out_.depth = std::max(out_.depth, depth);
    std::uint32_t kids[4] = {bin_.nodes[node].first, bin_.nodes[node].first + 1, 0, 0};
    int n = 2;
    while (n < 4) {
      int best = -1;
      double best_area = -1;
      for (int i = 0; i < n; ++i) {
        const BvhNode& c = bin_.nodes[kids[i]];
        if (!c.is_leaf() && c.box.half_area() > best_area) {
          best_area = c.box.half_area();
          best = i;
        }
      }
      if (best < 0) break;
      const std::uint32_t opened = kids[best];
      kids[best] = bin_.nodes[opened].first;
      kids[n++] = bin_.nodes[opened].first + 1;
    }
    const std::uint32_t index = static_cast<std::uint32_t>(out_.nodes.size());
    out_.nodes.emplace_back();
    std::uint32_t refs[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
      const BvhNode& c = bin_.nodes[kids[i]];
      refs[i] = c.is_leaf() ? leaf_ref(kids[i]) : collapse(kids[i], depth + 1);
    }
    WideNode& w = out_.nodes[index];
    for (int i = 0; i < 4; ++i) {
      // Binary node boxes are unions of float vertex coordinates, so these conversions are exact.
      const bool used = i < n;
      const Aabb& b = bin_.nodes[kids[i]].box;
      w.lo_x[i] = used ? static_cast<float>(b.lo.x) : kInf;
      w.lo_y[i] = used ? static_cast<float>(b.lo.y) : kInf;
      w.lo_z[i] = used ? static_cast<float>(b.lo.z) : kInf;
      w.hi_x[i] = used ? static_cast<float>(b.hi.x) : -kInf;
      w.hi_y[i] = used ? static_cast<float>(b.hi.y) : -kInf;
      w.hi_z[i] = used ? static_cast<float>(b.hi.z) : -kInf;
      w.child[i] = refs[i];
      w.pad[i] = 0;
    }
    return index;
  }

  const Bvh& bin_;
  std::span<const Vec3f> positions_;
  std::span<const std::array<std::uint32_t, 3>> triangles_;
  MeshBvh& out_;
  std::vector<std::uint32_t> leaf_group_;
};

// ---- Traversal --------------------------------------------------------------------------------

// Per-ray constants of the SIMD box and triangle tests.
struct RayPacket1 {
  __m128 o[3];      // origin, broadcast
  __m128 inv[3];    // 1 / d, broadcast
  int near_off[3];  // float offset of the near plane array of each axis in a WideNode
  int far_off[3];
  // Watertight test (Woop et al. 2013): permutation and shear.
  int kx, ky, kz;
  __m128 sx, sy, sz;
  __m128 okx, oky, okz;
};

RayPacket1 prepare(const MeshRay& r) {
  RayPacket1 p;
  const float* o = &r.o.x;
  const float* d = &r.d.x;
  for (int a = 0; a < 3; ++a) {
    p.o[a] = _mm_set1_ps(o[a]);
    float da = d[a];
    if (std::abs(da) < kMinDirection) da = da < 0 ? -kMinDirection : kMinDirection;
    const float inv = 1.0f / da;
    p.inv[a] = _mm_set1_ps(inv);
    // WideNode floats: lo_x 0, hi_x 4, lo_y 8, hi_y 12, lo_z 16, hi_z 20.
    p.near_off[a] = a * 8 + (inv >= 0 ? 0 : 4);
    p.far_off[a] = a * 8 + (inv >= 0 ? 4 : 0);
  }
  const WatertightRay w = make_watertight_ray(r.o, r.d);
  p.kx = w.kx;
  p.ky = w.ky;
  p.kz = w.kz;
  p.sx = _mm_set1_ps(w.sx);
  p.sy = _mm_set1_ps(w.sy);
  p.sz = _mm_set1_ps(w.sz);
  p.okx = _mm_set1_ps(o[w.kx]);
  p.oky = _mm_set1_ps(o[w.ky]);
  p.okz = _mm_set1_ps(o[w.kz]);
  return p;
}

// Slab test of the four children against [tmin, tmax]; returns the hit mask and the entries.
inline int intersect_node(const WideNode& n, const RayPacket1& p, __m128 tmin, __m128 tmax,
                          __m128& tnear) {
  const float* f = n.lo_x;
  const __m128 nx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(f + p.near_off[0]), p.o[0]), p.inv[0]);
  const __m128 ny = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(f + p.near_off[1]), p.o[1]), p.inv[1]);
  const __m128 nz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(f + p.near_off[2]), p.o[2]), p.inv[2]);
  const __m128 fx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(f + p.far_off[0]), p.o[0]), p.inv[0]);
  const __m128 fy = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(f + p.far_off[1]), p.o[1]), p.inv[1]);
  const __m128 fz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(f + p.far_off[2]), p.o[2]), p.inv[2]);
  tnear = _mm_max_ps(_mm_max_ps(nx, ny), _mm_max_ps(nz, tmin));
  // Widen the far distance away from the near one: scale it up when it is positive, down when it
  // is negative (a node behind the origin, met by the whole-line queries of spans). Scaling a
  // negative far distance up would shrink the interval and cull flat boxes (a mesh's
  // axis-aligned face) behind the origin.
  const __m128 far = _mm_min_ps(_mm_min_ps(fx, fy), fz);
  const __m128 ahead = _mm_cmpge_ps(far, _mm_setzero_ps());
  const __m128 widen = _mm_or_ps(_mm_and_ps(ahead, _mm_set1_ps(kSlabWiden)),
                                 _mm_andnot_ps(ahead, _mm_set1_ps(kSlabNarrow)));
  const __m128 tfar = _mm_min_ps(_mm_mul_ps(far, widen), tmax);
  return _mm_movemask_ps(_mm_cmple_ps(tnear, tfar));
}

// Watertight test of one group's four triangles: the hit mask, t, and (u, v, w, det) per lane.
struct GroupResult {
  alignas(16) float t[4];
  alignas(16) float v[4];
  alignas(16) float w[4];
  alignas(16) float det[4];
};

inline int intersect_group(const TriangleGroup& g, const RayPacket1& p, __m128 tmin, __m128 tmax,
                           GroupResult& res) {
  // Shear and scale the vertices into ray space (per vertex, so shared vertices agree exactly).
  const __m128 a_kz = _mm_sub_ps(_mm_load_ps(g.v[0][p.kz]), p.okz);
  const __m128 b_kz = _mm_sub_ps(_mm_load_ps(g.v[1][p.kz]), p.okz);
  const __m128 c_kz = _mm_sub_ps(_mm_load_ps(g.v[2][p.kz]), p.okz);
  const __m128 ax =
      _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g.v[0][p.kx]), p.okx), _mm_mul_ps(p.sx, a_kz));
  const __m128 ay =
      _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g.v[0][p.ky]), p.oky), _mm_mul_ps(p.sy, a_kz));
  const __m128 bx =
      _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g.v[1][p.kx]), p.okx), _mm_mul_ps(p.sx, b_kz));
  const __m128 by =
      _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g.v[1][p.ky]), p.oky), _mm_mul_ps(p.sy, b_kz));
  const __m128 cx =
      _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g.v[2][p.kx]), p.okx), _mm_mul_ps(p.sx, c_kz));
  const __m128 cy =
      _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g.v[2][p.ky]), p.oky), _mm_mul_ps(p.sy, c_kz));
  __m128 u = _mm_sub_ps(_mm_mul_ps(cx, by), _mm_mul_ps(cy, bx));
  __m128 v = _mm_sub_ps(_mm_mul_ps(ax, cy), _mm_mul_ps(ay, cx));
  __m128 w = _mm_sub_ps(_mm_mul_ps(bx, ay), _mm_mul_ps(by, ax));
  const __m128 zero = _mm_setzero_ps();
  const int zero_mask = _mm_movemask_ps(
      _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_cmpeq_ps(v, zero)), _mm_cmpeq_ps(w, zero)));
  if (zero_mask) {
    // An edge function exactly 0 in float: recompute that lane's three in double (the paper's
    // fallback), so the sign of a ray exactly through an edge or vertex is exact.
    alignas(16) float f[6][4], uu[4], vv[4], ww[4];
    _mm_store_ps(f[0], ax), _mm_store_ps(f[1], ay), _mm_store_ps(f[2], bx);
    _mm_store_ps(f[3], by), _mm_store_ps(f[4], cx), _mm_store_ps(f[5], cy);
    _mm_store_ps(uu, u), _mm_store_ps(vv, v), _mm_store_ps(ww, w);
    for (int l = 0; l < 4; ++l) {
      if (!(zero_mask >> l & 1)) continue;
      const double dax = f[0][l], day = f[1][l], dbx = f[2][l], dby = f[3][l], dcx = f[4][l],
                   dcy = f[5][l];
      uu[l] = static_cast<float>(dcx * dby - dcy * dbx);
      vv[l] = static_cast<float>(dax * dcy - day * dcx);
      ww[l] = static_cast<float>(dbx * day - dby * dax);
    }
    u = _mm_load_ps(uu);
    v = _mm_load_ps(vv);
    w = _mm_load_ps(ww);
  }
  const __m128 pos =
      _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(u, zero), _mm_cmpge_ps(v, zero)), _mm_cmpge_ps(w, zero));
  const __m128 neg =
      _mm_and_ps(_mm_and_ps(_mm_cmple_ps(u, zero), _mm_cmple_ps(v, zero)), _mm_cmple_ps(w, zero));
  const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
  __m128 mask = _mm_and_ps(_mm_or_ps(pos, neg), _mm_cmpneq_ps(det, zero));
  if (!_mm_movemask_ps(mask)) return 0;
  const __m128 az = _mm_mul_ps(p.sz, a_kz), bz = _mm_mul_ps(p.sz, b_kz),
               cz = _mm_mul_ps(p.sz, c_kz);
  const __m128 ts = _mm_add_ps(_mm_add_ps(_mm_mul_ps(u, az), _mm_mul_ps(v, bz)), _mm_mul_ps(w, cz));
  const __m128 t = _mm_div_ps(ts, det);
  mask = _mm_and_ps(mask, _mm_and_ps(_mm_cmpge_ps(t, tmin), _mm_cmple_ps(t, tmax)));
  const int m = _mm_movemask_ps(mask);
  if (m) {
    _mm_store_ps(res.t, t);
    _mm_store_ps(res.v, v);
    _mm_store_ps(res.w, w);
    _mm_store_ps(res.det, det);
  }
  return m;
}

struct StackEntry {
  std::uint32_t ref;
  float tnear;
};

constexpr int kStackSize = 256;

// A traversal stack: on the C stack for every tree of sane depth; on the heap (one allocation per
// query) only for trees deeper than kStackSize / 3 levels, which the SAH build makes only for
// pathological inputs.
class Stack {
 public:
  explicit Stack(const MeshBvh& bvh) {
    const std::size_t need = static_cast<std::size_t>(bvh.depth) * 3 + 4;
    if (need > kStackSize) {
      heap_.resize(need);
      data_ = heap_.data();
    }
  }
  StackEntry* data() { return data_; }

 private:
  StackEntry local_[kStackSize];
  std::vector<StackEntry> heap_;
  StackEntry* data_ = local_;
};

// Starts loading every hit child (node or first leaf group) at once, so that the memory latency
// of siblings overlaps instead of adding up.
inline void prefetch_children(const MeshBvh& bvh, const WideNode& node, int mask) {
  while (mask) {
    const std::uint32_t ref = node.child[__builtin_ctz(mask)];
    mask &= mask - 1;
    const char* p = (ref & kLeafBit) ? reinterpret_cast<const char*>(&bvh.groups[ref & 0x1FFFFFFFu])
                                     : reinterpret_cast<const char*>(&bvh.nodes[ref]);
    _mm_prefetch(p, _MM_HINT_T0);
    _mm_prefetch(p + 64, _MM_HINT_T0);
    if (ref & kLeafBit) _mm_prefetch(p + 128, _MM_HINT_T0);
  }
}

// Ordered descent: pushes the hit children except the nearest (farthest first, so they pop
// nearest first) with their entry distances, and returns the nearest.
inline std::uint32_t order_children(const WideNode& node, int mask, __m128 tn, StackEntry* stack,
                                    int& top) {
  const int first = __builtin_ctz(mask);
  mask &= mask - 1;
  if (!mask) return node.child[first];  // one child hit: no ordering, no push
  alignas(16) float tnear[4];
  _mm_store_ps(tnear, tn);
  const int second = __builtin_ctz(mask);
  mask &= mask - 1;
  if (!mask) {  // two: push the farther
    const bool swap = tnear[second] < tnear[first];
    const int near = swap ? second : first, far = swap ? first : second;
    stack[top++] = {node.child[far], tnear[far]};
    return node.child[near];
  }
  mask |= (1 << first) | (1 << second);
  int order[4], k = 0;
  while (mask) {
    const int i = __builtin_ctz(mask);
    mask &= mask - 1;
    int j = k++;
    while (j > 0 && tnear[order[j - 1]] < tnear[i]) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = i;
  }
  for (int j = 0; j < k - 1; ++j) stack[top++] = {node.child[order[j]], tnear[order[j]]};
  return node.child[order[k - 1]];
}

inline std::uint32_t leaf_first(std::uint32_t ref) { return ref & 0x1FFFFFFFu; }
inline std::uint32_t leaf_groups(std::uint32_t ref) { return ((ref >> 29) & 3u) + 1; }

}  // namespace

MeshBvh build_mesh_bvh(std::span<const Vec3f> positions,
                       std::span<const std::array<std::uint32_t, 3>> triangles,
                       const MeshBvhConfig& config) {
  MeshBvh out;
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
  BvhBuildConfig bc;
  bc.bins = config.bins;
  bc.max_leaf_size = std::clamp(config.max_leaf_size, 1, 4 * kMaxGroupsPerLeaf);
  bc.leaf_block = std::max(config.leaf_block, 1);
  bc.traversal_cost = config.traversal_cost;
  const Bvh binary = build_bvh_from_refs(std::move(refs), bc);
  Collapser(binary, positions, triangles, out).run();
  return out;
}

bool intersect_closest(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit& hit) {
  if (bvh.empty()) return false;
  const RayPacket1 p = prepare(ray);
  const __m128 tmin = _mm_set1_ps(ray.tmin);
  float tmax_s = ray.tmax;
  __m128 tmax = _mm_set1_ps(tmax_s);
  Stack stack_storage(bvh);
  StackEntry* stack = stack_storage.data();
  int top = 0;
  bool found = false;
  GroupResult res;
  std::uint32_t ref = bvh.root;
  for (;;) {
    if (!(ref & kLeafBit)) {
      const WideNode& node = bvh.nodes[ref];
      __m128 tn;
      int mask = intersect_node(node, p, tmin, tmax, tn);
      if (mask) {
        prefetch_children(bvh, node, mask);
        ref = order_children(node, mask, tn, stack, top);
        continue;
      }
    } else {
      const std::uint32_t first = leaf_first(ref), count = leaf_groups(ref);
      for (std::uint32_t gi = first; gi < first + count; ++gi) {
        int m = intersect_group(bvh.groups[gi], p, tmin, tmax, res);
        while (m) {
          const int l = __builtin_ctz(m);
          m &= m - 1;
          if (res.t[l] <= tmax_s) {
            tmax_s = res.t[l];
            hit = {
                res.t[l], res.v[l] / res.det[l],        res.w[l] / res.det[l], bvh.groups[gi].id[l],
                gi,       static_cast<std::uint32_t>(l)};
            found = true;
          }
        }
        tmax = _mm_set1_ps(tmax_s);
      }
    }
    // Pop, skipping entries whose entry point lies past the current nearest hit.
    for (;;) {
      if (top == 0) return found;
      const StackEntry& e = stack[--top];
      if (e.tnear <= tmax_s) {
        ref = e.ref;
        break;
      }
    }
  }
}

bool intersect_any(const MeshBvh& bvh, const MeshRay& ray) {
  if (bvh.empty()) return false;
  const RayPacket1 p = prepare(ray);
  const __m128 tmin = _mm_set1_ps(ray.tmin);
  const __m128 tmax = _mm_set1_ps(ray.tmax);
  Stack stack_storage(bvh);
  StackEntry* stack = stack_storage.data();
  int top = 0;
  GroupResult res;
  std::uint32_t ref = bvh.root;
  for (;;) {
    if (!(ref & kLeafBit)) {
      const WideNode& node = bvh.nodes[ref];
      __m128 tn;
      const int mask = intersect_node(node, p, tmin, tmax, tn);
      if (mask) {
        prefetch_children(bvh, node, mask);
        ref = order_children(node, mask, tn, stack, top);
        continue;
      }
    } else {
      const std::uint32_t first = leaf_first(ref), count = leaf_groups(ref);
      for (std::uint32_t gi = first; gi < first + count; ++gi)
        if (intersect_group(bvh.groups[gi], p, tmin, tmax, res)) return true;
    }
    if (top == 0) return false;
    ref = stack[--top].ref;
  }
}

void intersect_every(const MeshBvh& bvh, const MeshRay& ray, std::vector<MeshBvhHit>& out) {
  if (bvh.empty()) return;
  const RayPacket1 p = prepare(ray);
  const __m128 tmin = _mm_set1_ps(ray.tmin);
  const __m128 tmax = _mm_set1_ps(ray.tmax);
  Stack stack_storage(bvh);
  StackEntry* stack = stack_storage.data();
  int top = 0;
  GroupResult res;
  stack[top++] = {bvh.root, 0};
  while (top > 0) {
    const std::uint32_t ref = stack[--top].ref;
    if (!(ref & kLeafBit)) {
      const WideNode& node = bvh.nodes[ref];
      __m128 tn;
      int mask = intersect_node(node, p, tmin, tmax, tn);
      while (mask) {
        const int i = __builtin_ctz(mask);
        mask &= mask - 1;
        stack[top++] = {node.child[i], 0};
      }
    } else {
      const std::uint32_t first = leaf_first(ref), count = leaf_groups(ref);
      for (std::uint32_t gi = first; gi < first + count; ++gi) {
        int m = intersect_group(bvh.groups[gi], p, tmin, tmax, res);
        while (m) {
          const int l = __builtin_ctz(m);
          m &= m - 1;
          out.push_back({res.t[l], res.v[l] / res.det[l], res.w[l] / res.det[l],
                         bvh.groups[gi].id[l], gi, static_cast<std::uint32_t>(l)});
        }
      }
    }
  }
}

}  // namespace raycast
