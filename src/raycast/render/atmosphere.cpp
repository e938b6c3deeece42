#include "render/atmosphere.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "math/float_error.h"

namespace raycast {

namespace {

// Where a segment's turbulence is looked up when the segment has no end: POV-Ray's manual warns
// that far points make the fog noisy and offers turb_depth against it; a fixed far point keeps
// misses deterministic and their noise at a bounded frequency.
constexpr double kMissTurbulenceLength = 1e4;

// The density integral above the offset over a piece of length `length` starting at x0 >= 0
// above it, rising by dh per unit: a (atan(x1 / a) - atan(x0 / a)) / dh, written through the
// difference formula so that nearly level pieces lose nothing to cancellation.
double above_offset(double alt, double x0, double dh, double length) {
  if (!(alt > 0)) return 0;
  const double u = x0 / alt;
  if (std::isinf(length)) {
    if (!(dh > 0)) return kInfinity;
    return alt * (std::numbers::pi / 2 - std::atan(u)) / dh;
  }
  const double v = (x0 + length * dh) / alt;
  const double q = length * dh / (alt * (1 + u * v));
  if (std::abs(q) < 1e-8) return length / (1 + u * v);
  return alt * std::atan(q) / dh;
}

// A value in [0, 1) fixed by the direction's bits: the rainbow's jitter, the same for the same
// ray in every render (renders are deterministic).
double direction_hash(const Vec3& u) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const double c : {u.x, u.y, u.z}) {
    h ^= std::bit_cast<std::uint64_t>(c) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 31;
  }
  return double(h >> 11) * 0x1.0p-53;
}

// The rainbow's weight at u by its arc: 1 within falloff_angle / 2 of up (the angle around the
// direction), 0 beyond arc_angle / 2, linear between.
double arc_fade(const Rainbow& r, const Vec3& u) {
  if (r.arc_angle >= 360) return 1;
  const Vec3 a = u - dot(u, r.direction) * r.direction;
  const Vec3 b = r.up - dot(r.up, r.direction) * r.direction;
  const double la = length(a), lb = length(b);
  if (!(la > 0 && lb > 0)) return 1;
  const double phi =
      std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0)) * 180 / std::numbers::pi;
  const double full = r.falloff_angle / 2, none = r.arc_angle / 2;
  if (phi <= full) return 1;
  if (phi >= none) return 0;
  return (none - phi) / (none - full);
}

}  // namespace

Vec3 sky_color(const SkySphere& sky, const Vec3& background, const Vec3& d) {
  const Vec3 p = sky.to_sky.point(normalize(d));
  Vec3 through{1, 1, 1}, sum{0, 0, 0};
  for (auto it = sky.layers.rbegin(); it != sky.layers.rend(); ++it) {
    const texture::Rgbft c = texture::evaluate(*it, p);
    sum += std::clamp(1 - c.filter - c.transmit, 0.0, 1.0) * mul(through, c.rgb);
    through = mul(through, c.filter * c.rgb + Vec3{c.transmit, c.transmit, c.transmit});
    if (!(through.x > 0 || through.y > 0 || through.z > 0)) break;
  }
  return mul(sky.emission, sum) + mul(through, background);
}

double ground_fog_depth(double offset, double alt, double h0, double dh, double length) {
  const double x0 = h0 - offset;
  if (dh == 0) return x0 <= 0 ? length : above_offset(alt, x0, 0, length);
  // The parameter where the segment's line crosses the offset's height.
  const double cross = -x0 / dh;
  double depth = 0;
  if (dh > 0) {
    if (x0 < 0) depth += std::min(length, cross);  // below, rising to the offset
    const double start = std::max(0.0, cross);
    if (start < length)
      depth += above_offset(alt, std::max(0.0, x0 + start * dh), dh, length - start);
  } else {
    if (x0 > 0) depth += above_offset(alt, x0, dh, std::min(length, cross));
    const double start = std::max(0.0, cross);
    if (start < length) depth += length - start;  // below, sinking
  }
  return depth;
}

double fog_depth(const Fog& fog, const Ray& ray, double span) {
  const Vec3 u = normalize(ray.d);
  double depth = span;
  if (fog.kind == Fog::Kind::kGround) {
    const Vec3 o = fog.to_fog.point(ray.o);
    const Vec3 e = fog.to_fog.vector(u);
    depth = ground_fog_depth(fog.offset, fog.alt, dot(fog.up, o), dot(fog.up, e), span);
  }
  if (fog.turbulence.any() && depth > 0) {
    const double at = fog.turb_depth * std::min(span, kMissTurbulenceLength);
    const Vec3 p = fog.to_fog.point(ray.o + at * u);
    const texture::Turbulence& t = fog.turbulence;
    const Vec3 moved = p + texture::turbulence_offset(p, t, 2);
    const double scale =
        1 - std::min(1.0, texture::turbulence_value(moved, t.octaves, t.omega, t.lambda, 2));
    depth = scale > 0 ? depth * scale : 0;  // not inf * 0 on a miss
  }
  return depth;
}

Vec3 apply_fogs(const std::vector<Fog>& fogs, const Ray& ray, double span, const Vec3& light) {
  Vec3 passing{1, 1, 1}, added{0, 0, 0};
  for (const Fog& fog : fogs) {
    const double depth = fog_depth(fog, ray, span);
    const double k =
        std::max(fog.transmit, std::isinf(depth) ? 0.0 : std::exp(-depth / fog.distance));
    const Vec3 tint = Vec3{1 - fog.filter, 1 - fog.filter, 1 - fog.filter} + fog.filter * fog.color;
    passing = mul(passing, k * tint);
    added += (1 - k) * fog.color;
  }
  return mul(passing, light) + added;
}

Vec3 apply_rainbows(const std::vector<Rainbow>& rainbows, const Ray& ray, double span,
                    const Vec3& light) {
  const Vec3 u = normalize(ray.d);
  Vec3 out = light;
  for (const Rainbow& r : rainbows) {
    const double cos_theta = std::clamp(dot(u, r.direction), -1.0, 1.0);
    double index =
        (std::acos(cos_theta) * 180 / std::numbers::pi - (r.angle - r.width / 2)) / r.width;
    if (r.jitter != 0) index += r.jitter * (direction_hash(u) - 0.5);
    if (!(index >= 0 && index <= 1)) continue;
    const double fade = arc_fade(r, u);
    if (!(fade > 0)) continue;
    const texture::Rgbft c = texture::lookup(r.colors, index);
    const double k = std::max(c.transmit, std::isinf(span) ? 0.0 : std::exp(-span / r.distance));
    const double veil = (1 - k) * fade;
    const Vec3 tint = Vec3{1, 1, 1} - c.filter * veil * (Vec3{1, 1, 1} - c.rgb);
    out = (1 - veil) * mul(tint, out) + veil * c.rgb;
  }
  return out;
}

Vec3 veiled(const Atmosphere& atmosphere, const Ray& ray, double span, const Vec3& light) {
  const Vec3 behind =
      atmosphere.rainbows.empty() ? light : apply_rainbows(atmosphere.rainbows, ray, span, light);
  return atmosphere.fogs.empty() ? behind : apply_fogs(atmosphere.fogs, ray, span, behind);
}

Vec3 miss_color(const Atmosphere& atmosphere, const Vec3& background, const Ray& ray) {
  const Vec3 seen = atmosphere.sky ? sky_color(*atmosphere.sky, background, ray.d) : background;
  return atmosphere.veils() ? veiled(atmosphere, ray, kInfinity, seen) : seen;
}

}  // namespace raycast
