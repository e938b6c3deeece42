#pragma once
// Dispersion (POV-Ray's interior `dispersion`): a refracting surface whose index of refraction
// depends on the wavelength splits white light into bands, each traced on its own path.
#include <algorithm>
#include <array>
#include <cmath>

#include "scene/material.h"

namespace raycast {

/// Bands a dispersive refraction is split into, at most.
inline constexpr int kMaxDispersionSamples = 64;

/// The index of refraction at spectral position `band` in [0, 1] (0 red, 1 violet): from
/// ior / sqrt(dispersion) to ior * sqrt(dispersion), geometric in between, so that violet's index
/// over red's is `dispersion` and the middle of the spectrum keeps `ior`.
inline double band_ior(double ior, double dispersion, double band) {
  return ior * std::pow(dispersion, band - 0.5);
}

/// The spectral position of band k of n (n >= 2): red to violet, evenly.
inline double band_position(int k, int n) { return double(k) / double(n - 1); }

/// The share of white light band k of n carries: the fully saturated hue of its position (red,
/// through yellow, green and blue, to violet at 270 degrees), each channel scaled so the n
/// shares sum to white (a channel no band carries is shared evenly).
inline std::array<Color, kMaxDispersionSamples> band_weights(int n) {
  std::array<Color, kMaxDispersionSamples> w{};
  Color sum{0, 0, 0};
  for (int k = 0; k < n; ++k) {
    const double h = 4.5 * band_position(k, n);  // hue in sixths of a turn, 0 to 270 degrees
    const auto channel = [h](double centre) {
      double d = std::abs(h - centre);
      d = std::min(d, 6 - d);
      return std::clamp(2 - d, 0.0, 1.0);  // HSV with S = V = 1
    };
    w[std::size_t(k)] = {channel(0), channel(2), channel(4)};
    sum += w[std::size_t(k)];
  }
  for (int k = 0; k < n; ++k)
    for (std::size_t c = 0; c < 3; ++c)
      w[std::size_t(k)][c] = sum[c] > 0 ? w[std::size_t(k)][c] / sum[c] : 1.0 / n;
  return w;
}

/// Whether refraction through m splits light into bands.
inline bool disperses(const Material& m) { return m.dispersion != 1 && m.dispersion_samples >= 2; }

}  // namespace raycast
