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
// have reached the cache (the hottest instruction of this function in perf, session 11). The
// empty asm keeps the value a scalar of its own, so GCC cannot merge neighbouring loads.
[[gnu::always_inline]] inline double ray_component(const double& x) {
  double v = x;
#if defined(__x86_64__)
  asm("" : "+x"(v));
#endif
  return v;
}

}  // namespace mesh_ray_detail

/// The ray in the float form the mesh BVH takes (to_mesh_ray's body, mesh/mesh.h), and the factor
/// that turns its t back into units of ray.d (t_ray = t_mesh * scale). [tmin, tmax] are rounded
/// outwards.
[[gnu::always_inline]] inline MeshRay convert_ray(const Ray& ray, double& scale) {
  using namespace mesh_ray_detail;
  const double ox = ray_component(ray.o.x), oy = ray_component(ray.o.y),
               oz = ray_component(ray.o.z), dx = ray_component(ray.d.x),
               dy = ray_component(ray.d.y), dz = ray_component(ray.d.z);
  // Scale d by a power of two (exact) so that its largest component lies in [1, 2): then it is a
  // normal float whatever the caller's units, and t scales by the same power. The exponent is read
  // from the bits (the direction is finite and non-zero: is_valid rays only). std::fabs and
  // std::max rather than abs/max_component: the same exponent, without branches.
  const double m = std::max(std::fabs(dx), std::max(std::fabs(dy), std::fabs(dz)));
  const int e = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7FF) - 1023;
  double inv_scale;
  if (e > -1022 && e < 1022) [[likely]] {
    scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - e) << 52);
    inv_scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + e) << 52);
  } else {
    scale = std::ldexp(1.0, -std::ilogb(m));
    inv_scale = 1 / scale;
  }
  MeshRay r;
  r.o = Vec3f(Vec3{ox, oy, oz});
  r.d = Vec3f(Vec3{dx, dy, dz} * scale);
  r.tmin = round_down(ray_component(ray.tmin) * inv_scale);
  r.tmax = round_up(ray_component(ray.tmax) * inv_scale);
  return r;
}

}  // namespace raycast
