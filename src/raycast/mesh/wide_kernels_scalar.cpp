// The portable mesh kernels: plain C++ lanes (any architecture; the reference the SIMD paths
// are tested against).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "mesh/mesh_ray.h"
#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

namespace raycast::kernels_scalar {

struct V8 {
  float v[8];
};
using M8 = int;  // bit i: lane i

inline V8 load8(const float* p) {
  V8 r;
  for (int i = 0; i < 8; ++i) r.v[i] = p[i];
  return r;
}
inline V8 load8_u8(const std::uint8_t* p) {
  V8 r;
  for (int i = 0; i < 8; ++i) r.v[i] = static_cast<float>(p[i]);
  return r;
}
inline V8 load44(const float* a, const float* b) {
  V8 r;
  for (int i = 0; i < 4; ++i) r.v[i] = a[i], r.v[i + 4] = b[i];
  return r;
}
inline V8 splat(float x) {
  V8 r;
  for (float& f : r.v) f = x;
  return r;
}
inline void store8(float* p, V8 a) {
  for (int i = 0; i < 8; ++i) p[i] = a.v[i];
}
template <class F>
inline V8 lanewise(V8 a, V8 b, F f) {
  V8 r;
  for (int i = 0; i < 8; ++i) r.v[i] = f(a.v[i], b.v[i]);
  return r;
}
template <class F>
inline M8 compare(V8 a, V8 b, F f) {
  M8 m = 0;
  for (int i = 0; i < 8; ++i) m |= f(a.v[i], b.v[i]) ? 1 << i : 0;
  return m;
}
inline V8 operator+(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) { return x + y; });
}
inline V8 operator-(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) { return x - y; });
}
inline V8 operator*(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) { return x * y; });
}
inline V8 operator/(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) { return x / y; });
}
// SSE's minps / maxps: the second operand unless the first is strictly smaller / larger.
inline V8 vmin(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) { return x < y ? x : y; });
}
inline V8 vmax(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) { return x > y ? x : y; });
}
inline M8 cmp_le(V8 a, V8 b) {
  return compare(a, b, [](float x, float y) { return x <= y; });
}
inline M8 cmp_ge(V8 a, V8 b) {
  return compare(a, b, [](float x, float y) { return x >= y; });
}
inline M8 cmp_eq(V8 a, V8 b) {
  return compare(a, b, [](float x, float y) { return x == y; });
}
inline M8 cmp_ne(V8 a, V8 b) {
  return compare(a, b, [](float x, float y) { return !(x == y); });
}
// Integer max / min of the float bits (the nearest walk's node test, mesh/wide_traverse.inl).
inline V8 vmax_bits(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) {
    return std::bit_cast<std::int32_t>(x) > std::bit_cast<std::int32_t>(y) ? x : y;
  });
}
inline V8 vmin_bits(V8 a, V8 b) {
  return lanewise(a, b, [](float x, float y) {
    return std::bit_cast<std::int32_t>(x) < std::bit_cast<std::int32_t>(y) ? x : y;
  });
}
inline M8 mand(M8 a, M8 b) { return a & b; }
inline M8 mor(M8 a, M8 b) { return a | b; }
inline int bits(M8 m) { return m; }
inline V8 select(M8 m, V8 a, V8 b) {
  V8 r;
  for (int i = 0; i < 8; ++i) r.v[i] = (m >> i & 1) ? a.v[i] : b.v[i];
  return r;
}

}  // namespace raycast::kernels_scalar

#define RAYCAST_KERNEL_NS kernels_scalar
#include "mesh/wide_traverse.inl"
// After the single-ray traversal, which it uses.
#include "mesh/packet_traverse.inl"
#undef RAYCAST_KERNEL_NS

namespace raycast {
const MeshKernels kMeshKernelsScalar = {Isa::kScalar,
                                        kernels_scalar::closest,
                                        kernels_scalar::any,
                                        kernels_scalar::every,
                                        kernels_scalar::closest8,
                                        kernels_scalar::closest8_rays,
                                        kernels_scalar::occluded_if_valid};
}  // namespace raycast
