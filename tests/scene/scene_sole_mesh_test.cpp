// A scene of one untransformed mesh takes Scene's direct path (its box, then the mesh, without
// the walk over objects): the same answers as the general path, which a second, far-away object
// forces on the same mesh. Random rays, rays that end at or just before their hit, rays aimed at
// the mesh's vertices and edge midpoints, shadow rays leaving the surface, and invalid rays.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "geometry/spawn.h"
#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "scene/scene.h"
#include "support/random.h"

namespace raycast {
namespace {

struct ScenePair {
  Scene sole, general;
};

// `sole`: the mesh (plus, when asked, an object with empty bounds, which the direct path
// ignores); `general`: the mesh and a far sphere.
ScenePair make_scenes(const std::shared_ptr<const Mesh>& mesh, bool with_empty) {
  ScenePair s;
  Object m;
  m.shape = MeshShape{mesh};
  if (with_empty) {
    Object empty;
    empty.shape = MeshShape{make_mesh({}, {})};
    s.sole.objects.push_back(empty);
  }
  s.sole.objects.push_back(m);
  Object far;
  far.shape = make_sphere({100, 100, 100}, 0.5);
  s.general.objects = {m, far};
  s.sole.build();
  s.general.build();
  return s;
}

void expect_same(const ScenePair& s, const Ray& ray, int n, int& hits) {
  SceneHit a, b;
  const bool fa = s.sole.intersect(ray, a), fb = s.general.intersect(ray, b);
  ASSERT_EQ(fa, fb) << n;
  if (fa) {
    ++hits;
    EXPECT_EQ(a.local.t, b.local.t) << n;
    EXPECT_EQ(a.local.prim, b.local.prim) << n;
    EXPECT_EQ(a.local.part, b.local.part) << n;
    EXPECT_EQ(a.local.a, b.local.a) << n;
    EXPECT_EQ(a.local.b, b.local.b) << n;
    EXPECT_EQ(s.sole.objects[a.object].shape.index(), s.general.objects[b.object].shape.index());
  }
  EXPECT_EQ(s.sole.occluded(ray), s.general.occluded(ray)) << n;
}

TEST(Scene, SoleMesh_AnswersAsTheGeneralPath) {
  const TriangleSoup soup = make_octa_sphere(24, 1.0, {0.2, -0.1, 0.3});
  const auto mesh = make_mesh(soup.positions, soup.triangles);
  for (bool with_empty : {false, true}) {
    const ScenePair s = make_scenes(mesh, with_empty);
    testing::Rng rng(91);
    int hits = 0, n = 0;
    for (; n < 3000; ++n) {
      Ray ray = testing::random_ray(rng, 3, 1.5);
      if (n % 2 == 1) ray.tmax = rng.uniform(0.05, 3.0);
      if (n % 7 == 4) ray.tmin = -rng.uniform(0, 2);
      if (n % 10 == 3) ray.d[n % 3] = 0;
      if (n % 50 == 9) ray.d.y = std::numeric_limits<double>::quiet_NaN();
      if (n % 50 == 19) ray.o.x = std::numeric_limits<double>::infinity();
      expect_same(s, ray, n, hits);
      SceneHit h;
      if (!s.general.intersect(ray, h)) continue;
      // The same ray ending exactly at its hit, one step before it, and one after.
      for (double tmax : {h.local.t, std::nextafter(h.local.t, 0.0), h.local.t * (1 + 1e-9)}) {
        Ray r = ray;
        r.tmax = tmax;
        expect_same(s, r, n, hits);
      }
      // A shadow ray leaving the surface (offset by its error bound) towards a light.
      const SurfaceInfo si = s.general.surface(ray, h);
      const Vec3 light{4, 5, 6};
      const Vec3 p = offset_ray_origin(si, light - si.p);
      expect_same(s, Ray{p, light - p, 0, 1}, n, hits);
    }
    // Rays aimed at every vertex and edge midpoint of the mesh.
    for (std::size_t i = 0; i < soup.triangles.size(); i += 3) {
      const auto& t = soup.triangles[i];
      const Vec3 v0(soup.positions[t[0]]), v1(soup.positions[t[1]]);
      for (const Vec3& target : {v0, 0.5 * (v0 + v1)}) {
        const Vec3 o = rng.in_box(4) + Vec3{0, 0, 6};
        expect_same(s, Ray{o, target - o, 0, kInfinity}, n++, hits);
        expect_same(s, Ray{o, target - o, 0, 1}, n++, hits);
      }
    }
    EXPECT_GT(hits, 1000);  // the rays do reach the mesh
  }
}

// Scenes the direct path must not take: a transformed mesh, a mesh beside an unbounded plane, two
// meshes. They answer as before (checked against the mesh's own query in object space).
TEST(Scene, SoleMesh_NotTakenWhenTheSceneIsMore) {
  const TriangleSoup soup = make_octa_sphere(12, 0.0);
  const auto mesh = make_mesh(soup.positions, soup.triangles);
  Object moved;
  moved.shape = MeshShape{mesh};
  moved.xf = Transform::translate({0.5, 0, 0});
  Object plane;
  plane.shape = make_plane({0, 1, 0}, {0, -5, 0});
  Object still;
  still.shape = MeshShape{mesh};
  Scene a, b;
  a.objects = {moved};
  b.objects = {still, plane};
  a.build();
  b.build();
  const Ray ray{{0.5, 0.1, 5}, {0, 0, -1}, 0, kInfinity};
  SceneHit h;
  LocalHit own;
  ASSERT_TRUE(a.intersect(ray, h));
  ASSERT_TRUE(intersect(*mesh, Ray{{0, 0.1, 5}, {0, 0, -1}, 0, kInfinity}, own));
  EXPECT_EQ(h.local.t, own.t);
  EXPECT_EQ(h.local.prim, own.prim);
  ASSERT_TRUE(b.intersect(ray, h));
  ASSERT_TRUE(intersect(*mesh, ray, own));
  EXPECT_EQ(h.object, 0);
  EXPECT_EQ(h.local.t, own.t);
  ASSERT_TRUE(b.intersect(Ray{{3, 0, 0}, {0, -1, 0}, 0, kInfinity}, h));
  EXPECT_EQ(h.object, 1);  // the plane, which a sole-mesh path would miss
  EXPECT_TRUE(b.occluded(Ray{{3, 0, 0}, {0, -1, 0}, 0, kInfinity}));
}

}  // namespace
}  // namespace raycast
