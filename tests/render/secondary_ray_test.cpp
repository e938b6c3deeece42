// Secondary rays leave the surface they start on (geometry/spawn.h), pinned on the case that
// once failed: a hit point computed exactly on the plane y = 0 has a zero error bound.
#include <gtest/gtest.h>

#include "geometry/plane.h"
#include "geometry/spawn.h"
#include "geometry/sphere.h"

namespace raycast {
namespace {

TEST(OffsetRayOrigin, ExactPointOnPlane_StillLeavesTheSurface) {
  const Plane plane = make_plane({0, 1, 0}, {0, 0, 0});
  const Ray down{{0, 1, 0}, {0.6, -0.8, 0}};
  LocalHit hit;
  ASSERT_TRUE(intersect(plane, down, hit));
  const SurfaceInfo si = surface(plane, down, hit);
  ASSERT_EQ(si.p.y, 0);  // exactly on the plane, zero error bound along the normal
  const Vec3 up{0.6, 0.8, 0};
  const Vec3 o = offset_ray_origin(si, up);
  EXPECT_GT(o.y, 0);
  EXPECT_FALSE(intersect(plane, {o, up}, hit)) << "t = " << hit.t;
  const Vec3 below = offset_ray_origin(si, down.d);  // continuing through, as a refracted ray
  EXPECT_LT(below.y, 0);
  EXPECT_FALSE(intersect(plane, {below, down.d}, hit)) << "t = " << hit.t;
}

TEST(OffsetRayOrigin, RandomSphereHits_NeverReHitTheSphereOutward) {
  const unsigned seed = 7;
  SCOPED_TRACE(seed);
  const Sphere sphere = make_sphere({0.3, -1.7, 2.2}, 1.3);
  std::uint64_t state = seed;
  auto uniform = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1p-53;
  };
  int tested = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o{uniform() * 8 - 4, uniform() * 8 - 4, uniform() * 8 - 4 + 10};
    const Ray r{o,
                Vec3{0.3, -1.7, 2.2} - o + Vec3{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5}};
    LocalHit hit;
    if (!intersect(sphere, r, hit)) continue;
    const SurfaceInfo si = surface(sphere, r, hit);
    const Vec3 mirror = r.d - 2 * dot(r.d, si.n) * si.n;
    LocalHit again;
    EXPECT_FALSE(intersect(sphere, {offset_ray_origin(si, mirror), mirror}, again)) << i;
    ++tested;
  }
  EXPECT_GT(tested, 1000);
}

}  // namespace
}  // namespace raycast
