#pragma once
// Four boxes against one ray in one pass, in float (SSE2, the x86-64 baseline; a scalar loop of
// the same arithmetic elsewhere). A culling test for the top level over objects: it is
// conservative, so every box whose exact double box the exact segment meets passes (a few more
// may), and the objects' own exact tests decide. The error bound:
// - boxes are rounded outwards to float (which only moves entries earlier and exits later);
// - per ray and axis, t = plane * inv - (o * inv +- s), where s ~ 2^-20 (M + |o|) |inv| covers
//   the rounding of plane * inv, of o and o * inv and of inv itself in absolute terms (M bounds
//   the set's |coordinates|; the error is at most about 4 u (M + |o|) |inv|, u = 2^-24), and the
//   relative rounding of the result is covered by comparing entry <= exit * (1 + 2^-18), with
//   entry >= 0;
// - an axis whose 1 / d is not within [2^-100, 2^100], whose |o| exceeds 2^100 or whose s would,
//   constrains nothing (its entry is -inf, its exit +inf), and so does every axis of a ray with
//   tmin < 0: such rays pass every box, which is conservative.
// NaN distances (0 * inf from an infinite box side) leave that axis unconstrained, as in
// intersect_slabs: the min/max keep their second operand then.
#include <bit>
#include <cmath>
#include <cstdint>

#include "geometry/aabb.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace raycast {

/// Four boxes, planes by row: lo x, lo y, lo z, hi x, hi y, hi z; one lane per box.
struct alignas(16) Box4 {
  float plane[6][4];
};

/// Box coordinates beyond +-kBox4Limit are stored as infinite (the box test stays finite).
inline constexpr double kBox4Limit = 0x1p100;
/// Relative slack of the entry/exit comparison and the absolute slack factor of s (see above).
inline constexpr float kBox4ExitScale = 1.0f + 0x1p-18f;
inline constexpr double kBox4Slack = 0x1p-20;

/// The largest float not above x, and the smallest not below (x not NaN). The step is taken on
/// the bits (no libm call on the per-ray path).
inline float float_down(double x) {
  const float f = static_cast<float>(x);
  if (!(static_cast<double>(f) > x)) return f;
  if (f == 0) return -0x1p-149f;
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}
inline float float_up(double x) {
  const float f = static_cast<float>(x);
  if (!(static_cast<double>(f) < x)) return f;
  if (f == 0) return 0x1p-149f;
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>(f > 0 ? bits + 1 : bits - 1);
}

/// Lane `lane` of `b` set to `box` rounded outwards (an empty box gives an empty lane).
inline void set_box4_lane(Box4& b, int lane, const Aabb& box) {
  for (int a = 0; a < 3; ++a) {
    const double lo = box.lo[a], hi = box.hi[a];
    b.plane[a][lane] = lo < -kBox4Limit ? -INFINITY : lo > kBox4Limit ? INFINITY : float_down(lo);
    b.plane[3 + a][lane] = hi > kBox4Limit ? INFINITY : hi < -kBox4Limit ? -INFINITY : float_up(hi);
  }
}

/// An empty lane: lo = +inf, hi = -inf on every axis.
inline void clear_box4_lane(Box4& b, int lane) {
  for (int a = 0; a < 3; ++a) {
    b.plane[a][lane] = INFINITY;
    b.plane[3 + a][lane] = -INFINITY;
  }
}

/// The per-ray constants of the test, made once per query.
struct alignas(16) Box4Ray {
  float inv[3][4];       // float(1 / d) per axis, in every lane; 0 for an unconstrained axis
  float near_off[3][4];  // o * inv + s; +inf for an unconstrained axis
  float far_off[3][4];   // o * inv - s; -inf for an unconstrained axis
  std::uint32_t near_row[3], far_row[3];  // rows of Box4::plane: lo or hi by the sign of d
  float tmin;                             // rounded down; -inf when every box passes
};

