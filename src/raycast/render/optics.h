#pragma once
// Mirror reflection, Snell refraction, the exact dielectric Fresnel reflectance and the integer
// power of the Phong highlight.
#include <algorithm>
#include <cmath>

#include "math/vec3.h"

namespace raycast {

/// d mirrored about the unit normal n (d keeps its length).
inline Vec3 reflect(const Vec3& d, const Vec3& n) { return d - 2 * dot(d, n) * n; }

/// Refracts the unit direction wi (travelling towards the surface) through a surface whose unit
/// normal n faces against it (dot(wi, n) <= 0), with eta = eta_i / eta_t (Snell's law). Writes
/// the unit transmitted direction and returns true, or returns false under total internal
/// reflection.
inline bool refract(const Vec3& wi, const Vec3& n, double eta, Vec3& wt) {
  const double cos_i = std::min(1.0, -dot(wi, n));
  const double sin2_t = eta * eta * std::max(0.0, 1 - cos_i * cos_i);
  if (sin2_t > 1) return false;
  const double cos_t = std::sqrt(1 - sin2_t);
  wt = normalize(eta * wi + (eta * cos_i - cos_t) * n);
  return true;
}

/// The Fresnel reflectance of unpolarised light at a smooth dielectric boundary, exact
/// (F = (Rs + Rp) / 2, Born and Wolf 1999 1.5.2), not Schlick's approximation. cos_i is the
/// cosine of the angle of incidence in [0, 1]; eta_i, eta_t the refractive indices on the
/// incident and transmitted sides. Total internal reflection gives 1.
inline double fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const double sin_t = eta_i / eta_t * std::sqrt(std::max(0.0, 1 - cos_i * cos_i));
  if (sin_t >= 1) return 1;
  const double cos_t = std::sqrt(std::max(0.0, 1 - sin_t * sin_t));
  const double rs = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  const double rp = (eta_i * cos_t - eta_t * cos_i) / (eta_i * cos_t + eta_t * cos_i);
  return 0.5 * (rs * rs + rp * rp);
}

/// x^n for n >= 1 by repeated squaring, for the Phong highlight (a tenth of std::pow's
/// instructions). Each squaring doubles the relative error
/// before it, so the result is within about (n + log2 n) ulps of x^n (relative), e.g. 1e-13 for
/// n = 200, far below the 1/255 of a displayed code.
inline double integer_power(double x, unsigned n) {
  double result = 1;
  for (;;) {
    if (n & 1) result *= x;
    n >>= 1;
    if (n == 0) return result;
    x *= x;
  }
}

}  // namespace raycast
