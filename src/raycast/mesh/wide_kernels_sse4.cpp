// The SSE4.2 mesh kernels: eight lanes as two 4-wide registers.
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

// Everything below (and nothing in the headers above) is compiled for SSE4.2.
#pragma GCC push_options
#pragma GCC target("sse4.2,popcnt")

namespace raycast::kernels_sse4 {

struct V8 {
  __m128 a, b;
};
struct M8 {
  __m128 a, b;
};

inline V8 load8(const float* p) { return {_mm_load_ps(p), _mm_load_ps(p + 4)}; }
inline V8 load8_u8(const std::uint8_t* p) {
  const __m128i x = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p));
  return {_mm_cvtepi32_ps(_mm_cvtepu8_epi32(x)),
          _mm_cvtepi32_ps(_mm_cvtepu8_epi32(_mm_srli_si128(x, 4)))};
}
inline V8 load44(const float* a, const float* b) { return {_mm_load_ps(a), _mm_load_ps(b)}; }
inline V8 splat(float x) { return {_mm_set1_ps(x), _mm_set1_ps(x)}; }
inline void store8(float* p, V8 v) { _mm_store_ps(p, v.a), _mm_store_ps(p + 4, v.b); }
inline V8 operator+(V8 x, V8 y) { return {_mm_add_ps(x.a, y.a), _mm_add_ps(x.b, y.b)}; }
inline V8 operator-(V8 x, V8 y) { return {_mm_sub_ps(x.a, y.a), _mm_sub_ps(x.b, y.b)}; }
inline V8 operator*(V8 x, V8 y) { return {_mm_mul_ps(x.a, y.a), _mm_mul_ps(x.b, y.b)}; }
inline V8 operator/(V8 x, V8 y) { return {_mm_div_ps(x.a, y.a), _mm_div_ps(x.b, y.b)}; }
inline V8 vmin(V8 x, V8 y) { return {_mm_min_ps(x.a, y.a), _mm_min_ps(x.b, y.b)}; }
inline V8 vmax(V8 x, V8 y) { return {_mm_max_ps(x.a, y.a), _mm_max_ps(x.b, y.b)}; }
// Integer max / min of the float bits (the nearest walk's node test, mesh/wide_traverse.inl).
inline __m128 max_bits4(__m128 x, __m128 y) {
  return _mm_castsi128_ps(_mm_max_epi32(_mm_castps_si128(x), _mm_castps_si128(y)));
}
inline __m128 min_bits4(__m128 x, __m128 y) {
  return _mm_castsi128_ps(_mm_min_epi32(_mm_castps_si128(x), _mm_castps_si128(y)));
}
inline V8 vmax_bits(V8 x, V8 y) { return {max_bits4(x.a, y.a), max_bits4(x.b, y.b)}; }
inline V8 vmin_bits(V8 x, V8 y) { return {min_bits4(x.a, y.a), min_bits4(x.b, y.b)}; }
inline M8 cmp_le(V8 x, V8 y) { return {_mm_cmple_ps(x.a, y.a), _mm_cmple_ps(x.b, y.b)}; }
inline M8 cmp_ge(V8 x, V8 y) { return {_mm_cmpge_ps(x.a, y.a), _mm_cmpge_ps(x.b, y.b)}; }
inline M8 cmp_eq(V8 x, V8 y) { return {_mm_cmpeq_ps(x.a, y.a), _mm_cmpeq_ps(x.b, y.b)}; }
inline M8 cmp_ne(V8 x, V8 y) { return {_mm_cmpneq_ps(x.a, y.a), _mm_cmpneq_ps(x.b, y.b)}; }
inline M8 mand(M8 x, M8 y) { return {_mm_and_ps(x.a, y.a), _mm_and_ps(x.b, y.b)}; }
inline M8 mor(M8 x, M8 y) { return {_mm_or_ps(x.a, y.a), _mm_or_ps(x.b, y.b)}; }
inline int bits(M8 m) { return _mm_movemask_ps(m.a) | _mm_movemask_ps(m.b) << 4; }
inline V8 select(M8 m, V8 x, V8 y) {
  return {_mm_blendv_ps(y.a, x.a, m.a), _mm_blendv_ps(y.b, x.b, m.b)};
}

}  // namespace raycast::kernels_sse4

#define RAYCAST_KERNEL_NS kernels_sse4
#include "mesh/wide_traverse.inl"
// After the single-ray traversal, which it uses.
#include "mesh/packet_traverse.inl"
#undef RAYCAST_KERNEL_NS

#pragma GCC pop_options

namespace raycast {
const MeshKernels kMeshKernelsSse4 = {Isa::kSse4,
                                      kernels_sse4::closest,
                                      kernels_sse4::any,
                                      kernels_sse4::every,
                                      kernels_sse4::closest8,
                                      kernels_sse4::closest8_rays,
                                      kernels_sse4::occluded_if_valid};
}  // namespace raycast
#endif