/// kBox4Slack * magnitude, per axis, in the first three lanes (the fourth 0): `magnitude[a]` bounds
/// |coordinate a| over the finite planes of every box tested with the ray.
struct alignas(16) Box4Scale {
  float slack[4];
};

inline Box4Scale make_box4_scale(const double magnitude[3]) {
  Box4Scale s{};
  for (int a = 0; a < 3; ++a) s.slack[a] = float_up(kBox4Slack * magnitude[a]);
  return s;
}

/// The test's constants for `ray` (inv_d = reciprocal(ray.d)). In float: o and 1 / d rounded to
/// nearest, s = (slack + 2^-20 |o|) |inv| + 2^-120 with its own roundings (relative, a few u,
/// inside the slack's factor of 8 over the error it covers).
inline Box4Ray make_box4_ray(const Ray& ray, const Vec3& inv_d, const Box4Scale& scale) {
  Box4Ray r;
  const bool usable = ray.tmin >= 0;
#if defined(__SSE2__)
  const __m128 inv = _mm_movelh_ps(_mm_cvtpd_ps(_mm_set_pd(inv_d.y, inv_d.x)),
                                   _mm_cvtpd_ps(_mm_set_pd(0.0, inv_d.z)));
  const __m128 o = _mm_movelh_ps(_mm_cvtpd_ps(_mm_set_pd(ray.o.y, ray.o.x)),
                                 _mm_cvtpd_ps(_mm_set_pd(0.0, ray.o.z)));
  const __m128 abs_mask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 abs_inv = _mm_and_ps(inv, abs_mask), abs_o = _mm_and_ps(o, abs_mask);
  const __m128 sl = _mm_add_ps(
      _mm_mul_ps(_mm_add_ps(_mm_load_ps(scale.slack),
                            _mm_mul_ps(abs_o, _mm_set1_ps(static_cast<float>(kBox4Slack)))),
                 abs_inv),
      _mm_set1_ps(0x1p-120f));
  const __m128 oi = _mm_mul_ps(o, inv);
  const __m128 big = _mm_set1_ps(0x1p100f);
  __m128 ok = _mm_and_ps(
      _mm_and_ps(_mm_cmpge_ps(abs_inv, _mm_set1_ps(0x1p-100f)), _mm_cmple_ps(abs_inv, big)),
      _mm_and_ps(_mm_cmple_ps(sl, big), _mm_cmple_ps(abs_o, big)));
  if (!usable) ok = _mm_setzero_ps();
  const __m128 inf = _mm_set1_ps(INFINITY);
  const __m128 v_inv = _mm_and_ps(ok, inv);
  const __m128 v_near = _mm_or_ps(_mm_and_ps(ok, _mm_add_ps(oi, sl)), _mm_andnot_ps(ok, inf));
  const __m128 v_far = _mm_or_ps(_mm_and_ps(ok, _mm_sub_ps(oi, sl)),
                                 _mm_andnot_ps(ok, _mm_sub_ps(_mm_setzero_ps(), inf)));
  _mm_store_ps(r.inv[0], _mm_shuffle_ps(v_inv, v_inv, 0x00));
  _mm_store_ps(r.inv[1], _mm_shuffle_ps(v_inv, v_inv, 0x55));
  _mm_store_ps(r.inv[2], _mm_shuffle_ps(v_inv, v_inv, 0xAA));
  _mm_store_ps(r.near_off[0], _mm_shuffle_ps(v_near, v_near, 0x00));
  _mm_store_ps(r.near_off[1], _mm_shuffle_ps(v_near, v_near, 0x55));
  _mm_store_ps(r.near_off[2], _mm_shuffle_ps(v_near, v_near, 0xAA));
  _mm_store_ps(r.far_off[0], _mm_shuffle_ps(v_far, v_far, 0x00));
  _mm_store_ps(r.far_off[1], _mm_shuffle_ps(v_far, v_far, 0x55));
  _mm_store_ps(r.far_off[2], _mm_shuffle_ps(v_far, v_far, 0xAA));
#else
  for (int a = 0; a < 3; ++a) {
    const float inv = static_cast<float>(inv_d[a]), o = static_cast<float>(ray.o[a]);
    const float sl =
        (scale.slack[a] + std::abs(o) * static_cast<float>(kBox4Slack)) * std::abs(inv) + 0x1p-120f;
    const float oi = o * inv;
    const bool ok = usable && std::abs(inv) >= 0x1p-100f && std::abs(inv) <= 0x1p100f &&
                    sl <= 0x1p100f && std::abs(o) <= 0x1p100f;
    for (int l = 0; l < 4; ++l) {
      r.inv[a][l] = ok ? inv : 0.0f;
      r.near_off[a][l] = ok ? oi + sl : INFINITY;
      r.far_off[a][l] = ok ? oi - sl : -INFINITY;
    }
  }
#endif
  for (int a = 0; a < 3; ++a) {
    const std::uint32_t negative = std::signbit(inv_d[a]) ? 3 : 0;
    r.near_row[a] = static_cast<std::uint32_t>(a) + negative;
    r.far_row[a] = static_cast<std::uint32_t>(a) + 3 - negative;
  }
  r.tmin = usable ? float_down(ray.tmin) : -INFINITY;
  return r;
}

