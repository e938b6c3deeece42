// Secondary rays leaving an algebraic surface must not find it again at once: the heart's rim
// showed dark shadow-acne pixels while p_error did not cover the root's own error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/algebraic.h"
#include "geometry/clipped_solid.h"
#include "geometry/spawn.h"
#include "support/random.h"

namespace raycast {
namespace {

TEST(AlgebraicSpawn, Heart_SpawnedRaysDoNotRehit) {
  const Algebraic heart = make_algebraic("(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3",
                                         {{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}}, false);
  testing::Rng rng(5);
  SCOPED_TRACE("seed 5");
  constexpr double kNear = 1e-7;
  int hits = 0, rehits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 target = 0.8 * rng.direction();
    const Vec3 o = target + 5.0 * rng.direction();
    const Ray ray{o, target - o};
    LocalHit hit;
    if (!intersect(heart, ray, hit) || hit.part >= kFacePart) continue;
    ++hits;
    const SurfaceInfo si = surface(heart, ray, hit);
    Vec3 w = rng.direction();
    if (dot(w, si.n) < 0) w = -w;
    LocalHit again;
    if (intersect(heart, Ray{offset_ray_origin(si, w), w}, again) && again.t < kNear) ++rehits;
  }
  EXPECT_GT(hits, 10000);
  // The heart's equator is a singular curve (f has a triple root there, its gradient vanishes),
  // where roots are only good to about eps^(1/3): a residue of re-hits remains there (20 of
  // ~10^4 with this seed; 409 before the error bound and the tmin rule). Pin it below 0.5%.
  EXPECT_LE(rehits * 200, hits) << rehits << " re-hits of " << hits;
}

}  // namespace
}  // namespace raycast
