#pragma once
// The conversion of a double Ray (is_valid) to the float MeshRay the mesh BVH takes, inlined
// where it is used: mesh.cpp's queries and the kernels' occluded entry (mesh/wide_kernels.h),
// so that every caller converts with the same bits.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/ray.h"
#include "mesh/mesh_bvh.h"

namespace raycast {

namespace mesh_ray_detail {

// The next float below / above f, by its bits (std::nextafter's answers for every f, without the
// library call: +-0 steps to -+denorm_min, an infinity to the largest finite float).
[[gnu::always_inline]] inline float next_down(float f) {
  const std::uint32_t u = std::bit_cast<std::uint32_t>(f);
  if ((u & 0x7FFFFFFFu) == 0) return -std::numeric_limits<float>::denorm_min();
  return std::bit_cast<float>(u >> 31 ? u + 1 : u - 1);
}

[[gnu::always_inline]] inline float next_up(float f) {
  const std::uint32_t u = std::bit_cast<std::uint32_t>(f);
  if ((u & 0x7FFFFFFFu) == 0) return std::numeric_limits<float>::denorm_min();
  return std::bit_cast<float>(u >> 31 ? u - 1 : u + 1);
}

[[gnu::always_inline]] inline float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? next_down(f) : f;
}

[[gnu::always_inline]] inline float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? next_up(f) : f;
}

// One component of a ray, read by an 8-byte load of its own. Callers write their Ray in pieces
// of the compiler's choosing (the bench: o.x and o.y in one 16-byte store, o.z alone, d.x and d.y
// together, d.z alone) just before the call, and a 16-byte load that spans two such stores (GCC
// paired d.y with d.z) cannot take its bytes from the store buffer: it waits until both stores
// have reached the cache (it was the hottest instruction of this function in perf). The
// empty asm keeps the value a scalar of its own, so GCC cannot merge neighbouring loads.
[[gnu::always_inline]] inline double ray_component(const double& x) {
  double v = x;
#if defined(__x86_64__)
  asm("" : "+x"(v));
#endif
  return v;
}

}  // namespace mesh_ray_detail

/// A Ray's eight components, each read by a load of its own (ray_component).
struct RayParts {
  double ox, oy, oz, dx, dy, dz, tmin, tmax;
};

[[gnu::always_inline]] inline RayParts ray_parts(const Ray& ray) {
  using mesh_ray_detail::ray_component;
  return {ray_component(ray.o.x),  ray_component(ray.o.y), ray_component(ray.o.z),
          ray_component(ray.d.x),  ray_component(ray.d.y), ray_component(ray.d.z),
          ray_component(ray.tmin), ray_component(ray.tmax)};
}

/// The binary exponent of the direction's largest component, from its bits (unbiased: e for
/// magnitudes in [2^e, 2^(e+1)) when normal). std::fabs and std::max rather than
/// abs/max_component: the same exponent, without branches.
[[gnu::always_inline]] inline int direction_exponent(const RayParts& q) {
  const double m = std::max(std::fabs(q.dx), std::max(std::fabs(q.dy), std::fabs(q.dz)));
  return static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7FF) - 1023;
}

/// The ray in the float form the mesh BVH takes (to_mesh_ray's body, mesh/mesh.h), and the factor
/// that turns its t back into units of ray.d (t_ray = t_mesh * scale). [tmin, tmax] are rounded
/// outwards. e: direction_exponent(q).
[[gnu::always_inline]] inline MeshRay convert_ray(const RayParts& q, int e, double& scale) {
  using namespace mesh_ray_detail;
  // Scale d by a power of two (exact) so that its largest component lies in [1, 2): then it is a
  // normal float whatever the caller's units, and t scales by the same power (the direction is
  // finite and non-zero: is_valid rays only).
  double inv_scale;
  if (e > -1022 && e < 1022) [[likely]] {
    scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - e) << 52);
    inv_scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + e) << 52);
  } else {
    const double m = std::max(std::fabs(q.dx), std::max(std::fabs(q.dy), std::fabs(q.dz)));
    scale = std::ldexp(1.0, -std::ilogb(m));
    inv_scale = 1 / scale;
  }
  MeshRay r;
  r.o = Vec3f(Vec3{q.ox, q.oy, q.oz});
  r.d = Vec3f(Vec3{q.dx, q.dy, q.dz} * scale);
  r.tmin = round_down(q.tmin * inv_scale);
  r.tmax = round_up(q.tmax * inv_scale);
  return r;
}

[[gnu::always_inline]] inline MeshRay convert_ray(const Ray& ray, double& scale) {
  const RayParts q = ray_parts(ray);
  return convert_ray(q, direction_exponent(q), scale);
}

/// is_valid(ray) (geometry/ray.h) from its parts, the direction's half from e =
/// direction_exponent(q) where it can: a largest component within [2^-510, 2^510) puts |d|^2
/// within [2^-1020, 3 * 2^1020], a finite normal double. And is_valid's test of [tmin, tmax]
/// (!(tmin > tmax), neither NaN) is tmin <= tmax (false on NaN).
[[gnu::always_inline]] inline bool is_valid(const RayParts& q, int e) {
  const double o2 = q.ox * q.ox + q.oy * q.oy + q.oz * q.oz;
  if (e >= -510 && e < 510) [[likely]]
    return o2 <= std::numeric_limits<double>::max() && q.tmin <= q.tmax;
  return is_valid_extent(o2, q.dx * q.dx + q.dy * q.dy + q.dz * q.dz) && q.tmin <= q.tmax;
}

}  // namespace raycast
