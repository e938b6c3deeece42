// The AVX2 mesh kernels: eight lanes in one 256-bit register.
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

// Everything below (and nothing in the headers above) is compiled for AVX2. No FMA contraction:
// the build is ISO C++ (-ffp-contract=off), and the kernels must match the other ISAs bit for bit.
#pragma GCC push_options
#pragma GCC target("avx2,fma,bmi,bmi2,popcnt")

namespace raycast::kernels_avx2 {

struct V8 {
  __m256 v;
};
struct M8 {
  __m256 m;
};

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
// Integer max / min of the float bits (the nearest walk's node test, mesh/wide_traverse.inl).
inline V8 vmax_bits(V8 x, V8 y) {
  return {
      _mm256_castsi256_ps(_mm256_max_epi32(_mm256_castps_si256(x.v), _mm256_castps_si256(y.v)))};
}
inline V8 vmin_bits(V8 x, V8 y) {
  return {
      _mm256_castsi256_ps(_mm256_min_epi32(_mm256_castps_si256(x.v), _mm256_castps_si256(y.v)))};
}
inline M8 cmp_le(V8 x, V8 y) { return {_mm256_cmp_ps(x.v, y.v, _CMP_LE_OQ)}; }
inline M8 cmp_ge(V8 x, V8 y) { return {_mm256_cmp_ps(x.v, y.v, _CMP_GE_OQ)}; }
inline M8 cmp_eq(V8 x, V8 y) { return {_mm256_cmp_ps(x.v, y.v, _CMP_EQ_OQ)}; }
inline M8 cmp_ne(V8 x, V8 y) { return {_mm256_cmp_ps(x.v, y.v, _CMP_NEQ_UQ)}; }
inline M8 mand(M8 x, M8 y) { return {_mm256_and_ps(x.m, y.m)}; }
inline M8 mor(M8 x, M8 y) { return {_mm256_or_ps(x.m, y.m)}; }
inline int bits(M8 m) { return _mm256_movemask_ps(m.m); }
inline V8 select(M8 m, V8 x, V8 y) { return {_mm256_blendv_ps(y.v, x.v, m.m)}; }

}  // namespace raycast::kernels_avx2

#define RAYCAST_KERNEL_MINMAX_SLABS 1
// The leaf's rows through three byte offsets: 4 % fewer instructions on shadow rays (callgrind of
// `raycast bench --procedural sphere:200000 --rays shadow --threads 1`).
#define RAYCAST_KERNEL_ROW_OFFSETS 1
#define RAYCAST_KERNEL_NS kernels_avx2
#include "mesh/wide_traverse.inl"
// After the single-ray traversal, which it uses.
#include "mesh/packet_traverse.inl"
#undef RAYCAST_KERNEL_NS
#undef RAYCAST_KERNEL_ROW_OFFSETS
#undef RAYCAST_KERNEL_MINMAX_SLABS

#pragma GCC pop_options

namespace raycast {
const MeshKernels kMeshKernelsAvx2 = {Isa::kAvx2,
                                      kernels_avx2::closest,
                                      kernels_avx2::any,
                                      kernels_avx2::every,
                                      kernels_avx2::closest8,
                                      kernels_avx2::closest8_rays,
                                      kernels_avx2::occluded_if_valid};
}  // namespace raycast
#endif
