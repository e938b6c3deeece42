// Batches of rays through the packet path (scene/ray_batch.h) against the single-ray queries:
// every answer equal field for field, on a mix of coherent camera rows (packets), scattered rays,
// rays aimed at shared vertices and edges, invalid rays and a short tail.
#include "scene/ray_batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "support/random.h"

namespace raycast {
namespace {

Scene mesh_scene(int objects) {
  Scene scene;
  for (int i = 0; i < objects; ++i) {
    const TriangleSoup soup = make_octa_sphere(24, 0.05, {1.5 * i, 0, 0});
    Object o;
    o.shape = MeshShape{make_mesh(soup.positions, soup.triangles)};
    scene.objects.push_back(std::move(o));
  }
  scene.build();
  return scene;
}

// Rows of a pinhole camera's rays (coherent), with scattered and special rays between them.
std::vector<Ray> mixed_rays(testing::Rng& rng, const TriangleSoup& soup) {
  std::vector<Ray> rays;
  const Vec3 eye{0.3, 0.4, 4};
  for (int row = 0; row < 40; ++row) {
    for (int i = 0; i < 101; ++i) {  // not a multiple of 8: runs start anywhere
      const double x = -0.3 + 0.6 * i / 100.0, y = -0.35 + 0.7 * row / 39.0;
      rays.push_back(Ray{eye, Vec3{x - 0.3 * 0.1, y - 0.04, -1}});
    }
    if (row % 3 == 0) rays.push_back(random_ray(rng, 3, 0.5));     // scattered
    if (row % 5 == 0) rays.push_back(Ray{eye, {0, 0, -1}, 2, 1});  // empty [tmin, tmax]
    if (row % 4 == 0) {  // eight rays from one origin at shared vertices and edge points
      for (int l = 0; l < 8; ++l) {
        const auto& t = soup.triangles[rng.uniform(0, 1) * (soup.triangles.size() - 1)];
        const Vec3 a = Vec3(soup.positions[t[0]]), b = Vec3(soup.positions[t[1]]);
        rays.push_back(Ray{eye, (l % 2 ? a : a + 0.5 * (b - a)) - eye});
      }
    }
    if (row % 7 == 0) rays.push_back(Ray{eye, {0, 0, -1}, 0, 3.5});  // stops short
  }
  rays.push_back(random_ray(rng, 3, 0.5));  // a tail shorter than a packet
  rays.push_back(Ray{eye, {0.01, 0, -1}});
  return rays;
}

void expect_batch_equals_single(const Scene& scene, const std::vector<Ray>& rays) {
  std::vector<SceneHit> hits(rays.size());
  std::vector<std::uint8_t> found(rays.size());
  intersect_batch(scene, rays, hits, found);
  int hit_count = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    SceneHit one;
    const bool f = scene.intersect(rays[i], one);
    ASSERT_EQ(found[i] != 0, f) << "ray " << i;
    EXPECT_EQ(hits[i].object, one.object) << "ray " << i;
    if (!f) continue;
    ++hit_count;
    EXPECT_EQ(hits[i].local.t, one.local.t) << "ray " << i;
    EXPECT_EQ(hits[i].local.prim, one.local.prim) << "ray " << i;
    EXPECT_EQ(hits[i].local.part, one.local.part) << "ray " << i;
    EXPECT_EQ(hits[i].local.a, one.local.a) << "ray " << i;
    EXPECT_EQ(hits[i].local.b, one.local.b) << "ray " << i;
  }
  EXPECT_GT(hit_count, static_cast<int>(rays.size() / 4));
}

TEST(RayBatch, OneMesh_PacketsEqualSingleRays) {
  testing::Rng rng(8);
  const Scene scene = mesh_scene(1);
  ASSERT_EQ(scene.sole_mesh(), 0);
  const std::vector<Ray> rays = mixed_rays(rng, make_octa_sphere(24, 0.05));
  // The camera rows do go as packets.
  EXPECT_TRUE(coherent_rays(rays.data(), 8, 2.0));
  expect_batch_equals_single(scene, rays);
}

TEST(RayBatch, MeshBesideAnEmptyBox_PacketsEqualSingleRays) {
  // An object with an empty box (an empty mesh) first: the scene still takes the one-mesh path,
  // whose hits name object 1.
  testing::Rng rng(10);
  Scene scene;
  Object empty;
  empty.shape = MeshShape{make_mesh({}, {})};
  scene.objects.push_back(std::move(empty));
  const TriangleSoup soup = make_octa_sphere(24, 0.05);
  Object o;
  o.shape = MeshShape{make_mesh(soup.positions, soup.triangles)};
  scene.objects.push_back(std::move(o));
  scene.build();
  ASSERT_EQ(scene.sole_mesh(), 1);
  expect_batch_equals_single(scene, mixed_rays(rng, soup));
}

// A flat square on its own box's face (z = 0): rows of sixteen coherent rays down onto it and
// past its edges, with segment ends a few ulps either side of the plane. Whether a lane's ray
// reaches the mesh is the object's box test (widened exit, in double), so the packet path's box
// test per lane must decide exactly as the single ray's.
TEST(RayBatch, BoxFaceAndEdges_PacketsEqualSingleRays) {
  Scene scene;
  Object o;
  o.shape = MeshShape{
      make_mesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{{0, 1, 2}}, {{0, 2, 3}}})};
  scene.objects.push_back(std::move(o));
  scene.build();
  ASSERT_EQ(scene.sole_mesh(), 0);
  std::vector<Ray> rays;
  for (int row = 0; row < 64; ++row) {
    const double y = row % 8 == 7 ? 1.0 : -1.1 + row * (2.2 / 64);  // some rows on the edge
    for (int i = 0; i < 32; ++i) {
      const double x = 0.95 + i * (0.1 / 32);  // across the edge x = 1
      Ray r{{x, y, 1}, {0.001 * (i % 4), 0.001 * (row % 3), -1}};
      const int k = (i + row) % 9 - 4;  // ends k ulps from the plane's t (about 1)
      double end = 1;
      for (int s = 0; s < std::abs(k); ++s) end = std::nextafter(end, k < 0 ? 0.0 : 2.0);
      if (row % 2)
        r.tmax = end;
      else
        r.tmin = end;
      rays.push_back(r);
    }
  }
  EXPECT_TRUE(coherent_rays(rays.data(), 16, 2.0));
  expect_batch_equals_single(scene, rays);
}

