// The mesh BVH against brute force over the same watertight test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "mesh/triangle.h"
#include "support/mesh_rays.h"

namespace raycast {
namespace {

struct Brute {
  bool found = false;
  float t = 0;
  std::vector<std::uint32_t> tris;  // every triangle at the nearest t (ties)
};

Brute brute_force(const TriangleSoup& s, const MeshRay& r) {
  const WatertightRay w = make_watertight_ray(r.o, r.d);
  Brute b;
  for (std::uint32_t i = 0; i < s.triangles.size(); ++i) {
    const auto& t = s.triangles[i];
    TriangleHit h;
    if (!intersect_watertight(w, s.positions[t[0]], s.positions[t[1]], s.positions[t[2]], r.tmin,
                              r.tmax, h))
      continue;
    if (!b.found || h.t < b.t) {
      b.found = true;
      b.t = h.t;
      b.tris.clear();
    }
    if (h.t == b.t) b.tris.push_back(i);
  }
  return b;
}

TriangleSoup random_soup(std::mt19937& rng, int n, float spread, float size) {
  std::uniform_real_distribution<float> pos(-spread, spread), off(-size, size);
  TriangleSoup s;
  for (int i = 0; i < n; ++i) {
    const Vec3f c{pos(rng), pos(rng), pos(rng)};
    const auto base = static_cast<std::uint32_t>(s.positions.size());
    for (int k = 0; k < 3; ++k) s.positions.push_back(c + Vec3f{off(rng), off(rng), off(rng)});
    s.triangles.push_back({base, base + 1, base + 2});
  }
  return s;
}

void check_against_brute_force(const TriangleSoup& soup, const MeshBvh& bvh, const MeshRay& r) {
  const Brute b = brute_force(soup, r);
  MeshBvhHit h;
  const bool hit = intersect_closest(bvh, r, h);
  ASSERT_EQ(hit, b.found);
  EXPECT_EQ(intersect_any(bvh, r), b.found);
  if (!hit) return;
  EXPECT_EQ(h.t, b.t);
  EXPECT_NE(std::find(b.tris.begin(), b.tris.end(), h.triangle), b.tris.end())
      << "triangle " << h.triangle;
}

TEST(MeshBvh, RandomSoups_MatchBruteForce) {
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    const int n = 1 + static_cast<int>(rng() % 3000);
    const TriangleSoup soup = random_soup(rng, n, 10, seed % 2 ? 0.5f : 3.0f);
    MeshBvhConfig config;
    config.max_leaf_size = 1 + static_cast<int>(seed % 16);
    const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles, config);
    for (int i = 0; i < 300; ++i) {
      check_against_brute_force(soup, bvh, testing::random_mesh_ray(rng, 10));
      if (HasFatalFailure()) return;
    }
  }
}

TEST(MeshBvh, ProceduralSphere_MatchesBruteForce) {
  const TriangleSoup soup = make_octa_sphere(20);
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
  std::mt19937 rng(7);
  for (int i = 0; i < 500; ++i) {
    check_against_brute_force(soup, bvh, testing::random_mesh_ray(rng, 1));
    if (HasFatalFailure()) return;
  }
}

// Quantised child boxes must hold their triangles whatever the scale: clusters of small triangles
// from 1e-30 up to beyond the builder's clamp (2^125) and near the largest float, in one tree, so
// that nodes span extents from denormal-adjacent to infinite steps. Rays aimed at each triangle's
// centroid from nearby must find what brute force finds.
TEST(MeshBvh, QuantisedBoxes_ExtremeScales_MatchBruteForce) {
  std::mt19937 rng(11);
  const float scales[] = {1e-30f, 1e-3f, 1.0f, 1e20f, 1e37f, 1e38f, 3e38f};
  TriangleSoup soup;
  std::uniform_real_distribution<float> u(-1, 1);
  for (float scale : scales)
    for (int i = 0; i < 40; ++i) {
      const Vec3f c{u(rng) * scale, u(rng) * scale, u(rng) * scale};
      const auto base = static_cast<std::uint32_t>(soup.positions.size());
      for (int k = 0; k < 3; ++k)
        soup.positions.push_back(c + Vec3f{u(rng), u(rng), u(rng)} * (0.01f * scale));
      soup.triangles.push_back({base, base + 1, base + 2});
    }
  for (const auto& p : soup.positions)
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  for (const std::size_t quantise_above : {std::size_t(0), soup.triangles.size()}) {
    MeshBvhConfig config;
    config.quantise_above = quantise_above;  // quantised nodes, then float nodes
    const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles, config);
    ASSERT_EQ(bvh.quantised, quantise_above == 0);
    for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
      const auto& t = soup.triangles[i];
      const Vec3f& a = soup.positions[t[0]];
      const Vec3f& b = soup.positions[t[1]];
      const Vec3f& c = soup.positions[t[2]];
      const Vec3f centre = a * (1 / 3.0f) + b * (1 / 3.0f) + c * (1 / 3.0f);
      const float reach = std::max({std::abs(a.x - b.x), std::abs(a.y - c.y), std::abs(b.z - c.z)});
      for (int k = 0; k < 3; ++k) {
        MeshRay r;
        r.o = centre + Vec3f{u(rng), u(rng), u(rng)} * reach;
        Vec3f d = centre - r.o;
        const float m = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        if (!(m > 0)) continue;
        r.d = d * (1.5f / m);  // largest component in [1, 2), as the mesh's ray conversion makes it
        r.tmin = 0;
        r.tmax = std::numeric_limits<float>::infinity();
        check_against_brute_force(soup, bvh, r);
        if (HasFatalFailure()) return;
      }
    }
  }
}

