// The mesh traversal, written once and compiled once per instruction set (no include guard, no
// includes: a mesh/wide_kernels_<isa>.cpp file includes it after its headers, inside its own
// `#pragma GCC target` region, having defined RAYCAST_KERNEL_NS and, in that namespace, the lane
// type V8 (8 floats) and its mask type M8 with:
//   load8(p) (32-byte aligned), load8_u8(p) (8 bytes, converted to float), load44(a, b) (two
//   16-byte aligned halves), splat(x), store8(p, v),
//   + - * /, vmin(a, b) and vmax(a, b) (the second operand when either is NaN, as SSE's minps),
//   cmp_le, cmp_ge, cmp_eq (ordered: false on NaN), cmp_ne (true on NaN), mand, mor, bits(m)
//   (lane i -> bit i), select(m, a, b) (a where m).
// A kernel may define RAYCAST_KERNEL_MINMAX_SLABS to compute a float node's slab distances from
// both rows at fixed offsets (min and max) instead of rows chosen by the sign of d: same results.
// A kernel may define RAYCAST_KERNEL_FOLDED_ROWS instead: the rows chosen by the sign of d, as
// (o - plane) * (-1/d), so that each plane load folds into its subtraction (same results).
// With RAYCAST_KERNEL_FOLDED_ROWS, the walks of uses_octant_walks take the row offsets as
// constants, one walk per direction octant (same results).
// A kernel may define RAYCAST_KERNEL_ROW_OFFSETS: the triangle test addresses its rows through
// three per-ray byte offsets (same loads).
// A kernel may also define RAYCAST_KERNEL_NODE16 with NodeRay16, prepare_node16(o, inv, out) and
// intersect_node16(node, ...) for both node formats: its own node test with the same results
// (AVX-512: 16 lanes), which the walks use where uses_node16 says.
// Every lane operation is one IEEE single-precision operation and the code never fuses a multiply
// with an add, so every ISA returns the same hits bit for bit (the tests compare them).

