// ScenePackets (the renderer's camera-ray packets) answers as Scene::intersect does, lane by lane
// and bit for bit: scenes of one mesh (plain and transformed), a mesh beside a plane and spheres,
// two meshes; packets of camera-like coherent rays and of random rays, partial masks, rays that
// end at or just before their hit, invalid rays. Lanes outside the mask are not written.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "scene/scene.h"
#include "scene/scene_packets.h"
#include "support/objects.h"
#include "support/random.h"

namespace raycast {
namespace {

constexpr std::int32_t kUntouched = -7;

using testing::object_of;

Object mesh_object(const TriangleSoup& soup, std::optional<Transform> xf = std::nullopt) {
  return object_of(MeshShape{make_mesh(soup.positions, soup.triangles)}, std::move(xf));
}

// The named scenes; every one has a mesh and at most three bounded objects (a usable plan).
Scene make_scene(const std::string& name) {
  const TriangleSoup ball = make_octa_sphere(10, 0.08);
  const TriangleSoup small = make_octa_sphere(4, 0.0, {0, 0, 0}, 0.5);
  Scene s;
  if (name == "mesh") {
    s.objects = {mesh_object(ball)};
  } else if (name == "moved mesh") {
    s.objects = {
        mesh_object(ball, Transform::translate({0.2, 0.1, 0}) * Transform::rotate({1, 1, 0}, 30) *
                              Transform::scale({1.5, 0.8, 1.1}))};
  } else if (name == "mixed") {
    // A plane the mesh sits in (hits of both near the same t), a sphere cutting the mesh, a
    // sphere behind it.
    s.objects = {object_of(make_plane({0, 1, 0}, {0, -0.7, 0})), mesh_object(ball),
                 object_of(make_sphere({0.8, 0.3, 0.2}, 0.45)),
                 object_of(make_sphere({0, 0, -3}, 1.5))};
  } else if (name == "two meshes") {
    s.objects = {mesh_object(small, Transform::translate({0.6, 0.2, 0.4})),
                 object_of(make_plane({0.1, 1, 0}, {0, -0.9, 0})), mesh_object(ball)};
  }
  s.build();
  return s;
}

void expect_packet_is_single(const Scene& scene, const ScenePackets& packets, const Ray* rays,
                             int mask, int& hits, const std::string& where) {
  SceneHit got[16];
  for (SceneHit& h : got) h.object = kUntouched;
  const int found = packets.intersect(rays, mask, got);
  EXPECT_EQ(found & ~mask, 0) << where;
  for (int l = 0; l < packets.width(); ++l) {
    if (!(mask >> l & 1)) {
      EXPECT_EQ(got[l].object, kUntouched) << where << " lane " << l;
      continue;
    }
    SceneHit want;
    const bool hit = scene.intersect(rays[l], want);
    ASSERT_EQ(bool(found >> l & 1), hit) << where << " lane " << l;
    if (!hit) continue;
    ++hits;
    EXPECT_EQ(got[l].object, want.object) << where << " lane " << l;
    EXPECT_EQ(got[l].local.t, want.local.t) << where << " lane " << l;
    EXPECT_EQ(got[l].local.prim, want.local.prim) << where << " lane " << l;
    EXPECT_EQ(got[l].local.part, want.local.part) << where << " lane " << l;
    EXPECT_EQ(got[l].local.a, want.local.a) << where << " lane " << l;
    EXPECT_EQ(got[l].local.b, want.local.b) << where << " lane " << l;
    EXPECT_EQ(got[l].local.leaf, want.local.leaf) << where << " lane " << l;
    EXPECT_EQ(got[l].local.flip, want.local.flip) << where << " lane " << l;
  }
}

TEST(ScenePackets, UsableOnlyForMeshScenesItCanRepeat) {
  for (const char* name : {"mesh", "moved mesh", "mixed", "two meshes"})
    EXPECT_TRUE(ScenePackets(make_scene(name)).usable()) << name;
  Scene analytic;
  analytic.objects = {object_of(make_plane({0, 1, 0}, {0, 0, 0})),
                      object_of(make_sphere({0, 1, 0}, 1))};
  analytic.build();
  EXPECT_FALSE(ScenePackets(analytic).usable());  // no mesh: nothing to gain
  // ObjectSet orders four or more bounded objects per ray: not repeated.
  Scene many;
  for (int i = 0; i < int(ObjectSet::kBoxPairsFrom); ++i)
    many.objects.push_back(mesh_object(make_octa_sphere(2, 0.0, {3.0 * i, 0, 0})));
  many.build();
  EXPECT_FALSE(ScenePackets(many).usable());
  const int width = ScenePackets(make_scene("mesh")).width();
  EXPECT_TRUE(width == 8 || width == 16);
}

TEST(ScenePackets, CameraPackets_EqualSingleRays) {
  for (const char* name : {"mesh", "moved mesh", "mixed", "two meshes"}) {
    const Scene scene = make_scene(name);
    const ScenePackets packets(scene);
    ASSERT_TRUE(packets.usable());
    const int w = packets.width();
    // Pinhole rays of a 4 x (w / 4) block of pixels, blocks over a 48 x 48 image of the scene;
    // partial masks as at an image's right and bottom edges.
    const Vec3 eye{0.3, 0.9, 4.5};
    int hits = 0, n = 0;
    testing::Rng rng(7);
    for (int by = 0; by < 48; by += w / 4) {
      for (int bx = 0; bx < 48; bx += 4, ++n) {
        Ray rays[16];
        for (int l = 0; l < w; ++l) {
          const double x = (bx + l % 4 + 0.5) / 48 * 2 - 1, y = 1 - (by + l / 4 + 0.5) / 48 * 2;
          rays[l] = Ray{eye, normalize(Vec3{1.6 * x, 1.6 * y - 0.2, -4.5}), 0, kInfinity};
        }
        int mask = (1 << w) - 1;
        if (n % 5 == 1) mask &= 0x3333;                             // two columns
        if (n % 5 == 2) mask &= 0x00FF;                             // two rows
        if (n % 5 == 3) mask = 1 << int(rng.uniform(0, w - 0.01));  // one lane
        if (n % 7 == 5) rays[0].tmax = rng.uniform(2.5, 5.0);       // may end before the mesh
        expect_packet_is_single(scene, packets, rays, mask, hits,
                                std::string(name) + " block " + std::to_string(n));
      }
    }
    EXPECT_GT(hits, 300) << name;  // the rays do reach the scene
  }
}

TEST(ScenePackets, RandomPackets_EqualSingleRays) {
  for (const char* name : {"mesh", "moved mesh", "mixed", "two meshes"}) {
    const Scene scene = make_scene(name);
    const ScenePackets packets(scene);
    const int w = packets.width();
    testing::Rng rng(23);
    int hits = 0;
    for (int n = 0; n < 300; ++n) {
      Ray rays[16];
      for (int l = 0; l < w; ++l) {
        // Coherent bundles (one origin, close targets) and scattered rays.
        rays[l] =
            n % 2 ? testing::random_ray(rng, 3, 1.2)
                  : Ray{Vec3{0.2, 0.4, 3.5}, rng.in_box(0.8) - Vec3{0.2, 0.4, 3.5}, 0, kInfinity};
        if (l % 5 == 3) rays[l].tmin = rng.uniform(0, 2);
      }
      if (n % 10 == 7) rays[n % w].d.x = std::numeric_limits<double>::quiet_NaN();
      if (n % 10 == 8) rays[n % w].tmin = rays[n % w].tmax = 4;  // a point: no hit
      const int mask = n % 3 ? (1 << w) - 1 : int(rng() & ((1u << w) - 1));
      expect_packet_is_single(scene, packets, rays, mask, hits,
                              std::string(name) + " packet " + std::to_string(n));
      // Each lane ending exactly at its own hit, or just before it.
      SceneHit h[16];
      const int found = packets.intersect(rays, mask, h);
      Ray cut[16];
      for (int l = 0; l < w; ++l) {
        cut[l] = rays[l];
        if (found >> l & 1) cut[l].tmax = l % 2 ? h[l].local.t : std::nextafter(h[l].local.t, 0.0);
      }
      expect_packet_is_single(scene, packets, cut, mask, hits,
                              std::string(name) + " cut packet " + std::to_string(n));
    }
    EXPECT_GT(hits, 1000) << name;
  }
}

}  // namespace
}  // namespace raycast
