#include "load/formula_noise_registration.h"

#include "math/formula_noise.h"
#include "texture/noise.h"

namespace raycast {

namespace {

double noise_at(double x, double y, double z, int generator) {
  return texture::noise({x, y, z}, generator);
}

// A bound on each partial derivative of texture::noise. Inside a lattice cell the noise is a
// trilinear blend, by the fade of each coordinate's fraction, of the corners' gradient terms g.d;
// d/dx is fade'(fx) times the difference of the blends on the cell's two x faces, plus a convex
// combination of the gradients' x components (each at most 1). Generators 1 and 2: unit
// gradients, |g.d| <= sqrt(3), fade' <= 3/2, so 3/2 * 2 sqrt(3) + 1 = 6.20, scaled by 0.75: 4.65.
// Generator 3: edge gradients, |g.d| <= 2, fade' <= 15/8, so 15/8 * 4 + 1 = 8.5, scaled by 0.6:
// 5.1. The clamp to [0, 1] only flattens.
constexpr double kNoiseSlope = 5.1;

}  // namespace

void register_formula_noise() { set_formula_noise({&noise_at, kNoiseSlope}); }

}  // namespace raycast
