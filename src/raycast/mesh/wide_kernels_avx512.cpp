// The AVX-512 mesh kernels: eight lanes in one 256-bit register with AVX-512VL, comparisons into
// mask registers (32 vector registers, no movemask).
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

#if defined(__x86_64__)
#include <immintrin.h>

// Everything below (and nothing in the headers above) is compiled for AVX-512 (F, VL, DQ, BW).
// No FMA contraction: the build is ISO C++ (-ffp-contract=off).
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq,avx512bw,avx2,fma,bmi,bmi2,popcnt")

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

}  // namespace raycast::kernels_avx512

#define RAYCAST_KERNEL_NS kernels_avx512
#include "mesh/wide_traverse.inl"
#undef RAYCAST_KERNEL_NS

#pragma GCC pop_options

namespace raycast {
const MeshKernels kMeshKernelsAvx512 = {Isa::kAvx512, kernels_avx512::closest, kernels_avx512::any,
                                        kernels_avx512::every};
}  // namespace raycast
#endif
