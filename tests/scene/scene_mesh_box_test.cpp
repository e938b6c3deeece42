// Scene's direct path for a scene of one mesh tests the mesh's box before is_valid and before the
// mesh: its answer must stay the general path's also where a slab product is 0 * inf = NaN (a ray
// lying in the plane of a box face, parallel to it, either sign of zero) and for invalid rays. A
// cube mesh has its faces on its box, so such rays graze or hit its triangles: the direct path
// must answer as the general path (the mesh beside a far sphere) does.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/mesh.h"
#include "scene/scene.h"
#include "support/random.h"

namespace raycast {
namespace {

std::shared_ptr<const Mesh> make_cube_mesh() {
  std::vector<Vec3f> p;
  for (int i = 0; i < 8; ++i)
    p.push_back({i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f});
  const std::vector<std::array<std::uint32_t, 3>> t{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                                    {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                                    {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return make_mesh(p, t);
}

TEST(Scene, SoleMeshBox_RaysInTheBoxFacesAnswerAsTheGeneralPath) {
  const auto mesh = make_cube_mesh();
  Object m;
  m.shape = MeshShape{mesh};
  Object far;
  far.shape = make_sphere({100, 100, 100}, 0.5);
  Scene sole, general;
  sole.objects = {m};
  general.objects = {m, far};
  sole.build();
  general.build();
  ASSERT_EQ(sole.sole_mesh(), 0);
  ASSERT_EQ(general.sole_mesh(), -1);
  testing::Rng rng(13);
  int hits = 0, misses = 0;
  for (int n = 0; n < 6000; ++n) {
    const int a = n % 3;
    Ray ray{rng.in_box(1.5), rng.in_box(1), 0, kInfinity};
    // On a face plane (or off the box on that axis), the direction parallel to it.
    const double planes[] = {-1, 1, 1.25, -1.25};
    ray.o[a] = planes[(n / 3) % 4];
    ray.d[a] = (n / 12) % 2 ? -0.0 : 0.0;
    if (n % 5 == 1) ray.tmax = rng.uniform(0.1, 2);
    if (n % 7 == 2) ray.tmin = -rng.uniform(0, 2);
    // A second axis on a face plane too (an edge of the box) now and then.
    if (n % 11 == 3) {
      const int b = (a + 1) % 3;
      ray.o[b] = planes[(n / 5) % 2];
      ray.d[b] = (n / 7) % 2 ? -0.0 : 0.0;
    }
    if (n % 97 == 5) ray.tmin = std::numeric_limits<double>::quiet_NaN();
    if (n % 89 == 6) ray.o.y = std::numeric_limits<double>::quiet_NaN();
    SceneHit hs, hg;
    const bool fs = sole.intersect(ray, hs), fg = general.intersect(ray, hg);
    ASSERT_EQ(fs, fg) << n;
    if (fs) {
      ++hits;
      EXPECT_EQ(hs.local.t, hg.local.t) << n;
      EXPECT_EQ(hs.local.part, hg.local.part) << n;
    } else {
      ++misses;
    }
    EXPECT_EQ(sole.occluded(ray), general.occluded(ray)) << n;
  }
  EXPECT_GT(hits, 500);  // the rays do reach the faces
  EXPECT_GT(misses, 500);
}

}  // namespace
}  // namespace raycast
