// Early split clipping (MeshBvhConfig::split_budget): the split references' boxes hold their
// triangles, and the queries on a tree with split references return what they return without
// (closest, any, every without repeats), on meshes of long thin triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "mesh/split_refs.h"
#include "mesh/triangle.h"
#include "support/mesh_rays.h"

namespace raycast {
namespace {

// Long thin triangles in random directions (diagonal ones have the worst boxes).
TriangleSoup needles(std::mt19937& rng, int n) {
  std::uniform_real_distribution<float> pos(-5, 5), len(2, 8), width(0.001f, 0.05f);
  std::normal_distribution<float> dir;
  TriangleSoup s;
  for (int i = 0; i < n; ++i) {
    const Vec3f c{pos(rng), pos(rng), pos(rng)};
    const Vec3f d = normalize(Vec3f{dir(rng), dir(rng), dir(rng)});
    const Vec3f w = normalize(cross(d, Vec3f{dir(rng), dir(rng), dir(rng)}));
    const float l = len(rng);
    const auto base = static_cast<std::uint32_t>(s.positions.size());
    s.positions.push_back(c - 0.5f * l * d);
    s.positions.push_back(c + 0.5f * l * d);
    s.positions.push_back(c + width(rng) * w);
    s.triangles.push_back({base, base + 1, base + 2});
  }
  return s;
}

// A closed tube along a tilted axis: `around` sides of `along` long slivers each, with fan caps.
TriangleSoup tube(int around, int along, double length) {
  const Vec3 axis = normalize(Vec3{1, 0.7, 0.4});
  const Vec3 u = normalize(cross(axis, Vec3{0, 0, 1}));
  const Vec3 v = cross(axis, u);
  TriangleSoup s;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around;
      const Vec3 p = (length * j / along - 0.5 * length) * axis + std::cos(a) * u + std::sin(a) * v;
      s.positions.push_back(Vec3f(p));
    }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * around + i % around); };
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for (int end = 0; end < 2; ++end) {
    const auto centre = static_cast<std::uint32_t>(s.positions.size());
    s.positions.push_back(Vec3f((end == 0 ? -0.5 : 0.5) * length * axis));
    const int j = end == 0 ? 0 : along;
    for (int i = 0; i < around; ++i)
      if (end == 0)
        s.triangles.push_back({centre, at(i + 1, j), at(i, j)});
      else
        s.triangles.push_back({centre, at(i, j), at(i + 1, j)});
  }
  return s;
}

// A terrain grid rotated 30 degrees about z (its triangles' boxes are diagonal), heights varying.
TriangleSoup rotated_terrain(int g) {
  TriangleSoup s;
  const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) {
      const double x = -5 + 10.0 * i / g, y = -5 + 10.0 * j / g;
      s.positions.push_back(
          Vec3f(Vec3{c * x - sn * y, sn * x + c * y, 0.3 * std::sin(x) * std::cos(0.7 * y)}));
    }
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const std::uint32_t a = j * (g + 1) + i, b = a + 1, cc = a + g + 1, d = cc + 1;
      s.triangles.push_back({a, b, d});
      s.triangles.push_back({a, d, cc});
    }
  return s;
}

std::vector<std::uint32_t> every_sorted(const MeshBvh& bvh, const MeshRay& r) {
  std::vector<MeshBvhHit> hits;
  intersect_every(bvh, r, hits);
  std::vector<std::uint32_t> tris;
  for (const MeshBvhHit& h : hits) tris.push_back(h.triangle);
  std::sort(tris.begin(), tris.end());
  return tris;
}

