// The AVX-512 mesh kernels: eight lanes in one 256-bit register with AVX-512VL, comparisons into
// mask registers (32 vector registers, no movemask).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "mesh/mesh_ray.h"
#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

#if defined(__x86_64__)
#include <immintrin.h>

// Everything below (and nothing in the headers above) is compiled for AVX-512 (F, VL, DQ, BW).
// No FMA contraction: the build is ISO C++ (-ffp-contract=off).
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq,avx512bw,avx2,fma,bmi,bmi2,popcnt")
// GCC 12's 512-bit intrinsics start from _mm512_undefined_ps(), which -Wmaybe-uninitialized
// reports inside the header (a known false positive).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

namespace raycast::kernels_avx512 {

struct V8 {
  __m256 v;
};
using M8 = __mmask8;

inline V8 load8(const float* p) { return {_mm256_load_ps(p)}; }
inline V8 load8_u8(const std::uint8_t* p) {
  return {_mm256_cvtepi32_ps(
      _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p))))};
}
inline V8 load44(const float* a, const float* b) {
  return {_mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(a)), _mm_load_ps(b), 1)};
}
inline V8 splat(float x) { return {_mm256_set1_ps(x)}; }
inline void store8(float* p, V8 x) { _mm256_store_ps(p, x.v); }
inline V8 operator+(V8 x, V8 y) { return {_mm256_add_ps(x.v, y.v)}; }
inline V8 operator-(V8 x, V8 y) { return {_mm256_sub_ps(x.v, y.v)}; }
inline V8 operator*(V8 x, V8 y) { return {_mm256_mul_ps(x.v, y.v)}; }
inline V8 operator/(V8 x, V8 y) { return {_mm256_div_ps(x.v, y.v)}; }
inline V8 vmin(V8 x, V8 y) { return {_mm256_min_ps(x.v, y.v)}; }
inline V8 vmax(V8 x, V8 y) { return {_mm256_max_ps(x.v, y.v)}; }
inline M8 cmp_le(V8 x, V8 y) { return _mm256_cmp_ps_mask(x.v, y.v, _CMP_LE_OQ); }
inline M8 cmp_ge(V8 x, V8 y) { return _mm256_cmp_ps_mask(x.v, y.v, _CMP_GE_OQ); }
inline M8 cmp_eq(V8 x, V8 y) { return _mm256_cmp_ps_mask(x.v, y.v, _CMP_EQ_OQ); }
inline M8 cmp_ne(V8 x, V8 y) { return _mm256_cmp_ps_mask(x.v, y.v, _CMP_NEQ_UQ); }
inline M8 mand(M8 x, M8 y) { return x & y; }
inline M8 mor(M8 x, M8 y) { return x | y; }
inline int bits(M8 m) { return m; }
inline V8 select(M8 m, V8 x, V8 y) { return {_mm256_mask_blend_ps(m, y.v, x.v)}; }
// Integer max / min of the float bits (RAYCAST_KERNEL_BITS_MINMAX in mesh/wide_traverse.inl).
inline V8 vmax_bits(V8 x, V8 y) {
  return {
      _mm256_castsi256_ps(_mm256_max_epi32(_mm256_castps_si256(x.v), _mm256_castps_si256(y.v)))};
}
inline V8 vmin_bits(V8 x, V8 y) {
  return {
      _mm256_castsi256_ps(_mm256_min_epi32(_mm256_castps_si256(x.v), _mm256_castps_si256(y.v)))};
}

// The node test on 16 lanes (RAYCAST_KERNEL_NODE16 in mesh/wide_traverse.inl): one axis's
// sixteen planes [lo x 8 | hi x 8] per register, so a node is three loads (and, quantised, three
// dequantisations) instead of six. The lane
// operations and their operand order are those of the generic test (far distances negated, which
// commutes with IEEE rounding and with min/max), so the hits stay bit for bit those of the other
// ISAs.
struct NodeRay16 {
  __m512 o[3];      // [o_lo x 8 | o_hi x 8]: the origin as the lo and hi rows subtract it (prepare)
  __m512 mul[3];    // [1/d x 8 | -1/d x 8]
  __m512i perm[3];  // puts the near planes in lanes 0-7: the halves swapped when 1/d < 0
};

inline void prepare_node16(const float* o_lo, const float* o_hi, const float* inv, NodeRay16& r) {
  const __m512i same = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i swap = _mm512_setr_epi32(8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3, 4, 5, 6, 7);
  for (int a = 0; a < 3; ++a) {
    r.o[a] = _mm512_insertf32x8(_mm512_set1_ps(o_lo[a]), _mm256_set1_ps(o_hi[a]), 1);
    r.mul[a] = _mm512_insertf32x8(_mm512_set1_ps(inv[a]), _mm256_set1_ps(-inv[a]), 1);
    r.perm[a] = inv[a] >= 0 ? same : swap;
  }
}

