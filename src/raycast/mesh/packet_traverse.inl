// The packet traversal of up to eight rays (MeshKernels::closest8), written once and compiled once
// per instruction set: a mesh/wide_kernels_<isa>.cpp file includes it right after
// mesh/wide_traverse.inl (same lane type V8, same namespace, and it calls that file's single-ray
// traversal for the rays it does not trace as a packet). The packet's width N is a template
// parameter: 8 lanes (V8) on every ISA, and 16 (V16, mesh/packet_lanes16.inl) where the kernel
// has 512-bit registers (AVX-512: closest16_rays, mesh/mesh_packet16.h).
//
// Inner nodes are tested once for the whole packet, against the interval bounds of its rays
// (least and greatest origin and inverse direction per axis over the active lanes): a child that
// any lane's own slab test would enter passes this test (below), so the packet visits every leaf
// each of its rays would. In a leaf, every lane does the single-ray triangle test on its own ray
// with its own nearest hit so far, so a lane's hit is bit for bit the single ray's (the nearest hit
// is the least t, ties to the least triangle index, whatever the visiting order).

namespace raycast::RAYCAST_KERNEL_NS {

// The lane vector of a packet of N rays and its load, broadcast and store (the arithmetic,
// comparisons, bits and select are overloads on the vector type).
template <int N>
struct PacketLanes;

template <>
struct PacketLanes<8> {
  using V = V8;
  static V load(const float* p) { return load8(p); }
  static V broadcast(float x) { return splat(x); }
  static void store(float* p, V x) { store8(p, x); }
};

}  // namespace raycast::RAYCAST_KERNEL_NS

#ifdef RAYCAST_KERNEL_NODE16
#include "mesh/packet_lanes16.inl"
#endif

