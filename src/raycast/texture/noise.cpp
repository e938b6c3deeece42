#include "texture/noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace raycast::texture {

namespace {

constexpr int kTable = 256;

// A permutation of 0..255 by a Fisher-Yates shuffle driven by a fixed 64-bit LCG (Knuth's MMIX
// constants), so that the noise is the same on every run and machine.
struct LatticeTables {
  std::array<std::uint8_t, 2 * kTable> perm{};
  std::array<Vec3, kTable> gradients{};  // random unit vectors for generators 1 and 2
  // Three more per entry, one per component of the vector noise.
  std::array<std::array<Vec3, 3>, kTable> vector_gradients{};

  LatticeTables() {
    std::uint64_t state = 0x5eed1234abcdULL;
    auto next = [&]() {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return state >> 11;
    };
    std::array<int, kTable> p{};
    for (int i = 0; i < kTable; ++i) p[std::size_t(i)] = i;
    for (int i = kTable - 1; i > 0; --i)
      std::swap(p[std::size_t(i)], p[next() % std::uint64_t(i + 1)]);
    for (int i = 0; i < 2 * kTable; ++i)
      perm[std::size_t(i)] = std::uint8_t(p[std::size_t(i % kTable)]);
    for (Vec3& g : gradients) g = random_direction(next);
    for (auto& gs : vector_gradients)
      for (Vec3& g : gs) g = random_direction(next);
  }

