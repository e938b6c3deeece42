// Secondary rays leave the quadric family's convex solids without re-hitting them: the spawn
// offset (geometry/spawn.h) must exceed each shape's reported error bound on the hit point.
#include <gtest/gtest.h>

#include "geometry/cone.h"
#include "geometry/cylinder.h"
#include "geometry/ellipsoid.h"
#include "geometry/polyhedron.h"
#include "geometry/quadric.h"
#include "geometry/slab.h"
#include "geometry/spawn.h"
#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

// For random hits, rays spawned into the outer hemisphere must not hit the convex shape again.
// Returns the number of re-hits.
template <class S>
int rehits(const S& s, std::uint64_t seed, double extent) {
  Rng rng(seed);
  int bad = 0, hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = testing::random_ray(rng, 2 * extent, extent);
    LocalHit h;
    if (!intersect(s, ray, h)) continue;
    ++hits;
    const SurfaceInfo si = surface(s, ray, h);
    Vec3 w = rng.direction();
    if (dot(w, si.n) < 0) w = -w;
    const Ray out{offset_ray_origin(si, w), w};
    LocalHit again;
    if (intersect(s, out, again)) ++bad;
  }
  EXPECT_GT(hits, 300);
  return bad;
}

TEST(QuadricSpawn, OutgoingRays_NeverRehitConvexSolids) {
  EXPECT_EQ(rehits(make_ellipsoid({0.1, 0.2, -0.3}, {1, 0.3, 0.6}), 1, 1), 0);
  EXPECT_EQ(rehits(make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 0.3, 0.6)), 2, 1), 0);
  EXPECT_EQ(rehits(make_quadric(quadric_of_kind(QuadricKind::kCylinder, 0.5, 0.7, 1),
                                Aabb{{-1, -1, -1}, {1, 1, 1}}),
                   3, 1),
            0);
  EXPECT_EQ(rehits(make_cylinder(0.6, -0.5, 0.8), 4, 1), 0);
  EXPECT_EQ(rehits(make_cylinder({0.3, -0.2, -0.5}, {-0.4, 0.5, 0.6}, 0.4), 5, 1), 0);
  EXPECT_EQ(rehits(make_cone(0.7, 1.2), 6, 1), 0);
  EXPECT_EQ(rehits(make_slab({0.2, 1, -0.4}, -0.3, 0.2), 7, 1), 0);
  EXPECT_EQ(rehits(make_polyhedron({{1, 1, 1, -1},
                                    {-1, 0.2, 0.1, -0.8},
                                    {0.1, -1, 0.3, -0.7},
                                    {0.2, 0.1, -1, -0.9},
                                    {0.5, 0.5, -0.3, -1}}),
                   8, 1),
            0);
}

}  // namespace
}  // namespace raycast
