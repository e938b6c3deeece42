// Watertightness: rays from inside closed meshes aimed exactly at shared edges and vertices never
// slip between triangles (Woop, Benthin and Wald 2013).
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "mesh/triangle.h"

namespace raycast {
namespace {

TriangleSoup cube12() {
  TriangleSoup s;
  s.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  s.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                 {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  return s;
}

TriangleSoup icosphere(int subdivisions) {
  const float g = (1.0f + std::sqrt(5.0f)) / 2;
  TriangleSoup s;
  s.positions = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                 {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Vec3 m = normalize(Vec3(s.positions[a]) + Vec3(s.positions[b])) * 1.7;
      s.positions.push_back(Vec3f(m));
      return mid[key] = static_cast<std::uint32_t>(s.positions.size() - 1);
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : s.triangles) {
      const std::uint32_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]),
                          c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    s.triangles = std::move(next);
  }
  return s;
}

// Shoots rays from `origins` at every vertex and at points along every edge (float points
// computed on the edge, so many lie exactly on it); returns the number of misses.
int count_misses(const TriangleSoup& soup, const std::vector<Vec3>& origins, std::mt19937& rng) {
  const auto mesh = make_mesh(soup.positions, soup.triangles);
  const MeshShape shape{mesh};
  std::uniform_real_distribution<float> along(0, 1);
  int misses = 0;
  auto shoot = [&](const Vec3& o, const Vec3& target) {
    LocalHit h;
    const Ray ray{o, target - o};
    if (!intersect(shape, ray, h)) ++misses;
    if (!occluded(shape, ray)) ++misses;
  };
  for (const Vec3& o : origins) {
    for (const Vec3f& p : soup.positions) shoot(o, Vec3(p));
    for (const auto& t : soup.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3f a = soup.positions[t[k]], b = soup.positions[t[(k + 1) % 3]];
        shoot(o, Vec3(a + 0.5f * (b - a)));
        shoot(o, Vec3(a + along(rng) * (b - a)));
      }
  }
  return misses;
}

TEST(Watertight, Cube12_RaysAtEdgesAndVerticesFromInside_NeverMiss) {
  std::mt19937 rng(1);
  const std::vector<Vec3> origins{
      {0, 0, 0}, {0.25, -0.5, 0.125}, {-0.9, 0.9, 0.3}, {0.5, 0.5, 0.5}};
  EXPECT_EQ(count_misses(cube12(), origins, rng), 0);
}

TEST(Watertight, Icosphere_RaysAtEdgesAndVerticesFromInside_NeverMiss) {
  std::mt19937 rng(2);
  const std::vector<Vec3> origins{{0, 0, 0}, {0.3, 0.2, -0.1}, {-0.7, 0.1, 0.5}};
  EXPECT_EQ(count_misses(icosphere(2), origins, rng), 0);
}

TEST(Watertight, ProceduralSphere_RaysAtEdgesAndVerticesFromInside_NeverMiss) {
  std::mt19937 rng(3);
  const std::vector<Vec3> origins{{0, 0, 0}, {0.1, -0.2, 0.3}};
  EXPECT_EQ(count_misses(make_octa_sphere(12), origins, rng), 0);
}

TEST(Watertight, RandomInteriorRays_NeverMissAClosedMesh) {
  const TriangleSoup soup = make_octa_sphere(16);
  const MeshShape shape{make_mesh(soup.positions, soup.triangles)};
  std::mt19937 rng(4);
  std::normal_distribution<double> n;
  int misses = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 o = 0.5 * Vec3{n(rng), n(rng), n(rng)} * 0.3;
    Vec3 d{n(rng), n(rng), n(rng)};
    // Axis-aligned and diagonal directions too: the hardest for edge tests.
    if (i % 4 == 0) d = Vec3{0, 0, i % 8 ? 1.0 : -1.0};
    if (i % 4 == 1) d = Vec3{1, 1, 0};
    LocalHit h;
    misses += !intersect(shape, Ray{o, d}, h);
  }
  EXPECT_EQ(misses, 0);
}

TEST(Triangle, MollerTrumbore_AgreesWithWatertightInsideTheTriangle) {
  const Vec3f v0{0, 0, 1}, v1{1, 0, 1}, v2{0, 1, 1};
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.01f, 0.49f);
  for (int i = 0; i < 1000; ++i) {
    const Vec3f o{u(rng), u(rng), 0}, d{0, 0, 1};
    TriangleHit a, b;
    ASSERT_TRUE(intersect_watertight(make_watertight_ray(o, d), v0, v1, v2, 0, 10, a));
    ASSERT_TRUE(intersect_moller_trumbore(o, d, v0, v1, v2, 0, 10, b));
    EXPECT_FLOAT_EQ(a.t, b.t);
    EXPECT_NEAR(a.b1, b.b1, 1e-6);
    EXPECT_NEAR(a.b2, b.b2, 1e-6);
  }
  TriangleHit h;
  EXPECT_FALSE(intersect_moller_trumbore({2, 2, 0}, {0, 0, 1}, v0, v1, v2, 0, 10, h));
  EXPECT_FALSE(
      intersect_watertight(make_watertight_ray({2, 2, 0}, {0, 0, 1}), v0, v1, v2, 0, 10, h));
}

TEST(Triangle, Watertight_SharedEdgeExactly_HitsAtLeastOneSide) {
  // Two triangles sharing the diagonal of the unit square; rays straight down through points of
  // the diagonal, where the float edge function is exactly 0.
  const Vec3f a{0, 0, 0}, b{1, 0, 0}, c{1, 1, 0}, d{0, 1, 0};
  for (int i = 1; i < 64; ++i) {
    const float s = i / 64.0f;
    const WatertightRay r = make_watertight_ray({s, s, 1}, {0, 0, -1});
    TriangleHit h;
    const bool first = intersect_watertight(r, a, b, c, 0, 10, h);
    const bool second = intersect_watertight(r, a, c, d, 0, 10, h);
    EXPECT_TRUE(first || second) << "s = " << s;
  }
}

TEST(Triangle, Watertight_NaNVertices_NeverHit) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  TriangleHit h;
  EXPECT_FALSE(intersect_watertight(make_watertight_ray({0, 0, 0}, {0, 0, 1}), {nan, nan, nan},
                                    {1, 0, 1}, {0, 1, 1}, 0, 10, h));
}

}  // namespace
}  // namespace raycast