namespace raycast::RAYCAST_KERNEL_NS {

// Relative widening of a slab exit so that the float box test is conservative (pbrt-v4 6.8.2:
// 1 + 2 gamma(3) in float arithmetic). The exit is min(far distances, tmax) widened as one, so
// that tmax is widened too: a box whose exact entry is at most tmax has a rounded entry
// fl(fl(plane - o) * fl(1/d)), at most 3 roundings, (1 + u)^3 < 1 + 4u above it (u = 2^-24),
// and fl(tmax * kSlabWiden) >= tmax (1 + 6u)(1 - u) > tmax (1 + 4u): a hit at t == tmax is
// never culled by its box's rounding (negative ones likewise with kSlabNarrow).
constexpr float kSlabWiden = 1.0f + 2.0f * (3 * 0x1p-24f) / (1 - 3 * 0x1p-24f);
// The same margin for negative distances (multiplying by it moves them towards +infinity).
constexpr float kSlabNarrow = 2.0f - kSlabWiden;
// Non-zero direction components smaller than this are replaced by it (with their sign) when
// computing 1 / d (the ray is first scaled so that its largest component is in [1, 2)). A zero
// component keeps 1 / d = +-infinity: see prepare.
constexpr float kMinDirection = 0x1p-64f;
constexpr float kInfinityF = __builtin_huge_valf();

// A scalar exit or tmax widened as the node tests widen them (the nearest walk's pop compares a
// pushed entry with its current hit's t so widened, as the node test did).
inline float widen_exit(float t) { return std::max(t * kSlabWiden, t * kSlabNarrow); }

enum class Query { kNearest, kAny, kAll };

// Whether query Q on a tree of Node takes the kernel's 16-lane node test (RAYCAST_KERNEL_NODE16,
// AVX-512) rather than the 8-lane one. On bench/embree_table.sh's meshes the 8-lane test wins on
// float nodes, and on quantised ones for any-hit queries (10M sphere shadow rays about 20 %
// faster); quantised nearest-hit walks are faster with the 16-lane test (10M sphere, incoherent).
template <Query Q, class Node>
constexpr bool uses_node16() {
#ifdef RAYCAST_KERNEL_NODE16
  return std::is_same_v<Node, QuantisedNode> && Q != Query::kAny;
#else
  return false;
#endif
}

// Per-ray constants of the box and triangle tests.
struct RayData {
  V8 o[3];  // origin, broadcast
  // A ray with a zero direction component: the origin as the near and the far planes' rows
  // subtract it in the walk kInPlane (traverse_in_plane); not set for other rays.
  V8 o_near[3], o_far[3];
  V8 inv[3];          // 1 / d, broadcast
  V8 neg_inv[3];      // -1 / d, broadcast
  V8 neg_inv_far[3];  // -1 / d * kFarWiden (the ordered node tests; set by traverse)
  V8 tmax_far;        // tmax * kFarWiden (the any-hit walks' tmax is the ray's; set by traverse)
#ifdef RAYCAST_KERNEL_MINMAX_SLABS
  V8 mul_lo[3], mul_hi[3];  // neg_inv or neg_inv_far: the lo and hi rows' (set by traverse)
#endif
  int near_off[3];  // offset of the near planes of each axis in WideNode::box[axis] (and in
  int far_off[3];   // an axis's two rows of QuantisedNode::q)
  // Watertight test (Woop, Benthin and Wald 2013): permutation and shear.
  int kx, ky, kz;
  V8 sx, sy, sz;
  V8 okx, oky, okz;
  V8 tmin;
#ifdef RAYCAST_KERNEL_NODE16
  NodeRay16 node16;  // the kernel's own 16-lane node test (AVX-512)
#endif
};

// Fills p in place (returning RayData by value made GCC copy the AVX-512 part, nine 64-byte
// vectors, through the stack twice per ray), for query Q on a tree of Node.
// Returns whether a direction component is zero (those rays take traverse_in_plane).
template <Query Q, class Node>
inline bool prepare(const MeshRay& r, RayData& p) {
  const float* o = &r.o.x;
  const float* d = &r.d.x;
  float invs[3];
  bool zero = false;
  for (int a = 0; a < 3; ++a) {
    p.o[a] = splat(o[a]);
    float da = d[a];
    if (std::abs(da) < kMinDirection) [[unlikely]] {
      // A zero component keeps 1 / d = +-infinity (traverse_in_plane).
      if (da != 0)
        da = da < 0 ? -kMinDirection : kMinDirection;
      else
        zero = true;
    }
    const float inv = 1.0f / da;
    invs[a] = inv;
    p.inv[a] = splat(inv);
    p.neg_inv[a] = splat(-inv);
    // WideNode::box[a] and QuantisedNode::q[2a], q[2a + 1]: the lo planes, then the hi planes.
    p.near_off[a] = inv >= 0 ? 0 : kNodeWidth;
    p.far_off[a] = inv >= 0 ? kNodeWidth : 0;
  }
  const WatertightRay w = make_watertight_ray(r.o, r.d);
  p.kx = w.kx;
  p.ky = w.ky;
  p.kz = w.kz;
  p.sx = splat(w.sx);
  p.sy = splat(w.sy);
  p.sz = splat(w.sz);
  p.okx = splat(o[w.kx]);
  p.oky = splat(o[w.ky]);
  p.okz = splat(o[w.kz]);
  p.tmin = splat(r.tmin);
#ifdef RAYCAST_KERNEL_NODE16
  if constexpr (uses_node16<Q, Node>()) prepare_node16(o, o, invs, p.node16);
#endif
  (void)invs;
  return zero;
}

// The node arrays of the two formats (mesh/mesh_bvh.h).
template <class Node>
const Node* node_array(const MeshBvh& bvh) {
  if constexpr (std::is_same_v<Node, WideNode>)
    return bvh.nodes.data();
  else
    return bvh.qnodes.data();
}

// The near and far distances of a node's eight children on each axis: float planes as stored.
#ifdef RAYCAST_KERNEL_MINMAX_SLABS
// Both rows at fixed offsets, near and far as their min and max: no per-ray row offsets to keep
// in registers, and the plane loads fold into the subtractions (three-operand AVX; with SSE's
// two-operand forms and two registers per V8 this costs more than it saves). (o - plane) *
// (-1/d) is (plane - o) * (1/d) bit for bit, and for a used child (lo <= hi, no NaN) the smaller
// distance is the near plane's whatever the sign of d (equal values differ in bits only as zeros
// of opposite sign, which one multiplier cannot give).
inline void node_distances(const WideNode& n, const RayData& p, V8 d[6]) {
  for (int a = 0; a < 3; ++a) {
    const V8 lo = (p.o[a] - load8(n.box[a])) * p.neg_inv[a];
    const V8 hi = (p.o[a] - load8(n.box[a] + kNodeWidth)) * p.neg_inv[a];
    d[a] = vmin(lo, hi);
    d[3 + a] = vmax(lo, hi);
  }
}
#elif defined(RAYCAST_KERNEL_FOLDED_ROWS)
// The rows chosen by the sign of d, as (o - plane) * (-1/d): the plane loads fold into the
// subtractions. The same value as (plane - o) * (1/d) but for the sign of a zero distance (plane
// == o), which no comparison of the walk tells apart. AVX-512 (32 vector registers: the negated
// reciprocals stay in registers). Oct >= 0: the walk of one direction octant (bit a set when
// near_off[a] == kNodeWidth), whose row offsets are constants in the loads' addresses: the six
// per-ray offsets no longer compete for the 16 general registers (GCC reloaded them from the
// stack at every node).
template <int Oct = -1>
inline void node_distances(const WideNode& n, const RayData& p, V8 d[6]) {
  for (int a = 0; a < 3; ++a) {
    const int near_off = Oct < 0 ? p.near_off[a] : (Oct >> a & 1) * kNodeWidth;
    const int far_off = Oct < 0 ? p.far_off[a] : kNodeWidth - near_off;
    d[a] = (p.o[a] - load8(n.box[a] + near_off)) * p.neg_inv[a];
    d[3 + a] = (p.o[a] - load8(n.box[a] + far_off)) * p.neg_inv[a];
  }
}
#define RAYCAST_KERNEL_OCTANT_WALKS 1
#else
inline void node_distances(const WideNode& n, const RayData& p, V8 d[6]) {
  for (int a = 0; a < 3; ++a) {
    d[a] = (load8(n.box[a] + p.near_off[a]) - p.o[a]) * p.inv[a];
    d[3 + a] = (load8(n.box[a] + p.far_off[a]) - p.o[a]) * p.inv[a];
  }
}
#endif

// The same for quantised planes, dequantised exactly as the build checked them
// (origin + q * scale).
inline void node_distances(const QuantisedNode& n, const RayData& p, V8 d[6]) {
  const std::uint8_t* q = n.q[0];
  for (int a = 0; a < 3; ++a) {
    const V8 s = splat(node_scale(n.exponent[a])), o = splat(n.origin[a]);
    d[a] = ((o + load8_u8(q + 2 * kNodeWidth * a + p.near_off[a]) * s) - p.o[a]) * p.inv[a];
    d[3 + a] = ((o + load8_u8(q + 2 * kNodeWidth * a + p.far_off[a]) * s) - p.o[a]) * p.inv[a];
  }
}

// The walk of the rays with a zero direction component (prepare): their own origins per row.
constexpr int kInPlane = -2;

// node_distances for those rays: the rows chosen by the sign of d (as the generic test) with
// the near and far rows' origins of prepare. Every value as the generic test's but on the
// ray's zero axes.
inline void node_distances_in_plane(const WideNode& n, const RayData& p, V8 d[6]) {
  for (int a = 0; a < 3; ++a) {
    d[a] = (load8(n.box[a] + p.near_off[a]) - p.o_near[a]) * p.inv[a];
    d[3 + a] = (load8(n.box[a] + p.far_off[a]) - p.o_far[a]) * p.inv[a];
  }
}

inline void node_distances_in_plane(const QuantisedNode& n, const RayData& p, V8 d[6]) {
  const std::uint8_t* q = n.q[0];
  for (int a = 0; a < 3; ++a) {
    const V8 s = splat(node_scale(n.exponent[a])), o = splat(n.origin[a]);
    d[a] = ((o + load8_u8(q + 2 * kNodeWidth * a + p.near_off[a]) * s) - p.o_near[a]) * p.inv[a];
    d[3 + a] = ((o + load8_u8(q + 2 * kNodeWidth * a + p.far_off[a]) * s) - p.o_far[a]) * p.inv[a];
  }
}

// Slab test of the eight children against [tmin, tmax]: the hit mask and the entry distances.
template <int Oct, class Node>
inline int intersect_node8(const Node& n, const RayData& p, V8 tmax, V8& tnear) {
  V8 d[6];
  if constexpr (Oct == kInPlane) node_distances_in_plane(n, p, d);
#ifdef RAYCAST_KERNEL_OCTANT_WALKS
  else if constexpr (std::is_same_v<Node, WideNode>)
    node_distances<Oct>(n, p, d);
#endif
  else
    node_distances(n, p, d);
  const V8 nx = d[0], ny = d[1], nz = d[2], fx = d[3], fy = d[4], fz = d[5];
  tnear = vmax(vmax(nx, ny), vmax(nz, p.tmin));
  // Widen the exit, tmax included (kSlabWiden: a hit at t == tmax keeps its box), away from the
  // entry: scale it up when it is positive, down when it is negative (a node behind the origin,
  // met by the whole-line queries of spans). Scaling a negative exit up would shrink the interval
  // and cull flat boxes (a mesh's axis-aligned face) behind the origin. The larger of far *
  // widen and far * narrow is exactly that, whatever far's sign (two independent products and a
  // max: a shorter dependency chain than choosing the factor from the sign first).
  const V8 far = vmin(vmin(fx, fy), vmin(fz, tmax));
  const V8 tfar = vmax(far * splat(kSlabWiden), far * splat(kSlabNarrow));
  return bits(cmp_le(tnear, tfar)) & n.used;
}

// The widening of intersect_node8_ordered's exits, folded into the far rows' reciprocal. With
// a = fl(o - plane), n = fl(-1/d) and u = 2^-24, a positive exit fl(a * fl(n * kFarWiden)) is at
// least a n kFarWiden (1 - u)^2, and the test above's fl(fl(a n) * kSlabWiden) at most
// a n (1 + 6u) (1 + u)^2: with kFarWiden = 1 + 16u every positive exit is at least the test
// above's (so are its boxes, and a few more within 16 ulps). Negative exits keep their sign
// (rounding never flips one), zero ones their value. (Underflow aside, as in the test above.)
// tmax is widened by the same factor (p.tmax_far: the any-hit walk never lowers tmax): fl(tmax *
// kFarWiden) >= tmax (1 + 16u)(1 - u), above a rounded entry fl(fl(o - plane) * fl(-1/d)) <= (1 +
// u)^3 times an exact entry <= tmax (a hit at t == tmax keeps its box, as in the test above).
constexpr float kFarWiden = 1.0f + 0x1p-20f;

// The walk of the nearest-hit query on float nodes for the rays intersect_node8_ordered admits
// (traverse checks), on every ISA: its rule with the row offsets of the ray (this node test and
// the packets' lane test, packet_child, are the same operations, so every ISA and every packet lane
// culls alike: the nearest hit and its tie-break do not depend on the ISA).
constexpr int kOrdered = -3;

// intersect_node8_ordered with the ray's row offsets, tmax widened per call (the nearest walk
// lowers it), and the entry distances (for the ordering and the pop).
inline int intersect_node8_nearest(const WideNode& n, const RayData& p, V8 tmax, V8& tnear) {
  V8 d[6];
#ifdef RAYCAST_KERNEL_MINMAX_SLABS
  // Both rows at fixed offsets (no per-ray offsets in registers), each with its row's reciprocal
  // (mul_lo, mul_hi: the near row's -1/d, the far row's -1/d * kFarWiden), near and far as their
  // min and max: the values above, but where both are negative (then swapped: the bits' max
  // with tmin >= +0 ignores negatives and the bits' min culls either way) or zeros of opposite
  // sign (the same mask: +0 <= -0 as floats): the same mask and entry on every ISA.
  for (int a = 0; a < 3; ++a) {
    const V8 lo = (p.o[a] - load8(n.box[a])) * p.mul_lo[a];
    const V8 hi = (p.o[a] - load8(n.box[a] + kNodeWidth)) * p.mul_hi[a];
    d[a] = vmin(lo, hi);
    d[3 + a] = vmax(lo, hi);
  }
#else
  for (int a = 0; a < 3; ++a) {
    d[a] = (p.o[a] - load8(n.box[a] + p.near_off[a])) * p.neg_inv[a];
    d[3 + a] = (p.o[a] - load8(n.box[a] + p.far_off[a])) * p.neg_inv_far[a];
  }
#endif
  tnear = vmax_bits(vmax_bits(d[0], d[1]), vmax_bits(d[2], p.tmin));
  const V8 tfar = vmin_bits(vmin_bits(d[3], d[4]), vmin_bits(d[5], tmax * splat(kFarWiden)));
  return bits(cmp_le(tnear, tfar)) & n.used;
}

#ifdef RAYCAST_KERNEL_BITS_MINMAX
// The node test of the any-hit octant walks, for rays that traverse checked: tmin >= +0 (sign bit
// clear), tmax >= tmin, origin and direction finite, no direction component zero (so no distance
// is NaN). The kernel's vmax_bits / vmin_bits (integer max / min of the float bits: one cycle,
// where the float ones take two) order two floats as floats when one of them has its sign bit
// clear, so tnear has the value of the test above (tmin is an operand) and so has the exit's min
// with tmax. The far distance's min of three: the float min when no distance is negative; when one
// is, both are negative (the bits' min is never below the float min) and the box is culled as
// above, tnear being >= +0, except where a -0 (the origin on a far plane) with tnear == 0 enters a
// box the float test culls. And with tnear >= 0 the test above's far * kSlabNarrow (which differs
// from far * kSlabWiden as a max only when far < 0, where both cull) is not needed. So this test
// enters every box the test above enters and a few more (an any-hit walk's answer does not depend
// on it), with four dependent steps fewer between a node's loads and its mask.
template <int Oct>
inline int intersect_node8_ordered(const WideNode& n, const RayData& p) {
  V8 d[6];
  for (int a = 0; a < 3; ++a) {
    const int near_off = (Oct >> a & 1) * kNodeWidth, far_off = kNodeWidth - near_off;
    d[a] = (p.o[a] - load8(n.box[a] + near_off)) * p.neg_inv[a];
    d[3 + a] = (p.o[a] - load8(n.box[a] + far_off)) * p.neg_inv_far[a];
  }
  const V8 tnear = vmax_bits(vmax_bits(d[0], d[1]), vmax_bits(d[2], p.tmin));
  const V8 tfar = vmin_bits(vmin_bits(d[3], d[4]), vmin_bits(d[5], p.tmax_far));
  return bits(cmp_le(tnear, tfar)) & n.used;
}
#endif

// The node test of query Q on Node: the 8-lane one, or the kernel's 16-lane one (same results).
template <Query Q, int Oct, class Node>
inline int intersect_node(const Node& n, const RayData& p, V8 tmax, V8& tnear) {
  if constexpr (Oct == kOrdered && std::is_same_v<Node, WideNode>)
    return intersect_node8_nearest(n, p, tmax, tnear);
#ifdef RAYCAST_KERNEL_BITS_MINMAX
  if constexpr (Q == Query::kAny && Oct >= 0 && std::is_same_v<Node, WideNode>)
    return intersect_node8_ordered<Oct>(n, p);
#endif
#ifdef RAYCAST_KERNEL_NODE16
  if constexpr (uses_node16<Q, Node>())
    return intersect_node16(n, p.node16, p.tmin, tmax, tnear, kSlabWiden, kSlabNarrow);
#endif
  return intersect_node8<Oct>(n, p, tmax, tnear);
}

// Lane results of a two-group triangle test: t, and the edge functions v, w and det = u + v + w.
struct PairResult {
  alignas(32) float t[8];
  alignas(32) float v[8];
  alignas(32) float w[8];
  alignas(32) float det[8];
};

// Watertight test of two groups' eight triangles (lanes 0-3 from g0, 4-7 from g1): the hit mask
// (tmin <= t <= tmax) and, when it is not empty, the lane results.
// Always inlined where the walk asks for it (intersect_pair below): left to itself, GCC 12 does
// not inline it into the AVX-512 any-hit octant walks (the walk of every octant is reachable
// there), which costs a call per leaf with the walk's vectors spilled around it.
[[gnu::always_inline]] inline int intersect_pair_inlined(const TriangleGroup& g0,
                                                         const TriangleGroup& g1, const RayData& p,
                                                         V8 tmax, PairResult& res) {
  // Shear and scale the vertices into ray space (per vertex, so shared vertices agree exactly).
#ifdef RAYCAST_KERNEL_ROW_OFFSETS
  // Each row addressed as group + vertex * 48 (a constant) + axis * 16 (one of three per-ray
  // byte offsets), so the nine rows of both groups take three index registers, not nine.
  const std::ptrdiff_t x = p.kx * std::ptrdiff_t(sizeof g0.v[0][0]),
                       y = p.ky * std::ptrdiff_t(sizeof g0.v[0][0]),
                       z = p.kz * std::ptrdiff_t(sizeof g0.v[0][0]);
  const auto row = [](const TriangleGroup& g, int vertex, std::ptrdiff_t axis) {
    return reinterpret_cast<const float*>(reinterpret_cast<const char*>(g.v[vertex]) + axis);
  };
  const auto rows = [&](int vertex, std::ptrdiff_t axis) {
    return load44(row(g0, vertex, axis), row(g1, vertex, axis));
  };
#else
  const int x = p.kx, y = p.ky, z = p.kz;
  const auto rows = [&](int vertex, int axis) {
    return load44(g0.v[vertex][axis], g1.v[vertex][axis]);
  };
#endif
  const V8 a_kz = rows(0, z) - p.okz;
  const V8 b_kz = rows(1, z) - p.okz;
  const V8 c_kz = rows(2, z) - p.okz;
  const V8 ax = (rows(0, x) - p.okx) - p.sx * a_kz;
  const V8 ay = (rows(0, y) - p.oky) - p.sy * a_kz;
  const V8 bx = (rows(1, x) - p.okx) - p.sx * b_kz;
  const V8 by = (rows(1, y) - p.oky) - p.sy * b_kz;
  const V8 cx = (rows(2, x) - p.okx) - p.sx * c_kz;
  const V8 cy = (rows(2, y) - p.oky) - p.sy * c_kz;
  V8 u = cx * by - cy * bx;
  V8 v = ax * cy - ay * cx;
  V8 w = bx * ay - by * ax;
  const V8 zero = splat(0.0f);
  auto pos = mand(mand(cmp_ge(u, zero), cmp_ge(v, zero)), cmp_ge(w, zero));
  auto neg = mand(mand(cmp_le(u, zero), cmp_le(v, zero)), cmp_le(w, zero));
  // Most lanes fail here. The double fallback below can only turn a float 0 into a signed value
  // (rounding is monotonic, so a non-zero float edge function already has the exact sign), which
  // can take a lane out of pos or neg but never put one in: a pair with no candidate lane is a
  // miss without looking for zeros.
  if (!bits(mor(pos, neg))) return 0;
  const int zero_mask =
      bits(mand(mor(pos, neg), mor(mor(cmp_eq(u, zero), cmp_eq(v, zero)), cmp_eq(w, zero))));
  if (zero_mask) [[unlikely]] {
    // An edge function exactly 0 in float: recompute that lane's three in double (the paper's
    // fallback), so the sign of a ray exactly through an edge or vertex is exact.
    alignas(32) float f[6][8], uu[8], vv[8], ww[8];
    store8(f[0], ax), store8(f[1], ay), store8(f[2], bx);
    store8(f[3], by), store8(f[4], cx), store8(f[5], cy);
    store8(uu, u), store8(vv, v), store8(ww, w);
    for (int l = 0; l < 8; ++l) {
      if (!(zero_mask >> l & 1)) continue;
      const double dax = f[0][l], day = f[1][l], dbx = f[2][l], dby = f[3][l], dcx = f[4][l],
                   dcy = f[5][l];
      uu[l] = static_cast<float>(dcx * dby - dcy * dbx);
      vv[l] = static_cast<float>(dax * dcy - day * dcx);
      ww[l] = static_cast<float>(dbx * day - dby * dax);
    }
    u = load8(uu);
    v = load8(vv);
    w = load8(ww);
    pos = mand(mand(cmp_ge(u, zero), cmp_ge(v, zero)), cmp_ge(w, zero));
    neg = mand(mand(cmp_le(u, zero), cmp_le(v, zero)), cmp_le(w, zero));
  }
  const V8 det = (u + v) + w;
  const auto same_sign = mand(mor(pos, neg), cmp_ne(det, zero));
  if (!bits(same_sign)) return 0;
  const V8 az = p.sz * a_kz, bz = p.sz * b_kz, cz = p.sz * c_kz;
  const V8 ts = (u * az + v * bz) + w * cz;
  const V8 t = ts / det;
  const int m = bits(mand(same_sign, mand(cmp_ge(t, p.tmin), cmp_le(t, tmax))));
  if (m) {
    store8(res.t, t);
    store8(res.v, v);
    store8(res.w, w);
    store8(res.det, det);
  }
  return m;
}

// The pair test, inlined or called as GCC chooses.
inline int intersect_pair(const TriangleGroup& g0, const TriangleGroup& g1, const RayData& p,
                          V8 tmax, PairResult& res) {
  return intersect_pair_inlined(g0, g1, p, tmax, res);
}

// Starts loading every hit child (a node's cache lines, or all of a leaf's groups) at once,
// so that the memory latency of siblings overlaps instead of adding up. Always inlined: GCC 12
// finds an out-of-line copy free of side effects (__builtin_prefetch does not count) and deletes
// the calls.
template <class Node>
[[gnu::always_inline]] inline void prefetch_child(const MeshBvh& bvh, std::uint32_t ref) {
  const bool leaf = ref & kLeafBit;
  const char* c = leaf ? reinterpret_cast<const char*>(&bvh.groups[ref & 0x1FFFFFFFu])
                       : reinterpret_cast<const char*>(node_array<Node>(bvh) + ref);
  const int bytes = leaf ? static_cast<int>(((ref >> 29) & 3u) + 1) * int(sizeof(TriangleGroup))
                         : int(sizeof(Node));
  for (int off = 0; off < bytes; off += 64) __builtin_prefetch(c + off);
}

template <class Node>
[[gnu::always_inline]] inline void prefetch_children(const MeshBvh& bvh, const Node& node,
                                                     int mask) {
  while (mask) {
    prefetch_child<Node>(bvh, node.child[__builtin_ctz(mask)]);
    mask &= mask - 1;
  }
}

// Ordered descent: pushes the hit children except the nearest (farthest first, so that they pop
// nearest first) with their entry distances, prefetches the pushed ones (the nearest is read at
// once: its loads issue together without help), and returns the nearest.
template <class Node>
inline std::uint32_t order_children(const MeshBvh& bvh, const Node& node, int mask, V8 tn,
                                    TraversalEntry* stack, int& top) {
  const int first = __builtin_ctz(mask);
  mask &= mask - 1;
  if (!mask) return node.child[first];  // one child hit: no ordering, no push
  alignas(32) float tnear[8];
  store8(tnear, tn);
  const int second = __builtin_ctz(mask);
  mask &= mask - 1;
  if (!mask) {  // two: push the farther
    const bool swap = tnear[second] < tnear[first];
    const int near = swap ? second : first, far = swap ? first : second;
    prefetch_child<Node>(bvh, node.child[far]);
    stack[top++] = {node.child[far], tnear[far]};
    return node.child[near];
  }
  mask |= (1 << first) | (1 << second);
  // Insertion sort, farthest first, straight onto the stack; every child prefetched on the way
  // (all but the nearest would need the sort first).
  const int base = top;
  while (mask) {
    const int i = __builtin_ctz(mask);
    mask &= mask - 1;
    const TraversalEntry e{node.child[i], tnear[i]};
    prefetch_child<Node>(bvh, e.ref);
    int j = top++;
    while (j > base && stack[j - 1].tnear < e.tnear) {
      stack[j] = stack[j - 1];
      --j;
    }
    stack[j] = e;
  }
  return stack[--top].ref;
}

inline std::uint32_t leaf_first(std::uint32_t ref) { return ref & 0x1FFFFFFFu; }
inline std::uint32_t leaf_groups(std::uint32_t ref) { return ((ref >> 29) & 3u) + 1; }

// The one traversal of the three queries (the shape of madmann91/bvh's intersect<IsAnyHit>):
// nearest-first descent with entries beyond the current hit skipped (kNearest), stop at the
// first hit (kAny), or every hit appended to `out` (kAll).
template <Query Q, class Node, int Oct>
[[gnu::always_inline]] inline bool walk(const MeshBvh& bvh, const RayData& p, float tmax_s,
                                        MeshBvhHit* hit, std::vector<MeshBvhHit>* out,
                                        TraversalEntry* stack) {
  const Node* nodes = node_array<Node>(bvh);
  V8 tmax = splat(tmax_s);
  // The pop's bound: tmax_s widened as the node test widens it once a hit has set tmax_s; until
  // then every pushed entry passed the node test against the widened tmax.
  float reach_s = kInfinityF;
  int top = 0;
  bool found = false;
  PairResult res;
  std::uint32_t ref = bvh.root;
  for (;;) {
    if (!(ref & kLeafBit)) {
      const Node& node = nodes[ref];
      V8 tn;
      int mask = intersect_node<Q, Oct>(node, p, tmax, tn);
      if (mask) {
        if constexpr (Q == Query::kNearest) {
          ref = order_children(bvh, node, mask, tn, stack, top);
        } else {
          const int first = __builtin_ctz(mask);
          mask &= mask - 1;
          // Every hit child is prefetched, the one entered next too (Embree's order): its later
          // cache lines (a node's planes, a leaf's second group) then load with the first.
          prefetch_child<Node>(bvh, node.child[first]);
          while (mask) {
            const std::uint32_t child = node.child[__builtin_ctz(mask)];
            prefetch_child<Node>(bvh, child);
            stack[top++].ref = child;  // the entry distance: never read by these queries' pops
            mask &= mask - 1;
          }
          ref = node.child[first];
        }
        continue;
      }
    } else {
      const std::uint32_t first = leaf_first(ref), end = first + leaf_groups(ref);
      for (std::uint32_t gi = first; gi < end; gi += 2) {
        const TriangleGroup& g1 = gi + 1 < end ? bvh.groups[gi + 1] : kEmptyTriangleGroup;
        int m = Q == Query::kAny && Oct >= 0
                    ? intersect_pair_inlined(bvh.groups[gi], g1, p, tmax, res)
                    : intersect_pair(bvh.groups[gi], g1, p, tmax, res);
        if (!m) continue;
        if constexpr (Q == Query::kAny) return true;
        while (m) {
          const int l = __builtin_ctz(m);
          m &= m - 1;
          const std::uint32_t g = gi + (l >> 2);
          const MeshBvhHit h{res.t[l],
                             res.v[l] / res.det[l],
                             res.w[l] / res.det[l],
                             bvh.groups[g].id[l & 3],
                             bvh.groups[g].source[l & 3],
                             g,
                             static_cast<std::uint32_t>(l & 3)};
          if constexpr (Q == Query::kNearest) {
            // Ties in t go to the smaller triangle index, so that the answer does not depend on
            // the visiting order (packets visit leaves in another order).
            if (res.t[l] < tmax_s ||
                (res.t[l] == tmax_s && (!found || h.triangle < hit->triangle))) {
              tmax_s = res.t[l];
              *hit = h;
              found = true;
            }
          } else {
            append_mesh_hit(*out, h);
            found = true;
          }
        }
        if constexpr (Q == Query::kNearest) tmax = splat(tmax_s), reach_s = widen_exit(tmax_s);
      }
    }
    // Pop, skipping entries whose entry point lies past the current nearest hit (widened: a
    // tied triangle's box may round its entry a few ulps above it).
    for (;;) {
      if (top == 0) return found;
      const TraversalEntry& e = stack[--top];
      if (Q != Query::kNearest || e.tnear <= reach_s) {
        ref = e.ref;
        break;
      }
    }
  }
}

// Whether query Q on Node runs one walk per direction octant (row offsets as constants): the
// float-node walks of the folded-row kernels (AVX-512). On the 1M sphere of
// bench/embree_table.sh any-hit walks are about 2.5 % faster so; the nearest-hit walk, eight
// times larger in code, is about 3 % slower (primary rays).
template <Query Q, class Node>
constexpr bool uses_octant_walks() {
#ifdef RAYCAST_KERNEL_OCTANT_WALKS
  return std::is_same_v<Node, WideNode> && Q == Query::kAny;
#else
  return false;
#endif
}

// The rays with a zero direction component, out of line (rare; and so that the other rays'
// RayData never has its address taken, which kept GCC from holding it in registers). On such an
// axis the ray lies in the plane x_a = o_a and 1/d = +-infinity (as the sign of the zero: prepare),
// so each distance on that axis is +-infinity, or NaN where a plane equals the origin subtracted.
// The walk kInPlane's near planes' rows subtract the float just past o_a in the direction of 1/d,
// its far planes' rows the float just before it: a near plane at or behind o_a (on the side 1/d
// points away from) gives -infinity, a far plane at or beyond it +infinity, so every box holding
// the plane x_a = o_a is entered whatever the sign of the zero (a box with a face in that plane,
// met at its edge, was culled with 1/d clamped to +-2^-64: slab [-huge, 0]). A NaN comes only
// from a plane equal to a shifted origin, i.e. from a box that lies wholly on one side of x_a =
// o_a, holds no point of the ray, and may be entered or culled alike (no triangle in it can be
// hit). (The one origin of the other walks gives NaN for a box with a face at o_a.) Other axes
// keep o_a. The 16-lane node test's origins [lo rows | hi rows] likewise.
template <Query Q, class Node>
[[gnu::noinline, gnu::cold]] bool traverse_in_plane(const MeshBvh& bvh, const MeshRay& ray,
                                                    MeshBvhHit* hit, std::vector<MeshBvhHit>* out,
                                                    TraversalEntry* stack) {
  RayData p;
  prepare<Q, Node>(ray, p);
  const float* o = &ray.o.x;
  const float* d = &ray.d.x;
  float o_lo[3], o_hi[3], invs[3];
  for (int a = 0; a < 3; ++a) {
    float da = d[a];  // prepare's reciprocal
    if (std::abs(da) < kMinDirection && da != 0) da = da < 0 ? -kMinDirection : kMinDirection;
    invs[a] = 1.0f / da;
    float near_o = o[a], far_o = o[a];
    if (da == 0) {
      const float up = std::nextafter(o[a], kInfinityF), down = std::nextafter(o[a], -kInfinityF);
      near_o = invs[a] > 0 ? up : down;
      far_o = invs[a] > 0 ? down : up;
    }
    p.o_near[a] = splat(near_o);
    p.o_far[a] = splat(far_o);
    o_lo[a] = invs[a] >= 0 ? near_o : far_o;
    o_hi[a] = invs[a] >= 0 ? far_o : near_o;
  }
#ifdef RAYCAST_KERNEL_NODE16
  if constexpr (uses_node16<Q, Node>()) prepare_node16(o_lo, o_hi, invs, p.node16);
#endif
  (void)o_lo, (void)o_hi, (void)invs;
  return walk<Q, Node, kInPlane>(bvh, p, ray.tmax, hit, out, stack);
}

// The rays of the ordered node tests (intersect_node8_ordered): tmin >= +0, tmax >= tmin, origin
// and direction finite (a zero direction component is traverse_in_plane's). Finiteness as one
// sum (NaN or infinite when a term is; a sum of huge finite terms that overflows only sends the
// ray to the float test): a few instructions per ray, the same decision on every ISA.
inline bool ordered_ray(const MeshRay& ray) {
  const float s = ((ray.o.x + ray.o.y) + (ray.o.z + ray.d.x)) + ((ray.d.y + ray.d.z) + ray.tmin);
  return !std::signbit(ray.tmin) && ray.tmax >= ray.tmin && s - s == 0;
}

// The nearest-hit rays on float nodes that the ordered test does not admit, out of line with their
// own RayData (inlined beside the ordered walk, or passed its RayData by address, the ordered
// walk runs slower).
template <Query Q, class Node>
[[gnu::noinline, gnu::cold]] bool traverse_unordered(const MeshBvh& bvh, const MeshRay& ray,
                                                     MeshBvhHit* hit, std::vector<MeshBvhHit>* out,
                                                     TraversalEntry* stack) {
  RayData p;
  prepare<Q, Node>(ray, p);
  return walk<Q, Node, -1>(bvh, p, ray.tmax, hit, out, stack);
}

// traverse's body, always inlined: into traverse, and into occluded_if_valid below. kFromValidRay:
// `ray` is convert_ray's of an is_valid Ray (occluded_if_valid), so its tmax >= tmin (rounding
// outwards is monotonic) and its direction is finite (scaled to at most 2 on its largest axis).
template <Query Q, class Node, bool kFromValidRay = false>
[[gnu::always_inline]] inline bool traverse_inlined(const MeshBvh& bvh, const MeshRay& ray,
                                                    MeshBvhHit* hit, std::vector<MeshBvhHit>* out,
                                                    TraversalEntry* stack) {
  if (bvh.empty()) return false;
  RayData p;
  if (prepare<Q, Node>(ray, p)) [[unlikely]]
    return traverse_in_plane<Q, Node>(bvh, ray, hit, out, stack);
  if constexpr (Q == Query::kNearest && std::is_same_v<Node, WideNode>) {
    if (!ordered_ray(ray)) [[unlikely]]
      return traverse_unordered<Q, Node>(bvh, ray, hit, out, stack);
    for (int a = 0; a < 3; ++a) {
      p.neg_inv_far[a] = p.neg_inv[a] * splat(kFarWiden);
#ifdef RAYCAST_KERNEL_MINMAX_SLABS
      // As near_off[a] == 0 (prepare's inv >= 0), as a lane select: GCC made the conditional
      // copies branches through the stack.
      const M8 near_lo = cmp_ge(p.inv[a], splat(0.0f));
      p.mul_lo[a] = select(near_lo, p.neg_inv[a], p.neg_inv_far[a]);
      p.mul_hi[a] = select(near_lo, p.neg_inv_far[a], p.neg_inv[a]);
#endif
    }
    return walk<Q, Node, kOrdered>(bvh, p, ray.tmax, hit, out, stack);
  }
  if constexpr (uses_octant_walks<Q, Node>()) {
#ifdef RAYCAST_KERNEL_BITS_MINMAX
    // intersect_node8_ordered's rays; the others (NaN, infinities, tmin < 0) take the walk of
    // every octant.
    // (ordered_ray's test but for its sum: with the sum GCC allocates this walk's registers
    // worse, about 4 % slower on the 1M sphere's shadow rays.)
    if (!(ray.tmin >= 0 && !std::signbit(ray.tmin) && is_finite(ray.o) &&
          (kFromValidRay || (ray.tmax >= ray.tmin && is_finite(ray.d)))))
      return walk<Q, Node, -1>(bvh, p, ray.tmax, hit, out, stack);
    for (int a = 0; a < 3; ++a) p.neg_inv_far[a] = p.neg_inv[a] * splat(kFarWiden);
    p.tmax_far = splat(ray.tmax * kFarWiden);
#endif
    // The octant prepare chose the rows by (inv >= 0, NaN included), so the walks read the same.
    const int oct = (p.near_off[0] != 0) | (p.near_off[1] != 0) << 1 | (p.near_off[2] != 0) << 2;
    switch (oct) {
      case 0:
        return walk<Q, Node, 0>(bvh, p, ray.tmax, hit, out, stack);
      case 1:
        return walk<Q, Node, 1>(bvh, p, ray.tmax, hit, out, stack);
      case 2:
        return walk<Q, Node, 2>(bvh, p, ray.tmax, hit, out, stack);
      case 3:
        return walk<Q, Node, 3>(bvh, p, ray.tmax, hit, out, stack);
      case 4:
        return walk<Q, Node, 4>(bvh, p, ray.tmax, hit, out, stack);
      case 5:
        return walk<Q, Node, 5>(bvh, p, ray.tmax, hit, out, stack);
      case 6:
        return walk<Q, Node, 6>(bvh, p, ray.tmax, hit, out, stack);
      default:
        return walk<Q, Node, 7>(bvh, p, ray.tmax, hit, out, stack);
    }
  }
  return walk<Q, Node, -1>(bvh, p, ray.tmax, hit, out, stack);
}

template <Query Q, class Node>
bool traverse(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit* hit, std::vector<MeshBvhHit>* out,
              TraversalEntry* stack) {
  return traverse_inlined<Q, Node>(bvh, ray, hit, out, stack);
}

template <Query Q>
bool traverse_any_format(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit* hit,
                         std::vector<MeshBvhHit>* out, TraversalEntry* stack) {
  return bvh.quantised ? traverse<Q, QuantisedNode>(bvh, ray, hit, out, stack)
                       : traverse<Q, WideNode>(bvh, ray, hit, out, stack);
}

bool closest(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit& hit, TraversalEntry* stack) {
  return traverse_any_format<Query::kNearest>(bvh, ray, &hit, nullptr, stack);
}

bool any(const MeshBvh& bvh, const MeshRay& ray, TraversalEntry* stack) {
  return traverse_any_format<Query::kAny>(bvh, ray, nullptr, nullptr, stack);
}

void every(const MeshBvh& bvh, const MeshRay& ray, std::vector<MeshBvhHit>& out,
           TraversalEntry* stack) {
  traverse_any_format<Query::kAll>(bvh, ray, nullptr, &out, stack);
}

// occluded_if_valid's other trees: quantised nodes, or deeper than the local stack allows (out
// of line, so that occluded_if_valid inlines the walks of float nodes only).
[[gnu::noinline]] inline bool any_with_stack(const MeshBvh& bvh, const MeshRay& ray) {
  return with_traversal_stack(bvh, [&](TraversalEntry* stack) {
    return traverse_any_format<Query::kAny>(bvh, ray, nullptr, nullptr, stack);
  });
}

// The validity check, the conversion, the stack and the walk in one function, called straight
// from Scene::occluded's one-mesh path: a shadow ray pays one call, the check shares the
// conversion's loads and exponent, and the MeshRay reaches prepare in registers (traverse and
// the walks of float nodes inlined here) instead of through memory.
bool occluded_if_valid(const MeshBvh& bvh, const Ray& ray) {
  const RayParts q = ray_parts(ray);
  const int e = direction_exponent(q);
  if (!is_valid(q, e)) [[unlikely]]
    return false;
  double scale;
  const MeshRay r = convert_ray(q, e, scale);
  if (bvh.quantised || traversal_stack_size(bvh) > kLocalTraversalStack) [[unlikely]]
    return any_with_stack(bvh, r);
  TraversalEntry stack[kLocalTraversalStack];  // uninitialised: the walk writes before it reads
  return traverse_inlined<Query::kAny, WideNode, true>(bvh, r, nullptr, nullptr, stack);
}

}  // namespace raycast::RAYCAST_KERNEL_NS