// The node format follows the triangle count: quantised above MeshBvhConfig::quantise_above,
// float up to it; exactly one of the two node arrays is filled.
TEST(MeshBvh, NodeFormat_ChosenByTriangleCount) {
  const TriangleSoup soup = make_octa_sphere(8);
  const std::size_t n = soup.triangles.size();
  MeshBvhConfig config;
  config.quantise_above = n;
  const MeshBvh small = build_mesh_bvh(soup.positions, soup.triangles, config);
  EXPECT_FALSE(small.quantised);
  EXPECT_FALSE(small.nodes.empty());
  EXPECT_TRUE(small.qnodes.empty());
  config.quantise_above = n - 1;
  const MeshBvh large = build_mesh_bvh(soup.positions, soup.triangles, config);
  EXPECT_TRUE(large.quantised);
  EXPECT_TRUE(large.nodes.empty());
  EXPECT_EQ(large.qnodes.size(), small.nodes.size());  // the same tree in the other format
  EXPECT_EQ(large.depth, small.depth);
  EXPECT_EQ(large.memory_bytes() + small.nodes.size() * (sizeof(WideNode) - sizeof(QuantisedNode)),
            small.memory_bytes());
}

TEST(MeshBvh, Hits_ReportTheSourceIndexGivenToTheBuild) {
  const TriangleSoup soup = make_octa_sphere(8);
  std::vector<std::uint32_t> source(soup.triangles.size());
  for (std::size_t i = 0; i < source.size(); ++i) source[i] = static_cast<std::uint32_t>(7 * i + 3);
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles, {}, source);
  std::mt19937 rng(5);
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    MeshBvhHit h;
    if (!intersect_closest(bvh, testing::random_mesh_ray(rng, 1), h)) continue;
    ++hits;
    EXPECT_EQ(h.source, source[h.triangle]);
  }
  EXPECT_GT(hits, 0);
  std::vector<std::uint32_t> short_source(3, 0);
  EXPECT_THROW(build_mesh_bvh(soup.positions, soup.triangles, {}, short_source),
               std::invalid_argument);
}

TEST(MeshBvh, EveryHit_MatchesBruteForceCount) {
  const TriangleSoup soup = make_octa_sphere(10);
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
  std::mt19937 rng(3);
  for (int i = 0; i < 200; ++i) {
    MeshRay r = testing::random_mesh_ray(rng, 1);
    r.tmin = -std::numeric_limits<float>::infinity();
    r.tmax = std::numeric_limits<float>::infinity();
    const WatertightRay w = make_watertight_ray(r.o, r.d);
    std::size_t expected = 0;
    for (const auto& t : soup.triangles) {
      TriangleHit h;
      expected += intersect_watertight(w, soup.positions[t[0]], soup.positions[t[1]],
                                       soup.positions[t[2]], r.tmin, r.tmax, h);
    }
    std::vector<MeshBvhHit> hits;
    intersect_every(bvh, r, hits);
    EXPECT_EQ(hits.size(), expected) << "ray " << i;
  }
}

TEST(MeshBvh, Empty_NeverHits) {
  const MeshBvh bvh = build_mesh_bvh({}, {});
  MeshRay r{{0, 0, 0}, {0, 0, 1}, 0, 1e30f};
  MeshBvhHit h;
  EXPECT_FALSE(intersect_closest(bvh, r, h));
  EXPECT_FALSE(intersect_any(bvh, r));
  EXPECT_EQ(bvh.memory_bytes(), 0u);
}

TEST(MeshBvh, SingleTriangle_TminTmaxAreInclusive) {
  const std::vector<Vec3f> p{{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}};
  const std::vector<std::array<std::uint32_t, 3>> t{{0, 1, 2}};
  const MeshBvh bvh = build_mesh_bvh(p, t);
  MeshBvhHit h;
  EXPECT_TRUE(intersect_closest(bvh, {{0, 0, 0}, {0, 0, 1}, 0, 2}, h));
  EXPECT_EQ(h.t, 2.0f);
  EXPECT_TRUE(intersect_closest(bvh, {{0, 0, 0}, {0, 0, 1}, 2, 3}, h));
  EXPECT_FALSE(intersect_closest(bvh, {{0, 0, 0}, {0, 0, 1}, 0, std::nextafter(2.0f, 0.0f)}, h));
  EXPECT_FALSE(intersect_any(bvh, {{0, 0, 0}, {0, 0, 1}, std::nextafter(2.0f, 3.0f), 3}));
}

TEST(MeshBvh, AxisParallelRays_HitBoxesWithZeroExtent) {
  // A triangle in the plane z = 0 has a flat box; rays along every axis and exactly in the plane.
  const std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<std::uint32_t, 3>> t{{0, 1, 2}};
  const MeshBvh bvh = build_mesh_bvh(p, t);
  MeshBvhHit h;
  ASSERT_TRUE(intersect_closest(bvh, {{0.25f, 0.25f, 5}, {0, 0, -1}, 0, 100}, h));
  EXPECT_EQ(h.t, 5.0f);
  EXPECT_FLOAT_EQ(h.b1, 0.25f);
  EXPECT_FLOAT_EQ(h.b2, 0.25f);
  EXPECT_FALSE(intersect_closest(bvh, {{2, 0.25f, 5}, {0, 0, -1}, 0, 100}, h));
}

}  // namespace
}  // namespace raycast
