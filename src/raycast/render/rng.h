#pragma once
// A small, fast, seedable generator (PCG32, O'Neill 2014) and the per-pixel seeding that makes
// renders independent of the thread count.
#include <cstdint>

namespace raycast {

/// SplitMix64's finaliser (Steele et al. 2014): a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    state_ = 0;
    next();
    state_ += mix64(seed);
    next();
  }
  /// The generator for pixel (x, y) of a render with the scene's `seed`.
  static Rng for_pixel(int x, int y, unsigned seed) {
    const std::uint64_t key = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
    return Rng(mix64(key) ^ mix64(0x9e3779b97f4a7c15ull + seed));
  }

  std::uint32_t next() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + kIncrement;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
  }
  /// Uniform in [0, 1): 32 random bits scaled, never 1.
  double uniform() { return next() * 0x1p-32; }

 private:
  static constexpr std::uint64_t kIncrement = 1442695040888963407ull;
  std::uint64_t state_;
};

}  // namespace raycast