// The queries with and without split references, and brute force, on random rays.
void check_split_matches_unsplit(const TriangleSoup& soup, double budget, int rays,
                                 std::uint32_t seed, float spread, double min_ratio = 8) {
  MeshBvhConfig split_config;
  split_config.split_budget = budget;
  split_config.split_min_ratio = min_ratio;
  const MeshBvh plain = build_mesh_bvh(soup.positions, soup.triangles);
  const MeshBvh split = build_mesh_bvh(soup.positions, soup.triangles, split_config);
  ASSERT_FALSE(plain.split);
  ASSERT_TRUE(split.split);
  std::mt19937 rng(seed);
  for (int i = 0; i < rays; ++i) {
    MeshRay r = testing::random_mesh_ray(rng, spread);
    if (i % 3 == 0) {  // whole lines too: every() then crosses many triangles
      r.tmin = -std::numeric_limits<float>::infinity();
      r.tmax = std::numeric_limits<float>::infinity();
    }
    MeshBvhHit a, b;
    const bool ha = intersect_closest(plain, r, a);
    const bool hb = intersect_closest(split, r, b);
    ASSERT_EQ(ha, hb) << "ray " << i;
    if (ha) {
      EXPECT_EQ(a.t, b.t) << "ray " << i;
      EXPECT_EQ(a.triangle, b.triangle) << "ray " << i;
      EXPECT_EQ(a.b1, b.b1) << "ray " << i;
      EXPECT_EQ(a.b2, b.b2) << "ray " << i;
    }
    EXPECT_EQ(intersect_any(split, r), ha) << "ray " << i;
    const std::vector<std::uint32_t> ea = every_sorted(plain, r), eb = every_sorted(split, r);
    EXPECT_EQ(ea, eb) << "ray " << i;
    EXPECT_EQ(std::adjacent_find(eb.begin(), eb.end()), eb.end()) << "repeat, ray " << i;
    // Brute force over the same watertight test.
    const WatertightRay w = make_watertight_ray(r.o, r.d);
    std::vector<std::uint32_t> brute;
    for (std::uint32_t t = 0; t < soup.triangles.size(); ++t) {
      const auto& tri = soup.triangles[t];
      TriangleHit h;
      if (intersect_watertight(w, soup.positions[tri[0]], soup.positions[tri[1]],
                               soup.positions[tri[2]], r.tmin, r.tmax, h))
        brute.push_back(t);
    }
    EXPECT_EQ(eb, brute) << "ray " << i;
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(SplitRefs, PiecesHoldTheirTrianglesAndStayInTheTriangleBox) {
  std::mt19937 rng(1);
  const TriangleSoup soup = needles(rng, 200);
  BvhBuildRefs refs(soup.triangles.size());
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    Aabb box;
    for (std::uint32_t k : soup.triangles[i]) box.grow(Vec3(soup.positions[k]));
    refs[i] = make_build_ref(box, static_cast<std::uint32_t>(i));
  }
  const BvhBuildRefs original = refs;
  split_triangle_refs(soup.positions, soup.triangles, 1.0, 8.0, refs);
  EXPECT_EQ(refs.size(), 2 * soup.triangles.size());  // needles always have waste to split
  std::vector<std::vector<BvhBuildRef>> pieces(soup.triangles.size());
  for (const BvhBuildRef& r : refs) {
    ASSERT_LT(r.index, soup.triangles.size());
    const BvhBuildRef& o = original[r.index];
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(o.lo[a], r.lo[a]);
      EXPECT_LE(r.lo[a], r.hi[a]);
      EXPECT_LE(r.hi[a], o.hi[a]);
    }
    pieces[r.index].push_back(r);
  }
  // Points of each triangle (its vertices, edge points, interior points) lie in some piece.
  std::uniform_real_distribution<double> u(0, 1);
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    const Vec3 p0(soup.positions[soup.triangles[i][0]]), p1(soup.positions[soup.triangles[i][1]]),
        p2(soup.positions[soup.triangles[i][2]]);
    for (int s = 0; s < 200; ++s) {
      double b1 = u(rng), b2 = u(rng);
      if (s < 3) b1 = s == 1, b2 = s == 2;
      if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
      const Vec3 p = (1 - b1 - b2) * p0 + b1 * p1 + b2 * p2;
      const Vec3f q(p);
      const bool inside = std::any_of(pieces[i].begin(), pieces[i].end(), [&](const auto& r) {
        for (int a = 0; a < 3; ++a)
          if (!(r.lo[a] <= q[a] && q[a] <= r.hi[a])) return false;
        return true;
      });
      EXPECT_TRUE(inside) << "triangle " << i << " sample " << s;
    }
  }
}

TEST(SplitRefs, Needles_QueriesMatchTheUnsplitTree) {
  std::mt19937 rng(2);
  check_split_matches_unsplit(needles(rng, 1500), 0.3, 400, 3, 5);
  check_split_matches_unsplit(needles(rng, 300), 2.0, 300, 4, 5, 0);
}

TEST(SplitRefs, SliverTube_QueriesMatchTheUnsplitTree) {
  check_split_matches_unsplit(tube(48, 3, 12), 1.0, 500, 5, 6);
}

TEST(SplitRefs, RotatedTerrain_QueriesMatchTheUnsplitTree) {
  // Its box-to-area ratios are about 4: split every piece with any waste.
  check_split_matches_unsplit(rotated_terrain(40), 0.3, 500, 6, 5, 0);
}

TEST(SplitRefs, BudgetBoundsTheExtraReferences) {
  std::mt19937 rng(3);
  const TriangleSoup soup = needles(rng, 1000);
  MeshBvhConfig config;
  config.max_leaf_size = 1;  // one triangle per leaf: groups count references
  const MeshBvh plain = build_mesh_bvh(soup.positions, soup.triangles, config);
  config.split_budget = 0.3;
  const MeshBvh split = build_mesh_bvh(soup.positions, soup.triangles, config);
  EXPECT_EQ(plain.groups.size(), 1000u);
  EXPECT_EQ(split.groups.size(), 1300u);
}

// Rays from inside the closed sliver tube at its shared edges and vertices never slip through.
TEST(SplitRefs, SliverTube_RaysAtEdgesFromInside_NeverMiss) {
  const TriangleSoup soup = tube(32, 2, 10);
  MeshOptions options;
  options.bvh.split_budget = 1.0;
  const auto mesh = make_mesh(soup.positions, soup.triangles, {}, options);
  ASSERT_TRUE(mesh->bvh.split);
  const MeshShape shape{mesh};
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> along(0, 1);
  int misses = 0;
  auto shoot = [&](const Vec3& o, const Vec3& target) {
    LocalHit h;
    const Ray ray{o, target - o};
    if (!intersect(shape, ray, h)) ++misses;
    if (!occluded(shape, ray)) ++misses;
  };
  const Vec3 axis = normalize(Vec3{1, 0.7, 0.4});
  for (const Vec3& o : {Vec3{0, 0, 0}, 2.0 * axis, -3.1 * axis + Vec3{0.1, -0.2, 0.05}}) {
    for (const Vec3f& p : soup.positions) shoot(o, Vec3(p));
    for (const auto& t : soup.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3f a = soup.positions[t[k]], b = soup.positions[t[(k + 1) % 3]];
        shoot(o, Vec3(a + 0.5f * (b - a)));
        shoot(o, Vec3(a + along(rng) * (b - a)));
      }
  }
  EXPECT_EQ(misses, 0);
}

}  // namespace
}  // namespace raycast