namespace raycast::RAYCAST_KERNEL_NS {

// Per-lane constants of the watertight triangle test, and the packet's interval bounds.
template <int N>
struct PacketData {
  using V = typename PacketLanes<N>::V;
  V o[3], inv[3];                // per lane, for the single-ray slab test
  V neg_inv[3], neg_inv_far[3];  // per lane, for the ordered test (intersect_node8_nearest)
  V tmin;
  // Interval bounds per axis: the origin bound that gives the least entry (o_near) and the
  // greatest exit (o_far), the least and greatest 1/d, and which half of an axis's planes
  // ([lo x 8 | hi x 8]) is near and which far: 0 or kNodeWidth, as in the single-ray test.
  V8 o_near[3], o_far[3], inv_lo[3], inv_hi[3];
  int near_off[3], far_off[3];
  V8 tmin_lo;  // least tmin
  // The watertight test's constants, set by prepare_leaves when the packet reaches its first
  // leaf (most packets of primary rays miss the mesh and never do): each lane's, and as lanes
  // when every lane has the same axis permutation (`shared`).
  bool leaves_ready = false, shared = false;
  alignas(64) float lane_s[3][N], lane_ok[3][N];
  int kx, ky, kz;
  V sx, sy, sz, okx, oky, okz;
  // Each lane's constants as the single-ray leaf test reads them (only the triangle test's
  // members are set): leaf_by_lane passes them by reference, so the test reads its broadcasts
  // from here instead of a copy spilled to the stack for every lane of every leaf.
  RayData lane_ray[N];
};

// A packet's rays as lanes: ox, oy, oz, dx, dy, dz, tmin, tmax, each of N lanes (idle lanes
// hold a copy of an active ray).
template <int N>
struct PacketRays {
  alignas(64) float f[8][N];
  MeshRay ray(int l) const {
    return MeshRay{Vec3f{f[0][l], f[1][l], f[2][l]}, Vec3f{f[3][l], f[4][l], f[5][l]}, f[6][l],
                   f[7][l]};
  }
};

// The rays of `mask` as lanes; idle lanes copy the first active ray, so the bounds over all eight
// lanes are those over the active ones.
inline void gather_rays(const MeshRay* rays, int mask, PacketRays<8>& pr) {
  const int first = __builtin_ctz(mask);
  for (int l = 0; l < 8; ++l) {
    const MeshRay& r = rays[(mask >> l & 1) ? l : first];
    pr.f[0][l] = r.o.x, pr.f[1][l] = r.o.y, pr.f[2][l] = r.o.z;
    pr.f[3][l] = r.d.x, pr.f[4][l] = r.d.y, pr.f[5][l] = r.d.z;
    pr.f[6][l] = r.tmin, pr.f[7][l] = r.tmax;
  }
}

// mesh.cpp's to_mesh_ray on the N lanes at once (the same operations, so the same bits), for
// the rays of `mask` (idle lanes copy the first active one): false, with nothing converted, when a
// lane's largest |direction component| has an exponent outside to_mesh_ray's fast range (NaN and
// infinite directions included; the caller converts those rays one by one). GCC vector types of
// four lanes, so each instruction set's file compiles it to its own instructions (kept inside
// this one function, with __builtin_bit_cast, so that no function passes or returns one: -Wpsabi);
// only operations AVX2 has on 256 bits, so that GCC does not split them into scalars.
template <int N>
inline bool convert_rays(const Ray* rays, int mask, PacketRays<N>& pr, double* scale) {
  using D4 = double __attribute__((vector_size(32)));
  using I64x4 = std::int64_t __attribute__((vector_size(32)));
  using F4 = float __attribute__((vector_size(16)));
  using I32x4 = std::int32_t __attribute__((vector_size(16)));
  using U32x4 = std::uint32_t __attribute__((vector_size(16)));
  static_assert(sizeof(Ray) == 8 * sizeof(double), "a Ray is o, d, tmin, tmax: eight doubles");
  const int first = __builtin_ctz(mask);
  I64x4 out_of_range = {};
  for (int h = 0; h < N; h += 4) {
    // Lanes h..h+3 as rows (ox oy oz dx | dy dz tmin tmax), transposed into v[0..7] by two 4x4
    // shuffles.
    // The row pointers first, then the eight loads straight into named vectors (loads into an
    // array in the same loop went through the stack: ~18M of the conversion's 61M instructions).
    const double* row[4];
    for (int j = 0; j < 4; ++j) row[j] = &rays[(mask >> (h + j) & 1) ? h + j : first].o.x;
    D4 a0, a1, a2, a3, b0, b1, b2, b3;
    std::memcpy(&a0, row[0], sizeof(D4));
    std::memcpy(&a1, row[1], sizeof(D4));
    std::memcpy(&a2, row[2], sizeof(D4));
    std::memcpy(&a3, row[3], sizeof(D4));
    std::memcpy(&b0, row[0] + 4, sizeof(D4));
    std::memcpy(&b1, row[1] + 4, sizeof(D4));
    std::memcpy(&b2, row[2] + 4, sizeof(D4));
    std::memcpy(&b3, row[3] + 4, sizeof(D4));
    const D4 a[4] = {a0, a1, a2, a3}, b[4] = {b0, b1, b2, b3};
    D4 v[8];
    for (int k = 0; k < 8; k += 4) {
      const D4* m = k ? b : a;
      const D4 t0 = __builtin_shufflevector(m[0], m[1], 0, 4, 2, 6);
      const D4 t1 = __builtin_shufflevector(m[0], m[1], 1, 5, 3, 7);
      const D4 t2 = __builtin_shufflevector(m[2], m[3], 0, 4, 2, 6);
      const D4 t3 = __builtin_shufflevector(m[2], m[3], 1, 5, 3, 7);
      v[k] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
      v[k + 1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
      v[k + 2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
      v[k + 3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
    }
    // The biased exponent E of max(|dx|, |dy|, |dz|) is the greatest of the components' (the
    // exponent field grows with the magnitude); to_mesh_ray's fast range -1022 < e < 1022 is
    // 2 <= E <= 2044.
    const I64x4 ex = (__builtin_bit_cast(I64x4, v[3]) >> 52) & 0x7FF;
    const I64x4 ey = (__builtin_bit_cast(I64x4, v[4]) >> 52) & 0x7FF;
    const I64x4 ez = (__builtin_bit_cast(I64x4, v[5]) >> 52) & 0x7FF;
    const I64x4 exy = ex > ey ? ex : ey;
    const I64x4 e = exy > ez ? exy : ez;
    out_of_range |= (e < 2) | (e > 2044);
    const D4 sc = __builtin_bit_cast(D4, (2046 - e) << 52);  // 2^-e
    const D4 inv = __builtin_bit_cast(D4, e << 52);          // 2^e
    F4 out[8];
    for (int k = 0; k < 3; ++k) {
      out[k] = __builtin_convertvector(v[k], F4);
      out[3 + k] = __builtin_convertvector(v[3 + k] * sc, F4);
    }
    // round_down(tmin * inv) and round_up(tmax * inv): the nearest float, moved one step down
    // (up) when it lies above (below) the double; zero steps to the least subnormal of that
    // side. The double comparisons become float lanes through a conversion of -1 or 0.
    const D4 lo = v[6] * inv, hi = v[7] * inv;
    const F4 flo = __builtin_convertvector(lo, F4), fhi = __builtin_convertvector(hi, F4);
    const D4 minus_one = D4{} - 1;
    const F4 below_f =
        __builtin_convertvector(__builtin_convertvector(flo, D4) > lo ? minus_one : D4{}, F4);
    const F4 above_f =
        __builtin_convertvector(__builtin_convertvector(fhi, D4) < hi ? minus_one : D4{}, F4);
    const I32x4 below = below_f < 0, above = above_f < 0;
    const U32x4 ulo = __builtin_bit_cast(U32x4, flo), uhi = __builtin_bit_cast(U32x4, fhi);
    const I32x4 zero_lo = (ulo & 0x7FFFFFFFu) == 0, zero_hi = (uhi & 0x7FFFFFFFu) == 0;
    const I32x4 neg_lo = __builtin_bit_cast(I32x4, ulo) < 0;
    const I32x4 neg_hi = __builtin_bit_cast(I32x4, uhi) < 0;
    const U32x4 lo_down = zero_lo ? U32x4{} + 0x80000001u : (neg_lo ? ulo + 1 : ulo - 1);
    const U32x4 hi_up = zero_hi ? U32x4{} + 1u : (neg_hi ? uhi - 1 : uhi + 1);
    out[6] = __builtin_bit_cast(F4, below ? lo_down : ulo);
    out[7] = __builtin_bit_cast(F4, above ? hi_up : uhi);
    for (int k = 0; k < 8; ++k) std::memcpy(&pr.f[k][h], &out[k], sizeof(F4));
    std::memcpy(scale + h, &sc, sizeof sc);
  }
  return !(out_of_range[0] | out_of_range[1] | out_of_range[2] | out_of_range[3]);
}

// The least and greatest of eight floats (finite: prepare_packet checks), by halving shuffles on
// a GCC vector type (native lanes on every ISA; inside one function, so no vector crosses a call:
// -Wpsabi). Replaces a scalar loop of 16 min/max per axis.
inline void min_max8(const float* x, float& lo, float& hi) {
  using F8v = float __attribute__((vector_size(32)));
  F8v v;
  std::memcpy(&v, x, sizeof v);
  F8v a = v, b = v;
  F8v s = __builtin_shufflevector(a, a, 4, 5, 6, 7, 0, 1, 2, 3);
  a = s < a ? s : a;
  b = s > b ? s : b;
  s = __builtin_shufflevector(a, a, 2, 3, 0, 1, 6, 7, 4, 5);
  a = s < a ? s : a;
  s = __builtin_shufflevector(b, b, 2, 3, 0, 1, 6, 7, 4, 5);
  b = s > b ? s : b;
  s = __builtin_shufflevector(a, a, 1, 0, 3, 2, 5, 4, 7, 6);
  a = s < a ? s : a;
  s = __builtin_shufflevector(b, b, 1, 0, 3, 2, 5, 4, 7, 6);
  b = s > b ? s : b;
  lo = a[0];
  hi = b[0];
}

// The greatest of x[l] over the lanes l of `lanes` (not empty), as min_max8 does it.
inline float lanes_max8(const float* x, int lanes) {
  using F8v = float __attribute__((vector_size(32)));
  using I8v = std::int32_t __attribute__((vector_size(32)));
  F8v v;
  std::memcpy(&v, x, sizeof v);
  const I8v bit = {1, 2, 4, 8, 16, 32, 64, 128};
  v = (bit & lanes) != 0 ? v : F8v{} - kInfinityF;
  F8v s = __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3);
  v = s > v ? s : v;
  s = __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5);
  v = s > v ? s : v;
  s = __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6);
  v = s > v ? s : v;
  return v[0];
}

// min_max8 and lanes_max8 over the N lanes.
template <int N>
inline void min_max_lanes(const float* x, float& lo, float& hi) {
  min_max8(x, lo, hi);
  if constexpr (N == 16) {
    float lo2, hi2;
    min_max8(x + 8, lo2, hi2);
    lo = std::min(lo, lo2);
    hi = std::max(hi, hi2);
  }
}

template <int N>
inline float lanes_max(const float* x, int lanes) {
  if constexpr (N == 16) {
    const int lo = lanes & 0xFF, hi = lanes >> 8;
    if (!lo) return lanes_max8(x + 8, hi);
    if (!hi) return lanes_max8(x, lo);
    return std::max(lanes_max8(x, lo), lanes_max8(x + 8, hi));
  }
  return lanes_max8(x, lanes);
}

// Fills `p` for the lanes of `pr` (idle lanes hold an active ray); false when they cannot go as
// one packet: a direction sign that differs between lanes, or a ray that is not finite.
template <int N>
inline bool prepare_packet(const PacketRays<N>& pr, PacketData<N>& p) {
  using L = PacketLanes<N>;
  using V = typename L::V;
  constexpr int kAll = (1 << N) - 1;
  const auto& f = pr.f;
  const V zero = L::broadcast(0.0f);
  int finite =
      bits(cmp_eq(L::load(f[6]), L::load(f[6]))) & bits(cmp_eq(L::load(f[7]), L::load(f[7])));
  for (int k = 0; k < 6; ++k) finite &= bits(cmp_eq(L::load(f[k]) - L::load(f[k]), zero));
  if (finite != kAll) return false;
  for (int a = 0; a < 3; ++a) {
    // A zero or tiny component (prepare's 1/d = +-infinity or the clamp) goes one ray at a time:
    // the interval bounds below assume finite reciprocals of one sign.
    const V d = L::load(f[3 + a]);
    const int small = ~(bits(cmp_ge(d, L::broadcast(kMinDirection))) |
                        bits(cmp_le(d, L::broadcast(-kMinDirection)))) &
                      kAll;
    if (small) return false;
    p.o[a] = L::load(f[a]);
    p.inv[a] = L::broadcast(1.0f) / d;             // as the single-ray test computes it
    p.neg_inv[a] = L::broadcast(0.0f) - p.inv[a];  // -inv exactly (inv is not zero)
    p.neg_inv_far[a] = p.neg_inv[a] * L::broadcast(kFarWiden);
    alignas(64) float inv[N];
    L::store(inv, p.inv[a]);
    float olo, ohi, ilo, ihi;
    min_max_lanes<N>(f[a], olo, ohi);
    min_max_lanes<N>(inv, ilo, ihi);
    if ((ilo < 0) != (ihi < 0)) return false;  // lanes disagree on the near plane
    const bool positive = ilo >= 0;
    // Entry (plane - o) * inv is least for the greatest origin when 1/d > 0, the least origin
    // when 1/d < 0; the exit is greatest for the opposite bound.
    p.o_near[a] = splat(positive ? ohi : olo);
    p.o_far[a] = splat(positive ? olo : ohi);
    p.inv_lo[a] = splat(ilo);
    p.inv_hi[a] = splat(ihi);
    p.near_off[a] = positive ? 0 : kNodeWidth;
    p.far_off[a] = positive ? kNodeWidth : 0;
  }
  float tmin_lo, tmin_hi;
  min_max_lanes<N>(f[6], tmin_lo, tmin_hi);
  p.tmin_lo = splat(tmin_lo);
  p.tmin = L::load(f[6]);
  return true;
}

// The watertight test's constants of every lane (idle lanes copy an active ray).
template <int N>
inline void prepare_leaves(const PacketRays<N>& pr, PacketData<N>& p) {
  using L = PacketLanes<N>;
  p.shared = true;
  for (int l = 0; l < N; ++l) {
    const MeshRay r = pr.ray(l);
    const float* ro = &r.o.x;
    const WatertightRay w = make_watertight_ray(r.o, r.d);
    // Every lane's axis permutation the same as lane 0's (lane_ray[0] is set first).
    const RayData& first = p.lane_ray[0];
    p.shared = p.shared && (l == 0 || (w.kx == first.kx && w.ky == first.ky && w.kz == first.kz));
    p.lane_s[0][l] = w.sx;
    p.lane_s[1][l] = w.sy;
    p.lane_s[2][l] = w.sz;
    p.lane_ok[0][l] = ro[w.kx];
    p.lane_ok[1][l] = ro[w.ky];
    p.lane_ok[2][l] = ro[w.kz];
    RayData& lr = p.lane_ray[l];
    lr.kx = w.kx;
    lr.ky = w.ky;
    lr.kz = w.kz;
    lr.sx = splat(w.sx);
    lr.sy = splat(w.sy);
    lr.sz = splat(w.sz);
    lr.okx = splat(ro[w.kx]);
    lr.oky = splat(ro[w.ky]);
    lr.okz = splat(ro[w.kz]);
    lr.tmin = splat(r.tmin);
  }
  p.kx = p.lane_ray[0].kx;
  p.ky = p.lane_ray[0].ky;
  p.kz = p.lane_ray[0].kz;
  p.sx = L::load(p.lane_s[0]), p.sy = L::load(p.lane_s[1]), p.sz = L::load(p.lane_s[2]);
  p.okx = L::load(p.lane_ok[0]), p.oky = L::load(p.lane_ok[1]), p.okz = L::load(p.lane_ok[2]);
  p.leaves_ready = true;
}

// The packet's slab test of the eight children: the children that some lane may enter before
// `reach` (the greatest nearest hit so far over the lanes), and a lower bound of every lane's
// entry distance. Conservative with rounding: a lane's entry is round(round(plane - o) * inv),
// and rounding is monotonic, so putting the interval's extreme origin in the subtraction and
// taking the least of the two products with the extreme inverses (the product is monotonic in
// 1/d, whose sign all lanes share) bounds it from below; the exit likewise from above, and the
// widening of the exit is monotonic too.
// The near and far planes of a node's children (near: the plane a ray with the
// packet's direction signs enters by), kept for the per-lane tests.
struct NodePlanes {
  alignas(32) float near[3][8];
  alignas(32) float far[3][8];
};

// The near and far planes of axis a of a node's eight children, as every node test reads them:
// float nodes directly, quantised nodes dequantised (origin + q * scale).
template <class PD>
inline void node_planes(const WideNode& n, int a, const PD& p, V8& pn, V8& pf) {
  pn = load8(n.box[a] + p.near_off[a]);
  pf = load8(n.box[a] + p.far_off[a]);
}

template <class PD>
inline void node_planes(const QuantisedNode& n, int a, const PD& p, V8& pn, V8& pf) {
  const V8 s = splat(node_scale(n.exponent[a])), o = splat(n.origin[a]);
  pn = o + load8_u8(n.q[2 * a + p.near_off[a] / kNodeWidth]) * s;
  pf = o + load8_u8(n.q[2 * a + p.far_off[a] / kNodeWidth]) * s;
}

// The exit's widening of packet_node: float nodes' lanes take the ordered test
// (intersect_node8_nearest), whose exit fl(fl(o - plane) * fl(-1/d * kFarWiden)) is at most the
// lane's float exit fl(fl(plane - o) * fl(1/d)) times (1 + 16u)(1 + u)^2 / (1 - u), and whose
// tmax is fl(tmax * kFarWiden) <= tmax (1 + 16u)(1 + u): both below fl(x * kPacketWiden) >=
// x (1 + 32u)(1 - u) for the bound x >= the lane's float exit (and >= tmax). Quantised nodes' lanes
// take the float test (kSlabWiden).
constexpr float kPacketWiden = 1.0f + 0x1p-19f;
constexpr float kPacketNarrow = 1.0f - 0x1p-19f;

template <class Node, class PD>
inline int packet_node(const Node& n, const PD& p, V8 reach, V8& tnear, NodePlanes& planes) {
  V8 near[3], far[3];
  for (int a = 0; a < 3; ++a) {
    V8 pn, pf;
    node_planes(n, a, p, pn, pf);
    store8(planes.near[a], pn);
    store8(planes.far[a], pf);
    const V8 dn = pn - p.o_near[a];
    const V8 df = pf - p.o_far[a];
    near[a] = vmin(dn * p.inv_lo[a], dn * p.inv_hi[a]);
    far[a] = vmax(df * p.inv_lo[a], df * p.inv_hi[a]);
  }
  tnear = vmax(vmax(near[0], near[1]), vmax(near[2], p.tmin_lo));
  // The exit and `reach` widened as one, as in the single-ray test.
  const V8 f = vmin(vmin(far[0], far[1]), vmin(far[2], reach));
  constexpr bool kOrderedLanes = std::is_same_v<Node, WideNode>;
  const V8 widen = select(cmp_ge(f, splat(0.0f)), splat(kOrderedLanes ? kPacketWiden : kSlabWiden),
                          splat(kOrderedLanes ? kPacketNarrow : kSlabNarrow));
  return bits(cmp_le(tnear, f * widen)) & n.used;
}

// Child c of a node against every lane: the single-ray slab test of that child, lane by lane, on
// the planes packet_node read (node_planes: as every node test reads them). All lanes
// share the direction signs, so the near plane is the same for every lane. Float nodes: the
// ordered test of the single-ray nearest walk (intersect_node8_nearest; closest_format checks that
// every lane is an ordered ray), the same operations lane by lane.
template <bool Ordered, int N>
inline int packet_child(const NodePlanes& n, int c, const PacketData<N>& p,
                        typename PacketLanes<N>::V tmax) {
  using L = PacketLanes<N>;
  using V = typename L::V;
  V near[3], far[3];
  if constexpr (Ordered) {
    for (int a = 0; a < 3; ++a) {
      near[a] = (p.o[a] - L::broadcast(n.near[a][c])) * p.neg_inv[a];
      far[a] = (p.o[a] - L::broadcast(n.far[a][c])) * p.neg_inv_far[a];
    }
    const V tnear = vmax_bits(vmax_bits(near[0], near[1]), vmax_bits(near[2], p.tmin));
    const V tfar =
        vmin_bits(vmin_bits(far[0], far[1]), vmin_bits(far[2], tmax * L::broadcast(kFarWiden)));
    return bits(cmp_le(tnear, tfar));
  }
  for (int a = 0; a < 3; ++a) {
    near[a] = (L::broadcast(n.near[a][c]) - p.o[a]) * p.inv[a];
    far[a] = (L::broadcast(n.far[a][c]) - p.o[a]) * p.inv[a];
  }
  const V tnear = vmax(vmax(near[0], near[1]), vmax(near[2], p.tmin));
  const V f = vmin(vmin(far[0], far[1]), vmin(far[2], tmax));
  const V widen =
      select(cmp_ge(f, L::broadcast(0.0f)), L::broadcast(kSlabWiden), L::broadcast(kSlabNarrow));
  return bits(cmp_le(tnear, f * widen));
}

// Triangle `lane` of group g against every lane's ray: the watertight test of intersect_pair.
template <int N, class V = typename PacketLanes<N>::V>
inline int packet_triangle(const TriangleGroup& g, int lane, const PacketData<N>& p, V tmax, V& t,
                           V& v, V& w, V& det) {
  using L = PacketLanes<N>;
  const V a_kz = L::broadcast(g.v[0][p.kz][lane]) - p.okz;
  const V b_kz = L::broadcast(g.v[1][p.kz][lane]) - p.okz;
  const V c_kz = L::broadcast(g.v[2][p.kz][lane]) - p.okz;
  const V ax = (L::broadcast(g.v[0][p.kx][lane]) - p.okx) - p.sx * a_kz;
  const V ay = (L::broadcast(g.v[0][p.ky][lane]) - p.oky) - p.sy * a_kz;
  const V bx = (L::broadcast(g.v[1][p.kx][lane]) - p.okx) - p.sx * b_kz;
  const V by = (L::broadcast(g.v[1][p.ky][lane]) - p.oky) - p.sy * b_kz;
  const V cx = (L::broadcast(g.v[2][p.kx][lane]) - p.okx) - p.sx * c_kz;
  const V cy = (L::broadcast(g.v[2][p.ky][lane]) - p.oky) - p.sy * c_kz;
  V u = cx * by - cy * bx;
  v = ax * cy - ay * cx;
  w = bx * ay - by * ax;
  const V zero = L::broadcast(0.0f);
  const int zero_mask = bits(mor(mor(cmp_eq(u, zero), cmp_eq(v, zero)), cmp_eq(w, zero)));
  if (zero_mask) {
    alignas(64) float f[6][N], uu[N], vv[N], ww[N];
    L::store(f[0], ax), L::store(f[1], ay), L::store(f[2], bx);
    L::store(f[3], by), L::store(f[4], cx), L::store(f[5], cy);
    L::store(uu, u), L::store(vv, v), L::store(ww, w);
    for (int l = 0; l < N; ++l) {
      if (!(zero_mask >> l & 1)) continue;
      const double dax = f[0][l], day = f[1][l], dbx = f[2][l], dby = f[3][l], dcx = f[4][l],
                   dcy = f[5][l];
      uu[l] = static_cast<float>(dcx * dby - dcy * dbx);
      vv[l] = static_cast<float>(dax * dcy - day * dcx);
      ww[l] = static_cast<float>(dbx * day - dby * dax);
    }
    u = L::load(uu);
    v = L::load(vv);
    w = L::load(ww);
  }
  const auto pos = mand(mand(cmp_ge(u, zero), cmp_ge(v, zero)), cmp_ge(w, zero));
  const auto neg = mand(mand(cmp_le(u, zero), cmp_le(v, zero)), cmp_le(w, zero));
  det = (u + v) + w;
  const auto same_sign = mand(mor(pos, neg), cmp_ne(det, zero));
  if (!bits(same_sign)) return 0;
  const V az = p.sz * a_kz, bz = p.sz * b_kz, cz = p.sz * c_kz;
  const V ts = (u * az + v * bz) + w * cz;
  t = ts / det;
  return bits(mand(same_sign, mand(cmp_ge(t, p.tmin), cmp_le(t, tmax))));
}

// Keeps a lane's hit when it is nearer than its nearest so far, or as near with a smaller
// triangle index (the single-ray rule).
inline void keep_hit(int l, const MeshBvhHit& h, float* tmax_s, MeshBvhHit* hits, int& found) {
  if (h.t < tmax_s[l] ||
      (h.t == tmax_s[l] && (!(found >> l & 1) || h.triangle < hits[l].triangle))) {
    tmax_s[l] = h.t;
    hits[l] = h;
    found |= 1 << l;
  }
}

// A leaf's triangles one at a time against the lanes (the better order when many lanes enter
// it; the lanes must share the axis permutation).
template <int N>
inline void leaf_by_triangle(const MeshBvh& bvh, std::uint32_t first, std::uint32_t end,
                             const PacketData<N>& p, int lanes, float* tmax_s, MeshBvhHit* hits,
                             int& found) {
  using L = PacketLanes<N>;
  for (std::uint32_t gi = first; gi < end; ++gi) {
    const TriangleGroup& g = bvh.groups[gi];
    for (int k = 0; k < 4; ++k) {
      if (g.id[k] == kNoTriangle) continue;
      typename L::V t, v, w, det;
      int m = packet_triangle<N>(g, k, p, L::load(tmax_s), t, v, w, det) & lanes;
      if (!m) continue;
      alignas(64) float tl[N], vl[N], wl[N], dl[N];
      L::store(tl, t), L::store(vl, v), L::store(wl, w), L::store(dl, det);
      while (m) {
        const int l = __builtin_ctz(m);
        m &= m - 1;
        keep_hit(l,
                 MeshBvhHit{tl[l], vl[l] / dl[l], wl[l] / dl[l], g.id[k], g.source[k], gi,
                            static_cast<std::uint32_t>(k)},
                 tmax_s, hits, found);
      }
    }
  }
}

// A leaf's groups two at a time against one lane after another: the single-ray leaf test (the
// better order when few lanes enter the leaf).
template <int N>
inline void leaf_by_lane(const MeshBvh& bvh, std::uint32_t first, std::uint32_t end,
                         const PacketData<N>& p, int lanes, float* tmax_s, MeshBvhHit* hits,
                         int& found) {
  PairResult res;
  for (; lanes; lanes &= lanes - 1) {
    const int l = __builtin_ctz(lanes);
    const RayData& r = p.lane_ray[l];
    for (std::uint32_t gi = first; gi < end; gi += 2) {
      const TriangleGroup& g1 = gi + 1 < end ? bvh.groups[gi + 1] : kEmptyTriangleGroup;
      int m = intersect_pair(bvh.groups[gi], g1, r, splat(tmax_s[l]), res);
      while (m) {
        const int i = __builtin_ctz(m);
        m &= m - 1;
        const std::uint32_t g = gi + (i >> 2);
        keep_hit(l,
                 MeshBvhHit{res.t[i], res.v[i] / res.det[i], res.w[i] / res.det[i],
                            bvh.groups[g].id[i & 3], bvh.groups[g].source[i & 3], g,
                            static_cast<std::uint32_t>(i & 3)},
                 tmax_s, hits, found);
      }
    }
  }
}

// Whether the rays of `mask` are all ordered rays (ordered_ray; prepare_packet checked the rest).
template <int N>
inline bool ordered_lanes(const PacketRays<N>& pr, int mask) {
  for (int l = 0; l < N; ++l)
    if ((mask >> l & 1) && !ordered_ray(pr.ray(l))) return false;
  return true;
}

// The nearest hit of each ray of `mask` (lane l of `pr` for each bit l); returns the lanes that
// hit.
template <class Node, int N>
int closest_format(const MeshBvh& bvh, const PacketRays<N>& pr, int mask, MeshBvhHit* hits,
                   PacketEntry* stack, TraversalEntry* single_stack) {
  using L = PacketLanes<N>;
  PacketData<N> p;
  // Not one packet (or, on float nodes, a lane the ordered test does not admit): one ray at a time.
  if (!prepare_packet(pr, p) || (std::is_same_v<Node, WideNode> && !ordered_lanes(pr, mask))) {
    int found = 0;
    for (int l = 0; l < N; ++l) {
      if (!(mask >> l & 1)) continue;
      const MeshRay r = pr.ray(l);
      if (traverse<Query::kNearest, Node>(bvh, r, &hits[l], nullptr, single_stack)) found |= 1 << l;
    }
    return found;
  }
  alignas(64) float tmax_s[N];
  for (int l = 0; l < N; ++l) tmax_s[l] = (mask >> l & 1) ? pr.f[7][l] : -kInfinityF;
  typename L::V tmax = L::load(tmax_s);
  // Each lane's tmax widened as the node tests widen it: the pop's bound (a tied triangle's box
  // may round its entry a few ulps above the lane's nearest hit).
  const auto widen = [](typename L::V t) {
    return vmax(t * L::broadcast(kSlabWiden), t * L::broadcast(kSlabNarrow));
  };
  typename L::V reach = widen(tmax);
  int found = 0;
  int top = 0;
  std::uint32_t ref = bvh.root;
  int lanes = mask;
  for (;;) {
    if (!(ref & kLeafBit)) {
      const Node& node = node_array<Node>(bvh)[ref];
      const float reach_s = lanes_max<N>(tmax_s, lanes);
      V8 tn;
      NodePlanes planes;
      int m = packet_node(node, p, splat(reach_s), tn, planes);
      if (m) {
        // The lanes of each child the packet may enter, nearest child (by the packet's bound)
        // popped first.
        alignas(32) float tnl[8];
        store8(tnl, tn);
        const int base = top;
        while (m) {
          const int c = __builtin_ctz(m);
          m &= m - 1;
          const int lm =
              packet_child<std::is_same_v<Node, WideNode>, N>(planes, c, p, tmax) & lanes;
          if (!lm) continue;
          prefetch_children(bvh, node, 1 << c);
          const PacketEntry e{node.child[c], tnl[c], static_cast<std::uint32_t>(lm)};
          int j = top++;
          while (j > base && stack[j - 1].tnear < e.tnear) {
            stack[j] = stack[j - 1];
            --j;
          }
          stack[j] = e;
        }
        // The nearest child at once: a fresh entry's lanes all pass the pop's test (the
        // packet's entry bound is below each lane's entry, which is before its nearest hit).
        if (top > base) {
          const PacketEntry& e = stack[--top];
          ref = e.ref;
          lanes = static_cast<int>(e.lanes);
          continue;
        }
      }
    } else {
      const std::uint32_t first = leaf_first(ref), end = first + leaf_groups(ref);
      if (!p.leaves_ready) prepare_leaves(pr, p);
      // By lane (one pass of up to 8 triangles per lane) unless the lanes are many: k lanes
      // by lane cost k * pairs passes, by triangle 4 * groups tests of N lanes each. The factor
      // N / 2 (4 for 8 lanes, 8 for 16: a 16-lane test is two 256-bit halves on this Zen 4)
      // is the faster of 16 lanes against 4 (`raycast bench --packets` on the 1M sphere).
      if (!p.shared ||
          __builtin_popcount(lanes) * int((end - first + 1) / 2) < (N / 2) * int(end - first)) {
        leaf_by_lane<N>(bvh, first, end, p, lanes, tmax_s, hits, found);
      } else {
        leaf_by_triangle<N>(bvh, first, end, p, lanes, tmax_s, hits, found);
      }
      tmax = L::load(tmax_s);
      reach = widen(tmax);
    }
    // Pop; an entry keeps the lanes whose nearest hit so far is not before its entry bound.
    for (;;) {
      if (top == 0) return found;
      const PacketEntry& e = stack[--top];
      lanes = bits(cmp_ge(reach, L::broadcast(e.tnear))) & static_cast<int>(e.lanes);
      if (lanes) {
        ref = e.ref;
        break;
      }
    }
  }
}

template <int N>
inline int closest_lanes(const MeshBvh& bvh, const PacketRays<N>& pr, int mask, MeshBvhHit* hits,
                         PacketEntry* stack, TraversalEntry* single_stack) {
  return bvh.quantised ? closest_format<QuantisedNode, N>(bvh, pr, mask, hits, stack, single_stack)
                       : closest_format<WideNode, N>(bvh, pr, mask, hits, stack, single_stack);
}

int closest8(const MeshBvh& bvh, const MeshRay* rays, int mask, MeshBvhHit* hits,
             PacketEntry* stack, TraversalEntry* single_stack) {
  mask &= 0xFF;
  if (bvh.empty() || !mask) return 0;
  PacketRays<8> pr;
  gather_rays(rays, mask, pr);
  return closest_lanes<8>(bvh, pr, mask, hits, stack, single_stack);
}

int closest8_rays(const MeshBvh& bvh, const Ray* rays, int mask, MeshBvhHit* hits, double* scale,
                  PacketEntry* stack, TraversalEntry* single_stack) {
  mask &= 0xFF;
  if (!mask) return 0;
  PacketRays<8> pr;
  if (!convert_rays<8>(rays, mask, pr, scale)) return -1;
  if (bvh.empty()) return 0;
  return closest_lanes<8>(bvh, pr, mask, hits, stack, single_stack);
}

#ifdef RAYCAST_KERNEL_NODE16
// closest8_rays on sixteen rays as one packet (mesh/mesh_packet16.cpp declares it).
int closest16_rays(const MeshBvh& bvh, const Ray* rays, int mask, MeshBvhHit* hits, double* scale,
                   PacketEntry* stack, TraversalEntry* single_stack) {
  mask &= 0xFFFF;
  if (!mask) return 0;
  PacketRays<16> pr;
  if (!convert_rays<16>(rays, mask, pr, scale)) return -1;
  if (bvh.empty()) return 0;
  return closest_lanes<16>(bvh, pr, mask, hits, stack, single_stack);
}
#endif

}  // namespace raycast::RAYCAST_KERNEL_NS