TEST(RayBatch, TwoMeshes_SingleRaysEqual) {
  testing::Rng rng(9);
  const Scene scene = mesh_scene(2);
  ASSERT_EQ(scene.sole_mesh(), -1);
  expect_batch_equals_single(scene, mixed_rays(rng, make_octa_sphere(24, 0.05)));
}

TEST(RayBatch, Coherence_OctantOriginAndDirection) {
  Ray rays[3] = {Ray{{0, 0, 0}, {0.1, 0.2, -1}}, Ray{{0, 0, 0}, {0.11, 0.2, -1}},
                 Ray{{0, 0, 0}, {0.12, 0.21, -1}}};
  EXPECT_TRUE(coherent_rays(rays, 3, 1));
  rays[2].d.x = -0.01;  // another octant
  EXPECT_FALSE(coherent_rays(rays, 3, 1));
  rays[2].d.x = 0.12;
  rays[2].o.y = 0.1;  // origins apart (more than 1/32 of the extent)
  EXPECT_FALSE(coherent_rays(rays, 3, 1));
  EXPECT_TRUE(coherent_rays(rays, 3, 8));
  rays[2].o.y = 0;
  rays[2].d.x = 0.5;  // directions apart
  EXPECT_FALSE(coherent_rays(rays, 3, 1));
}

}  // namespace
}  // namespace raycast
