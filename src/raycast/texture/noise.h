#pragma once
// Solid noise for the texture patterns (docs/textures.md "Noise"): gradient noise on the integer
// lattice, in two kinds after POV-Ray's noise_generator: 1 and 2, a lattice gradient noise with
// random unit gradients and the cubic fade 3t^2 - 2t^3; 3, Perlin's improved noise (Perlin 2002,
// "Improving Noise": twelve edge gradients and the quintic fade 6t^5 - 15t^4 + 10t^3).
#include "math/vec3.h"

namespace raycast::texture {

/// Noise at p in [0, 1], 0.5 at every lattice point; continuous (C1 for generators 1 and 2, C2
/// for 3). Non-finite coordinates give 0.5.
double noise(const Vec3& p, int generator);

/// A vector of three noises at p, each in [-1, 1] (POV-Ray's DNoise: the direction turbulence
/// pushes a point): one lattice cell, three independent sets of gradients.
Vec3 vector_noise(const Vec3& p, int generator);

/// The parameters of turbulence: the amount per axis and the octave sum's shape.
struct Turbulence {
  Vec3 amount{0, 0, 0};
  int octaves = 6;      // 1 to 10
  double omega = 0.5;   // each octave's weight against the one before
  double lambda = 2.0;  // each octave's frequency against the one before
  bool any() const { return amount.x != 0 || amount.y != 0 || amount.z != 0; }
};

/// The displacement turbulence gives p: sum over octaves i of omega^i * vector_noise(lambda^i p),
/// times the amount per axis. Each component is bounded by |amount| * (1 - omega^octaves) /
/// (1 - omega) (omega < 1).
Vec3 turbulence_offset(const Vec3& p, const Turbulence& t, int generator);

/// Scalar turbulence: sum over octaves of omega^i * |2 noise(lambda^i p) - 1|, in
/// [0, (1 - omega^octaves) / (1 - omega)] (omega < 1).
double turbulence_value(const Vec3& p, int octaves, double omega, double lambda, int generator);

}  // namespace raycast::texture
