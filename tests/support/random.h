#pragma once
// The one source of randomness of the tests: a seeded generator that any <random> distribution
// accepts, and the random points, directions and rays every test draws from it.
#include <cstdint>
#include <random>

#include "geometry/ray.h"
#include "math/vec3.h"

namespace raycast::testing {

/// A seeded 64-bit Mersenne twister (a UniformRandomBitGenerator) with the draws tests share.
class Rng {
 public:
  using result_type = std::mt19937_64::result_type;
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  static constexpr result_type min() { return std::mt19937_64::min(); }
  static constexpr result_type max() { return std::mt19937_64::max(); }
  result_type operator()() { return engine_(); }

  double uniform(double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(engine_);
  }
  /// A point of [-half, half]^3 (braced initialisation draws x, y, z in that order).
  Vec3 in_box(double half) {
    return {uniform(-half, half), uniform(-half, half), uniform(-half, half)};
  }
  /// A unit vector, uniform on the sphere.
  Vec3 direction() {
    std::normal_distribution<double> g;
    for (;;) {
      const Vec3 v{g(engine_), g(engine_), g(engine_)};
      const double l = length(v);
      if (l > 1e-6) return v / l;
    }
  }

 private:
  std::mt19937_64 engine_;
};

/// A ray from a random point of centre + [-from, from]^3 towards a random point of
/// centre + [-to, to]^3, with a direction of random length in [0.1, 10] (t is in units of d,
/// never of a unit vector, so this exercises the scaling); tmin 0, tmax infinity.
inline Ray random_ray(Rng& rng, double from, double to, const Vec3& centre = {}) {
  const Vec3 o = centre + rng.in_box(from);
  Vec3 d = centre + rng.in_box(to) - o;
  if (length_squared(d) == 0) d = {1, 0, 0};
  return {o, normalize(d) * rng.uniform(0.1, 10), 0, kInfinity};
}

}  // namespace raycast::testing
