// Scene's direct path for a scene of one mesh tests the mesh's box before is_valid and before the
// mesh: its answer must stay the general path's also where a slab product is 0 * inf = NaN (a ray
// lying in the plane of a box face, parallel to it, either sign of zero) and for invalid rays. A
// cube mesh has its faces on its box, so such rays graze or hit its triangles: the direct path
// must answer as the general path (the mesh beside a far sphere) does.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
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

// The cube alone (Scene's direct path for one mesh) and beside a far sphere (the general path).
void build_sole_and_general(Scene& sole, Scene& general) {
  Object m;
  m.shape = MeshShape{make_cube_mesh()};
  Object far;
  far.shape = make_sphere({100, 100, 100}, 0.5);
  sole.objects = {m};
  general.objects = {m, far};
  sole.build();
  general.build();
}

// Expects both scenes' nearest hit and shadow answer to agree on `ray` (number n); returns
// whether the nearest query hit.
bool expect_same_answers(const Scene& sole, const Scene& general, const Ray& ray, int n) {
  SceneHit hs, hg;
  const bool fs = sole.intersect(ray, hs), fg = general.intersect(ray, hg);
  EXPECT_EQ(fs, fg) << n;
  if (fs && fg) {
    EXPECT_EQ(hs.local.t, hg.local.t) << n;
    EXPECT_EQ(hs.local.part, hg.local.part) << n;
  }
  EXPECT_EQ(sole.occluded(ray), general.occluded(ray)) << n;
  return fs;
}

TEST(Scene, SoleMeshBox_RaysInTheBoxFacesAnswerAsTheGeneralPath) {
  Scene sole, general;
  build_sole_and_general(sole, general);
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
    ++(expect_same_answers(sole, general, ray, n) ? hits : misses);
  }
  EXPECT_GT(hits, 500);  // the rays do reach the faces
  EXPECT_GT(misses, 500);
}

// Rays that start inside the mesh's box (or on its faces) with tmin <= 0 <= tmax skip the box
// test (they always meet the box). The box test only culls, so the skip cannot lose a hit; what
// this guards is the rest of the direct path for those rays (the validity check still made:
// infinite, zero or tiny directions, NaN tmax) and the rays beside them that take the test (tmin >
// 0, tmax < 0, an origin just outside a face): the answer must stay the general path's.
TEST(Scene, SoleMeshBox_RaysFromInsideTheBoxAnswerAsTheGeneralPath) {
  Scene sole, general;
  build_sole_and_general(sole, general);
  testing::Rng rng(29);
  int hits = 0, misses = 0;
  for (int n = 0; n < 8000; ++n) {
    Ray ray{rng.in_box(n % 4 == 0 ? 1.0 : 0.999), rng.in_box(1), 0, kInfinity};
    if (n % 6 == 1) ray.o[n % 3] = (n / 6) % 2 ? 1.0 : -1.0;  // on a face
    if (n % 13 == 2)
      ray.o[n % 3] = std::nextafter((n / 13) % 2 ? 1.0 : -1.0, 2.0 * ((n / 13) % 2) - 1);
    switch (n % 5) {
      case 1:
        ray.tmax = rng.uniform(0, 1);
        break;
      case 2:
        ray.tmin = -rng.uniform(0, 3);
        break;
      case 3:
        ray.tmin = rng.uniform(0, 1.5);
        break;  // tmin > 0: the box test
      case 4:
        ray.tmin = -rng.uniform(1, 3), ray.tmax = -rng.uniform(0, 1);
        break;
      default:
        break;
    }
    if (n % 97 == 5) ray.tmax = std::numeric_limits<double>::quiet_NaN();
    if (n % 89 == 6) ray.d.z = std::numeric_limits<double>::infinity();
    if (n % 83 == 7) ray.d = {0, 0, 0};
    if (n % 79 == 8) ray.d = ray.d * 1e-160;  // |d|^2 subnormal: not is_valid, yet traceable
    ++(expect_same_answers(sole, general, ray, n) ? hits : misses);
  }
  EXPECT_GT(hits, 3000);
  EXPECT_GT(misses, 1000);
}

}  // namespace
}  // namespace raycast