/// box4_hits lane by lane, the same arithmetic (the path of other architectures; tests compare
/// the two on x86-64).
inline unsigned box4_hits_scalar(const Box4& b, const Box4Ray& r, float tmax_up, float t_enter[4]) {
  unsigned mask = 0;
  for (int l = 0; l < 4; ++l) {
    float t0 = r.tmin, t1 = tmax_up;
    for (int a = 0; a < 3; ++a) {
      const float n = b.plane[r.near_row[a]][l] * r.inv[a][l] - r.near_off[a][l];
      const float f = b.plane[r.far_row[a]][l] * r.inv[a][l] - r.far_off[a][l];
      t0 = n > t0 ? n : t0;
      t1 = f < t1 ? f : t1;
    }
    t_enter[l] = t0;
    if (t0 <= t1 * kBox4ExitScale) mask |= 1u << l;
  }
  return mask;
}

/// Bit l set when box l of `b` may meet the segment [tmin, tmax] (tmax_up: the segment's tmax
/// rounded up to float); t_enter[l] is then its entry (at least tmin), for ordering and for
/// dropping it later against a lowered tmax with box4_enters_before.
inline unsigned box4_hits(const Box4& b, const Box4Ray& r, float tmax_up, float t_enter[4]) {
#if defined(__SSE2__)
  __m128 t0 = _mm_set1_ps(r.tmin), t1 = _mm_set1_ps(tmax_up);
  for (int a = 0; a < 3; ++a) {
    const __m128 inv = _mm_load_ps(r.inv[a]);
    const __m128 n = _mm_sub_ps(_mm_mul_ps(_mm_load_ps(b.plane[r.near_row[a]]), inv),
                                _mm_load_ps(r.near_off[a]));
    const __m128 f =
        _mm_sub_ps(_mm_mul_ps(_mm_load_ps(b.plane[r.far_row[a]]), inv), _mm_load_ps(r.far_off[a]));
    t0 = _mm_max_ps(n, t0);  // n NaN: t0 kept
    t1 = _mm_min_ps(f, t1);
  }
  _mm_store_ps(t_enter, t0);
  return static_cast<unsigned>(
      _mm_movemask_ps(_mm_cmple_ps(t0, _mm_mul_ps(t1, _mm_set1_ps(kBox4ExitScale)))));
#else
  return box4_hits_scalar(b, r, tmax_up, t_enter);
#endif
}

/// Whether a box entered at t_enter (from box4_hits) may still meet a segment whose tmax has
/// been lowered to tmax_up (rounded up): the test box4_hits would make with it.
inline bool box4_enters_before(float t_enter, float tmax_up) {
  return t_enter <= tmax_up * kBox4ExitScale;
}

}  // namespace raycast