  // Rejection sampling in the unit ball, then normalised: a uniform direction.
  template <class Next>
  static Vec3 random_direction(Next& next) {
    for (int tries = 0; tries < 1000; ++tries) {
      const double scale = 1.0 / double(1ULL << 53);
      const Vec3 v{2 * double(next()) * scale - 1, 2 * double(next()) * scale - 1,
                   2 * double(next()) * scale - 1};
      const double l2 = dot(v, v);
      if (l2 > 1e-4 && l2 <= 1) return v / std::sqrt(l2);
    }
    return {1, 0, 0};
  }
};

// Built at start-up (a namespace-scope constant: no guard on every noise call).
const LatticeTables kTables;
const LatticeTables& tables() { return kTables; }

// The lattice cell of a coordinate: its floor (wrapped to the table) and the fraction.
struct Cell {
  int i;
  double f;
};
inline Cell cell(double v) {
  const double fl = std::floor(v);
  // The table repeats every 256 cells: the floor modulo 256. In the range of a 64-bit integer
  // its low bits are that (two's complement), without the division; beyond, exact for any
  // finite double.
  if (std::abs(fl) < 0x1p62) [[likely]]
    return {int(static_cast<std::int64_t>(fl) & (kTable - 1)), v - fl};
  const double wrapped = fl - 256.0 * std::floor(fl / 256.0);
  return {int(wrapped) & (kTable - 1), v - fl};
}

// Perlin 2002: the gradient of a corner picked from the twelve cube edges (with four repeats to
// make sixteen) by the low four bits of its hash, dotted with the offset.
inline double edge_gradient(int hash, double x, double y, double z) {
  const int h = hash & 15;
  const double u = h < 8 ? x : y;
  const double v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

inline double cubic_fade(double s) { return s * s * (3 - 2 * s); }
inline double quintic_fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// The lattice noise of one kind at p: the eight corners of p's cell, each given by
// corner(hash, offset from the corner) (a number, or a vector of them), blended with the fade's
// weights along x, then y, then z.
template <class Fade, class Corner>
auto blend_corners(const Vec3& p, Fade fade, Corner corner) {
  const auto& perm = tables().perm;
  const Cell cx = cell(p.x), cy = cell(p.y), cz = cell(p.z);
  const double u = fade(cx.f), v = fade(cy.f), w = fade(cz.f);
  auto at = [&](int a, int b, int c) {
    const int hash =
        perm[std::size_t(perm[std::size_t(perm[std::size_t(cx.i + a)] + cy.i + b)] + cz.i + c)];
    return corner(hash, cx.f - a, cy.f - b, cz.f - c);
  };
  auto mix = [](double s, const auto& a0, const auto& a1) { return a0 + s * (a1 - a0); };
  const auto x00 = mix(u, at(0, 0, 0), at(1, 0, 0));
  const auto x10 = mix(u, at(0, 1, 0), at(1, 1, 0));
  const auto x01 = mix(u, at(0, 0, 1), at(1, 0, 1));
  const auto x11 = mix(u, at(0, 1, 1), at(1, 1, 1));
  return mix(w, mix(v, x00, x10), mix(v, x01, x11));
}

double improved_noise(const Vec3& p) {  // about [-1, 1]
  return blend_corners(p, quintic_fade, edge_gradient);
}

double lattice_noise(const Vec3& p) {  // within [-sqrt(3)/2, sqrt(3)/2]
  return blend_corners(p, cubic_fade, [](int hash, double x, double y, double z) {
    const Vec3& g = tables().gradients[std::size_t(hash)];
    return g.x * x + g.y * y + g.z * z;
  });
}

// The three components of the vector noise share the lattice cell, the fade weights and the
// corner hashes (as POV-Ray's DNoise does); only the gradients differ, so one call costs little
// more than one scalar noise.
Vec3 lattice_vector_noise(const Vec3& p) {
  return blend_corners(p, cubic_fade, [](int hash, double x, double y, double z) {
    const auto& g = tables().vector_gradients[std::size_t(hash)];
    return Vec3{g[0].x * x + g[0].y * y + g[0].z * z, g[1].x * x + g[1].y * y + g[1].z * z,
                g[2].x * x + g[2].y * y + g[2].z * z};
  });
}

// Improved noise's vector form: the component k takes the edge gradient of the corner's hash
// passed k more times through the permutation.
Vec3 improved_vector_noise(const Vec3& p) {
  return blend_corners(p, quintic_fade, [](int h0, double x, double y, double z) {
    const auto& perm = tables().perm;
    const int h1 = perm[std::size_t(h0)], h2 = perm[std::size_t(h1)];
    return Vec3{edge_gradient(h0, x, y, z), edge_gradient(h1, x, y, z), edge_gradient(h2, x, y, z)};
  });
}

}  // namespace

double noise(const Vec3& p, int generator) {
  if (!is_finite(p)) return 0.5;
  // Scaled so that the values seen in practice spread over [0, 1] (both kinds rarely reach
  // beyond 0.8 of their bound), then clamped.
  const double n = generator >= 3 ? 0.6 * improved_noise(p) : 0.75 * lattice_noise(p);
  return std::clamp(0.5 + n, 0.0, 1.0);
}

Vec3 vector_noise(const Vec3& p, int generator) {
  if (!is_finite(p)) return {0, 0, 0};
  const Vec3 n = generator >= 3 ? 0.6 * improved_vector_noise(p) : 0.75 * lattice_vector_noise(p);
  return {std::clamp(2 * n.x, -1.0, 1.0), std::clamp(2 * n.y, -1.0, 1.0),
          std::clamp(2 * n.z, -1.0, 1.0)};
}

Vec3 turbulence_offset(const Vec3& p, const Turbulence& t, int generator) {
  Vec3 sum{0, 0, 0};
  double weight = 1, frequency = 1;
  const int octaves = std::clamp(t.octaves, 1, 10);
  for (int i = 0; i < octaves; ++i) {
    sum += weight * vector_noise(frequency * p, generator);
    weight *= t.omega;
    frequency *= t.lambda;
  }
  return {sum.x * t.amount.x, sum.y * t.amount.y, sum.z * t.amount.z};
}

double turbulence_value(const Vec3& p, int octaves, double omega, double lambda, int generator) {
  double sum = 0, weight = 1, frequency = 1;
  octaves = std::clamp(octaves, 1, 10);
  for (int i = 0; i < octaves; ++i) {
    sum += weight * std::abs(2 * noise(frequency * p, generator) - 1);
    weight *= omega;
    frequency *= lambda;
  }
  return sum;
}

}  // namespace raycast::texture
