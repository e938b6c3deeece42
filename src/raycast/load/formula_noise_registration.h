#pragma once
// Hands texture/'s solid noise to math/'s formulas (math/formula_noise.h): the loaders link both
// layers, math/ may not include texture/.

namespace raycast {

/// Registers texture::noise for the formulas' noise1, noise2 and noise3. Idempotent.
void register_formula_noise();

}  // namespace raycast
