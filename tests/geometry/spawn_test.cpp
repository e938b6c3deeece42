// A secondary ray started with offset_ray_origin (pbrt-v4 style error bounds, no epsilon) must
// never hit the convex (or planar) shape it leaves again.
#include "geometry/spawn.h"

#include <gtest/gtest.h>

#include <random>

#include "objects/object.h"
#include "shape_checks.h"
#include "support/objects.h"

namespace raycast {
namespace {

using testing::object_of;

// Shoots `cases` random rays at `o`; at every hit spawns a ray into the outer hemisphere (or,
// for an open planar surface, a random hemisphere) and counts the ones that hit `o` again.
int count_rehits(const Object& o, bool open, unsigned seed, int cases, double half) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  const Vec3 centre = bounds(o).centre();
  testing::Rng rng(seed);
  std::uniform_real_distribution<double> len(1e-3, 1e3);
  int rehits = 0, hits = 0;
  for (int i = 0; i < cases; ++i) {
    Ray ray = testing::random_ray(rng, half, half / 3);
    ray.o += centre;
    LocalHit h;
    if (!intersect(o, ray, h)) continue;
    ++hits;
    const SurfaceInfo si = surface(o, ray, h);
    Vec3 w = rng.direction();
    const bool outward = open ? (rng() & 1) != 0 : true;
    if ((dot(w, si.n) < 0) == outward) w = -w;
    if (dot(w, si.n) == 0) continue;
    const Ray spawned{offset_ray_origin(si, w), w * len(rng)};
    LocalHit again;
    if (intersect(o, spawned, again)) {
      ++rehits;
      if (rehits <= 3)
        ADD_FAILURE() << "re-hit at t = " << again.t << " case " << i << " seed " << seed;
    }
  }
  EXPECT_GT(hits, cases / 10) << "too few hits to mean anything";
  return rehits;
}

constexpr int kCases = 100000;

const Transform kPlacement = Transform::translate({1e3, -2.5, 7}) *
                             Transform::rotate({1, 2, 3}, 37) * Transform::scale({3, 0.5, 1.25});

TEST(Spawn, ZeroErrorPoint_StillLeavesTheSurface) {
  SurfaceInfo si;
  si.p = {0, 0, 0};
  si.n = {0, 0, 1};
  const Vec3 up = offset_ray_origin(si, {0, 0, 1});
  const Vec3 down = offset_ray_origin(si, {0, 0, -1});
  EXPECT_GT(up.z, 0);
  EXPECT_LT(down.z, 0);
  EXPECT_EQ(up.x, 0);
  // Pinned bug: one subnormal step off z = 0, divided by a direction of length 1.5, underflowed
  // to t = -0 and the box face at z = 0 was hit again.
  const Box b = make_box({-1, -1, 0}, {1, 1, 1});
  LocalHit h;
  EXPECT_FALSE(intersect(b, Ray{down, {0.3, 0.2, -1.5}}, h));
  si.p = {1, 0, 0};
  si.n = {1, 0, 0};
  EXPECT_EQ(offset_ray_origin(si, {1, 0, 0}).x, std::nextafter(1.0, 2.0));
}

TEST(Spawn, Sphere_NeverRehit) {
  EXPECT_EQ(count_rehits(object_of(make_sphere({0.3, -0.2, 0.1}, 1.7)), false, 1, kCases, 6), 0);
}

TEST(Spawn, FarAwayTransformedSphere_NeverRehit) {
  EXPECT_EQ(count_rehits(object_of(make_sphere({0, 0, 0}, 1), kPlacement), false, 2, kCases, 6), 0);
}

TEST(Spawn, BoxWithFaceThroughZero_NeverRehit) {
  EXPECT_EQ(count_rehits(object_of(make_box({-1, -0.5, 0}, {0, 0.5, 2})), false, 12, kCases, 6), 0);
  EXPECT_EQ(count_rehits(object_of(make_disk(2)), true, 13, kCases, 5), 0);
}

TEST(Spawn, Box_NeverRehit) {
  EXPECT_EQ(count_rehits(object_of(make_box({-1, -0.5, 0.25}, {1.5, 0.5, 2})), false, 3, kCases, 6),
            0);
}

TEST(Spawn, TransformedBox_NeverRehit) {
  EXPECT_EQ(
      count_rehits(object_of(make_box({-1, -1, -1}, {1, 1, 1}), kPlacement), false, 4, kCases, 6),
      0);
}

TEST(Spawn, Triangle_NeverRehit) {
  const Triangle t = make_triangle({-2, -1, 0.3}, {2, -1.5, -0.2}, {0.5, 2, 0.7});
  EXPECT_EQ(count_rehits(object_of(t), true, 5, kCases, 5), 0);
  EXPECT_EQ(count_rehits(object_of(t, kPlacement), true, 6, kCases, 5), 0);
}

TEST(Spawn, Parallelogram_NeverRehit) {
  const Parallelogram q = make_parallelogram({-1.5, -1, 0.2}, {3, 0.5, -0.3}, {0.2, 2.5, 0.6});
  EXPECT_EQ(count_rehits(object_of(q), true, 7, kCases, 5), 0);
  EXPECT_EQ(count_rehits(object_of(q, kPlacement), true, 8, kCases, 5), 0);
}

TEST(Spawn, Disk_NeverRehit) {
  EXPECT_EQ(count_rehits(object_of(make_disk(2, 0.5, 0.3, 300)), true, 9, kCases, 5), 0);
  EXPECT_EQ(count_rehits(object_of(make_disk({0.2, 0.1, -0.3}, {1, 2, 3}, 2)), true, 10, kCases, 5),
            0);
  EXPECT_EQ(count_rehits(object_of(make_disk(2), kPlacement), true, 11, kCases, 5), 0);
}

}  // namespace
}  // namespace raycast
