#pragma once
// How much of a light reaches a point: spot and cylinder cones, distance attenuation, and the
// grid of points of an area light (docs/scene-format.md "Lights"). Used by the Whitted
// recursion (render/whitted_trace.inl).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/rng.h"
#include "scene/light.h"

namespace raycast {

/// A smoothstep between 0 at `outer` and 1 at `inner` (outer < inner); the value x itself.
inline double smooth_edge(double x, double outer, double inner) {
  if (x >= inner) return 1;
  if (x <= outer) return 0;
  const double t = (x - outer) / (inner - outer);
  return t * t * (3 - 2 * t);
}

/// The spot cone's factor for light leaving in the unit direction `from_light`: 1 inside
/// angle - falloff, 0 outside angle, a smoothstep between (over the angle or its cosine), times
/// cos^tightness of the angle off the axis.
inline double spot_cone(const Light& light, const Vec3& from_light) {
  constexpr double kDegrees = std::numbers::pi / 180;
  const double cos_theta = std::clamp(dot(light.direction, from_light), -1.0, 1.0);
  double f;
  if (light.edge == SpotEdge::kCosine) {
    const double inner = std::max(0.0, light.angle - light.falloff);
    f = smooth_edge(cos_theta, std::cos(light.angle * kDegrees), std::cos(inner * kDegrees));
  } else {
    const double theta = std::acos(cos_theta) / kDegrees;
    if (theta >= light.angle) return 0;
    if (theta <= light.angle - light.falloff) {
      f = 1;
    } else {
      const double x = (light.angle - theta) / light.falloff;
      f = x * x * (3 - 2 * x);
    }
  }
  if (light.tightness > 0 && f > 0) f *= std::pow(std::max(0.0, cos_theta), light.tightness);
  return f;
}

/// The cylinder light's factor at `p`: 0 behind the light or farther than `angle` from its
/// axis, 1 within angle - falloff, a smoothstep between.
inline double cylinder_cone(const Light& light, const Vec3& p) {
  const Vec3 to = p - light.position;
  const double along = dot(to, light.direction);
  if (!(along > 0)) return 0;
  const double off_axis = length(to - along * light.direction);
  return smooth_edge(-off_axis, -light.angle, -(light.angle - light.falloff));
}

/// The distance attenuation at squared distance dist2 from the light.
inline double attenuation_factor(const Light& light, double dist2) {
  switch (light.attenuation) {
    case Attenuation::kNone:
      return 1;
    case Attenuation::kInverseSquare:
      return 1 / dist2;
    case Attenuation::kFade:
      return 2 / (1 + std::pow(std::sqrt(dist2) / light.fade_distance, light.fade_power));
  }
  return 1;
}

/// An area light's grid seen from p: POV-Ray's array of size1 x size2 point lights spanning
/// axis1 and axis2 (corners included; one row or column is the centre line), jittered within
/// their cells, squeezed into an ellipse (circular), turned to face p (orient). The light's
/// fields copied: the compiler keeps them in registers across the generator's calls.
struct AreaLightGrid {
  Vec3 position, a1, a2;
  int n1, n2;
  bool jitter, circular;

  AreaLightGrid(const Light& light, const Vec3& p)
      : position(light.position),
        a1(light.axis1),
        a2(light.axis2),
        n1(light.size1),
        n2(light.size2),
        jitter(light.jitter),
        circular(light.circular) {
    if (!light.orient) return;
    // The grid's plane turned perpendicular to the light-to-point line, its axes' lengths kept.
    const Vec3 w = p - light.position;
    if (length_squared(w) > 0) {
      Vec3 s, t;
      make_frame(normalize(w), s, t);
      a1 = length(light.axis1) * s;
      a2 = length(light.axis2) * t;
    }
  }

  /// Grid point (i, j); with jitter, two numbers from rng.
  [[gnu::always_inline]] Vec3 point(int i, int j, Rng& rng) const {
    double u = n1 > 1 ? double(i) / (n1 - 1) - 0.5 : 0;
    double v = n2 > 1 ? double(j) / (n2 - 1) - 0.5 : 0;
    if (jitter) {
      if (n1 > 1) u += (rng.uniform() - 0.5) / (n1 - 1);
      if (n2 > 1) v += (rng.uniform() - 0.5) / (n2 - 1);
    }
    if (circular) {
      // The square [-0.5, 0.5]^2 onto the disc of radius 0.5, square rings onto circles
      // (Shirley and Chiu's concentric map).
      const double a = 2 * u, b = 2 * v;
      if (a != 0 || b != 0) {
        const bool wide = std::abs(a) > std::abs(b);
        const double r = wide ? a : b;
        const double phi = wide ? std::numbers::pi / 4 * (b / a)
                                : std::numbers::pi / 2 - std::numbers::pi / 4 * (a / b);
        u = 0.5 * r * std::cos(phi);
        v = 0.5 * r * std::sin(phi);
      }
    }
    return position + u * a1 + v * a2;
  }
};

/// Every grid point of the area light seen from p, row by row, each passed to add(target).
template <class Add>
void area_light_points(const Light& light, const Vec3& p, Rng& rng, Add&& add) {
  const AreaLightGrid grid(light, p);
  for (int i = 0; i < grid.n1; ++i)
    for (int j = 0; j < grid.n2; ++j) add(grid.point(i, j, rng));
}

}  // namespace raycast
