#pragma once
// Solid noise in formulas (noise1, noise2, noise3: POV-Ray's noise generators). The noise itself
// belongs to texture/, a layer math/ may not reach: the scene loaders, which link both, register
// it here once before they compile formulas (load/formula_noise_registration.cpp). Formulas that
// name noise before then are refused when compiled.
#include <algorithm>
#include <cmath>

#include "math/dual.h"
#include "math/interval.h"

namespace raycast {

/// The registered noise: `value` in [0, 1], and `slope`, a bound on the magnitude of each of its
/// partial derivatives everywhere (its Lipschitz constant per axis), from which the inclusions
/// over intervals and the derivatives' inclusions follow.
struct FormulaNoise {
  double (*value)(double x, double y, double z, int generator) = nullptr;
  double slope = 0;
};

void set_formula_noise(const FormulaNoise& noise);
const FormulaNoise& formula_noise();

inline double noise_of(double x, double y, double z, int generator) {
  const FormulaNoise& n = formula_noise();
  return n.value ? n.value(x, y, z, generator) : 0.5;
}

/// Over a box: the value at its centre, give or take the slope times the half widths (within
/// [0, 1]).
inline Interval noise_of(const Interval& x, const Interval& y, const Interval& z, int generator) {
  if (x.is_empty() || y.is_empty() || z.is_empty()) return Interval::empty();
  const double reach =
      formula_noise().slope * 0.5 * ((x.hi - x.lo) + (y.hi - y.lo) + (z.hi - z.lo));
  if (!(reach < 1)) return {0, 1};  // also infinite or NaN widths
  const double c = noise_of(x.mid(), y.mid(), z.mid(), generator);
  const Interval r = interval_detail::widen(c - reach, c + reach, 4);
  return {std::max(r.lo, 0.0), std::min(r.hi, 1.0)};
}

/// At a point: the partial derivatives by central differences (for normals and Newton steps).
template <int N>
Dual<double, N> noise_of(const Dual<double, N>& x, const Dual<double, N>& y,
                         const Dual<double, N>& z, int generator) {
  Dual<double, N> r(noise_of(x.v, y.v, z.v, generator));
  const double p[3] = {x.v, y.v, z.v};
  const Dual<double, N>* a[3] = {&x, &y, &z};
  for (int i = 0; i < 3; ++i) {
    const double h = 1e-6 * (1 + std::abs(p[i]));
    double lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
    lo[i] -= h;
    hi[i] += h;
    const double g =
        (noise_of(hi[0], hi[1], hi[2], generator) - noise_of(lo[0], lo[1], lo[2], generator)) /
        (2 * h);
    for (int k = 0; k < N; ++k) r.d[k] += g * a[i]->d[k];
  }
  return r;
}

/// Over a box: each partial derivative within [-slope, slope].
template <int N>
Dual<Interval, N> noise_of(const Dual<Interval, N>& x, const Dual<Interval, N>& y,
                           const Dual<Interval, N>& z, int generator) {
  Dual<Interval, N> r(noise_of(x.v, y.v, z.v, generator));
  const double s = formula_noise().slope;
  const Interval g{-s, s};
  for (int k = 0; k < N; ++k) r.d[k] = g * x.d[k] + g * y.d[k] + g * z.d[k];
  return r;
}

}  // namespace raycast
