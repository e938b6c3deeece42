// The lane vector of 16-ray packets (mesh/packet_traverse.inl's PacketLanes<16>): one 512-bit
// register of floats and a 16-bit mask register. Included by mesh/packet_traverse.inl only where
// the kernel file compiles for AVX-512 (it defines RAYCAST_KERNEL_NODE16), inside that file's
// `#pragma GCC target` region. Each operation is the one IEEE single-precision operation of the
// 8-lane type, so a lane's results are those of the 8-ray packet and of the single ray.

namespace raycast::RAYCAST_KERNEL_NS {

struct V16 {
  __m512 v;
};
using M16 = __mmask16;

inline V16 operator+(V16 x, V16 y) { return {_mm512_add_ps(x.v, y.v)}; }
inline V16 operator-(V16 x, V16 y) { return {_mm512_sub_ps(x.v, y.v)}; }
inline V16 operator*(V16 x, V16 y) { return {_mm512_mul_ps(x.v, y.v)}; }
inline V16 operator/(V16 x, V16 y) { return {_mm512_div_ps(x.v, y.v)}; }
// The second operand when either is NaN, as the 8-lane vmin/vmax.
inline V16 vmin(V16 x, V16 y) { return {_mm512_min_ps(x.v, y.v)}; }
inline V16 vmax(V16 x, V16 y) { return {_mm512_max_ps(x.v, y.v)}; }
inline V16 vmax_bits(V16 x, V16 y) {
  return {
      _mm512_castsi512_ps(_mm512_max_epi32(_mm512_castps_si512(x.v), _mm512_castps_si512(y.v)))};
}
inline V16 vmin_bits(V16 x, V16 y) {
  return {
      _mm512_castsi512_ps(_mm512_min_epi32(_mm512_castps_si512(x.v), _mm512_castps_si512(y.v)))};
}
inline M16 cmp_le(V16 x, V16 y) { return _mm512_cmp_ps_mask(x.v, y.v, _CMP_LE_OQ); }
inline M16 cmp_ge(V16 x, V16 y) { return _mm512_cmp_ps_mask(x.v, y.v, _CMP_GE_OQ); }
inline M16 cmp_eq(V16 x, V16 y) { return _mm512_cmp_ps_mask(x.v, y.v, _CMP_EQ_OQ); }
inline M16 cmp_ne(V16 x, V16 y) { return _mm512_cmp_ps_mask(x.v, y.v, _CMP_NEQ_UQ); }
inline M16 mand(M16 x, M16 y) { return static_cast<M16>(x & y); }
inline M16 mor(M16 x, M16 y) { return static_cast<M16>(x | y); }
inline int bits(M16 m) { return m; }
inline V16 select(M16 m, V16 x, V16 y) { return {_mm512_mask_blend_ps(m, y.v, x.v)}; }

template <>
struct PacketLanes<16> {
  using V = V16;
  static V load(const float* p) { return {_mm512_load_ps(p)}; }
  static V broadcast(float x) { return {_mm512_set1_ps(x)}; }
  static void store(float* p, V x) { _mm512_store_ps(p, x.v); }
};

}  // namespace raycast::RAYCAST_KERNEL_NS
