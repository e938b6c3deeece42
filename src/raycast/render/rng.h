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
  explicit Rng(std::uint64_t seed) { seed_from(seed); }
  /// The generator for pixel (x, y) of a render with the scene's `seed`: Rng(mix64(key) ^
  /// mix64(golden + seed)) with key = x << 32 | y. The seeding (four mix64 and two steps, about
  /// 50 instructions) waits for the first draw: most pixels of a Whitted render with point lights
  /// and one sample draw nothing. The numbers drawn are the same either way.
  static Rng for_pixel(int x, int y, unsigned seed) {
    Rng r;
    r.state_ = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
    r.salt_ = seed;
    r.pending_ = true;
    return r;
  }

  std::uint32_t next() {
    if (pending_) [[unlikely]]
      start();
    return step();
  }
  /// Uniform in [0, 1): 32 random bits scaled, never 1.
  double uniform() { return next() * 0x1p-32; }

 private:
  Rng() = default;
  void seed_from(std::uint64_t seed) {
    state_ = 0;
    step();
    state_ += mix64(seed);
    step();
  }
  // for_pixel's seeding, at the first draw (state_ holds the pixel's key until then).
  void start() {
    pending_ = false;
    seed_from(mix64(state_) ^ mix64(0x9e3779b97f4a7c15ull + salt_));
  }
  std::uint32_t step() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + kIncrement;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
  }

  static constexpr std::uint64_t kIncrement = 1442695040888963407ull;
  std::uint64_t state_ = 0;
  unsigned salt_ = 0;
  bool pending_ = false;
};

}  // namespace raycast