// One axis's sixteen planes [lo x 8 | hi x 8]: as stored, or dequantised.
inline __m512 axis_planes16(const WideNode& n, int a) { return _mm512_load_ps(n.box[a]); }
inline __m512 axis_planes16(const QuantisedNode& n, int a) {
  const __m512 q = _mm512_cvtepi32_ps(
      _mm512_cvtepu8_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(n.q[2 * a]))));
  return _mm512_add_ps(_mm512_set1_ps(n.origin[a]),
                       _mm512_mul_ps(q, _mm512_set1_ps(node_scale(n.exponent[a]))));
}

// (plane - o) * (+-1/d) of one axis's sixteen planes, near planes in lanes 0-7.
template <class Node>
inline __m512 axis_distances16(const Node& n, const NodeRay16& r, int a) {
  const __m512 plane = axis_planes16(n, a);
  return _mm512_mul_ps(_mm512_permutexvar_ps(r.perm[a], _mm512_sub_ps(plane, r.o[a])), r.mul[a]);
}

// The slab test of mesh/wide_traverse.inl's intersect_node, same results.
template <class Node>
inline int intersect_node16(const Node& n, const NodeRay16& r, V8 tmin, V8 tmax, V8& tnear,
                            float widen, float narrow) {
  const __m512 dx = axis_distances16(n, r, 0);
  const __m512 dy = axis_distances16(n, r, 1);
  const __m512 dz = axis_distances16(n, r, 2);
  // Lanes 0-7: max(max(nx, ny), max(nz, tmin)); lanes 8-15: max(max(-fx, -fy), max(-fz, -tmax))
  // = -min(min(fx, fy), min(fz, tmax)) (negation by the sign bit: exact, and max(-a, -b) picks
  // the operand min(a, b) picks, NaN included).
  const __m512 t = _mm512_insertf32x8(_mm512_castps256_ps512(tmin.v),
                                      _mm256_xor_ps(tmax.v, _mm256_set1_ps(-0.0f)), 1);
  const __m512 m = _mm512_max_ps(_mm512_max_ps(dx, dy), _mm512_max_ps(dz, t));
  const __m256 near = _mm512_castps512_ps256(m);
  const __m256 neg_far = _mm512_extractf32x8_ps(m, 1);
  // far * widen = (-far) * (-widen), far * narrow = (-far) * (-narrow): the larger is the
  // widened exit (tmax included) whatever its sign, as in the generic test.
  const __m256 tfar = _mm256_max_ps(_mm256_mul_ps(neg_far, _mm256_set1_ps(-widen)),
                                    _mm256_mul_ps(neg_far, _mm256_set1_ps(-narrow)));
  tnear = {near};
  return _mm256_cmp_ps_mask(near, tfar, _CMP_LE_OQ) & n.used;
}

}  // namespace raycast::kernels_avx512

#define RAYCAST_KERNEL_NODE16 1
// The 16-lane node test only where uses_node16 (mesh/wide_traverse.inl) says: elsewhere the 8-lane
// one (rows by the sign of d, loads folded), whose dependency chain has no lane-crossing permute
// or half extraction between a node's loads and its mask (on 1M shadow rays of
// bench/embree_table.sh, about 13 % faster than the 16-lane test).
#define RAYCAST_KERNEL_FOLDED_ROWS 1
#define RAYCAST_KERNEL_BITS_MINMAX 1
// The leaf's rows through three byte offsets: without them GCC kept the nine row offsets of the
// any-hit octant walks in the stack, reloaded at every leaf (1M shadow rays of
// bench/embree_table.sh: about 4 % faster with the offsets).
#define RAYCAST_KERNEL_ROW_OFFSETS 1
#define RAYCAST_KERNEL_NS kernels_avx512
#include "mesh/wide_traverse.inl"
// After the single-ray traversal, which it uses.
#include "mesh/packet_traverse.inl"
#undef RAYCAST_KERNEL_NS
#undef RAYCAST_KERNEL_NODE16
#undef RAYCAST_KERNEL_FOLDED_ROWS
#undef RAYCAST_KERNEL_BITS_MINMAX
#undef RAYCAST_KERNEL_ROW_OFFSETS

#pragma GCC diagnostic pop
#pragma GCC pop_options

namespace raycast {
const MeshKernels kMeshKernelsAvx512 = {Isa::kAvx512,
                                        kernels_avx512::closest,
                                        kernels_avx512::any,
                                        kernels_avx512::every,
                                        kernels_avx512::closest8,
                                        kernels_avx512::closest8_rays,
                                        kernels_avx512::occluded_if_valid};
}  // namespace raycast
#endif
