// Every ISA's mesh kernels (scalar, SSE4, AVX2, AVX-512; those the CPU lacks are skipped) against
// brute force and against the scalar kernels, bit for bit: random soups, closed meshes at scales
// 1e-6 to 1e6 shot at their shared edges and vertices, degenerate and needle triangles, NaN and
// infinite rays, and a deep tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>

#include "mesh/procedural.h"
#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

namespace raycast {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The queries of one ISA with their own stack.
struct Kernels {
  const MeshKernels& k;
  const MeshBvh& bvh;
  std::vector<TraversalEntry> stack = std::vector<TraversalEntry>(traversal_stack_size(bvh));
  bool closest(const MeshRay& r, MeshBvhHit& h) { return k.closest(bvh, r, h, stack.data()); }
  bool any(const MeshRay& r) { return k.any(bvh, r, stack.data()); }
  std::vector<std::tuple<std::uint32_t, float, float, float>> every(const MeshRay& r) {
    std::vector<MeshBvhHit> hits;
    k.every(bvh, r, hits, stack.data());
    std::vector<std::tuple<std::uint32_t, float, float, float>> out;
    for (const MeshBvhHit& h : hits) out.emplace_back(h.triangle, h.t, h.b1, h.b2);
    std::sort(out.begin(), out.end());
    return out;
  }
};

class WideKernels : public testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    kernels_ = mesh_kernels(GetParam());
    if (!kernels_) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  }
  const MeshKernels* kernels_ = nullptr;
};

// The build config for one of the two node formats (mesh/mesh_bvh.h), whatever the mesh size.
MeshBvhConfig with_format(MeshBvhConfig c, bool quantised) {
  c.quantise_above = quantised ? 0 : std::numeric_limits<std::size_t>::max();
  return c;
}

constexpr bool kBothFormats[] = {false, true};

// The nearest watertight hit by testing every triangle (ties: every triangle at that t).
struct Brute {
  bool found = false;
  float t = 0;
  std::vector<std::uint32_t> tris;
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

// `kernels` against brute force, and bit for bit against the scalar kernels.
void check_ray(Kernels& kernels, Kernels& scalar, const TriangleSoup& soup, const MeshRay& r) {
  const Brute b = brute_force(soup, r);
  MeshBvhHit h, s;
  const bool hit = kernels.closest(r, h);
  ASSERT_EQ(hit, b.found);
  ASSERT_EQ(scalar.closest(r, s), hit);
  EXPECT_EQ(kernels.any(r), b.found);
  if (hit) {
    EXPECT_EQ(h.t, b.t);
    // Ties go to the least triangle index: every node test keeps every box that may hold a
    // tied triangle (the culling margin of mesh/wide_traverse.inl), whatever its rounding.
    EXPECT_EQ(h.triangle, *std::min_element(b.tris.begin(), b.tris.end()));
    EXPECT_EQ(h.triangle, s.triangle);
    EXPECT_EQ(h.t, s.t);
    EXPECT_EQ(h.b1, s.b1);
    EXPECT_EQ(h.b2, s.b2);
  }
  EXPECT_EQ(kernels.every(r), scalar.every(r));
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

MeshRay random_ray(std::mt19937& rng, float spread) {
  std::uniform_real_distribution<float> pos(-1.5f * spread, 1.5f * spread);
  std::normal_distribution<float> dir;
  MeshRay r;
  r.o = {pos(rng), pos(rng), pos(rng)};
  do r.d = {dir(rng), dir(rng), dir(rng)};
  while (!(length_squared(r.d) > 0.01f));
  r.tmin = rng() % 4 == 0 ? -kInf : 0;
  r.tmax = rng() % 4 == 0 ? kInf : std::uniform_real_distribution<float>(0.5f, 10.0f)(rng) * spread;
  return r;
}

TEST_P(WideKernels, RandomSoups_MatchBruteForceAndScalar) {
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    const TriangleSoup soup =
        random_soup(rng, 1 + static_cast<int>(rng() % 2000), 10, seed % 2 ? 0.5f : 3.0f);
    MeshBvhConfig config;
    config.max_leaf_size = 1 + static_cast<int>(seed % 16);
    for (const bool quantised : kBothFormats) {
      SCOPED_TRACE(quantised ? "quantised nodes" : "float nodes");
      const MeshBvh bvh =
          build_mesh_bvh(soup.positions, soup.triangles, with_format(config, quantised));
      ASSERT_EQ(bvh.quantised, quantised);
      Kernels k{*kernels_, bvh}, s{kMeshKernelsScalar, bvh};
      std::mt19937 ray_rng(seed);
      for (int i = 0; i < 200; ++i) {
        check_ray(k, s, soup, random_ray(ray_rng, 10));
        if (HasFatalFailure()) return;
      }
    }
  }
}

TEST_P(WideKernels, DegenerateAndNeedleTriangles_MatchBruteForceAndScalar) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  TriangleSoup soup;
  auto add = [&](Vec3f a, Vec3f b, Vec3f c) {
    const auto base = static_cast<std::uint32_t>(soup.positions.size());
    soup.positions.insert(soup.positions.end(), {a, b, c});
    soup.triangles.push_back({base, base + 1, base + 2});
  };
  for (int i = 0; i < 300; ++i) {
    const Vec3f a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    add(a, b, a + 0.5f * (b - a));                                    // collinear: zero area
    add(a, a, b);                                                     // repeated vertex
    add(a, b, a + (b - a) * 0.5f + Vec3f{0, 1e-6f, 0});               // needle, 1e-6 wide
    add(a * 1000.0f, b * 1000.0f, a * 1000.0f + Vec3f{0, 0, 1e-3f});  // long needle
  }
  for (const bool quantised : kBothFormats) {
    SCOPED_TRACE(quantised ? "quantised nodes" : "float nodes");
    const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles, with_format({}, quantised));
    Kernels k{*kernels_, bvh}, s{kMeshKernelsScalar, bvh};
    for (int i = 0; i < 400; ++i) {
      MeshRay r = random_ray(rng, 1);
      if (i % 2) {  // aim at a needle's or a degenerate triangle's vertex
        const auto& t = soup.triangles[rng() % soup.triangles.size()];
        r.d = soup.positions[t[rng() % 3]] - r.o;
        r.tmin = 0;
        r.tmax = kInf;
      }
      check_ray(k, s, soup, r);
      if (HasFatalFailure()) return;
    }
  }
}

TEST_P(WideKernels, NanAndInfiniteRays_NeverHitOrMatchScalar) {
  const TriangleSoup soup = make_octa_sphere(8);
  for (const bool quantised : kBothFormats) {
    SCOPED_TRACE(quantised ? "quantised nodes" : "float nodes");
    const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles, with_format({}, quantised));
    Kernels k{*kernels_, bvh}, s{kMeshKernelsScalar, bvh};
    const std::vector<MeshRay> nan_rays{
        {{kNaN, 0, 0}, {1, 0, 0}, 0, kInf},     {{0, 0, 0}, {kNaN, 1, 0}, 0, kInf},
        {{0, 0, 0}, {1, 0, 0}, kNaN, kInf},     {{0, 0, 0}, {1, 0, 0}, 0, kNaN},
        {{kInf, 0, 0}, {-1, 0, 0}, 0, kInf},    {{0, 0, 0}, {0, 0, 0}, 0, kInf},
        {{-kInf, kInf, 0}, {1, -1, 0}, 0, kInf}};
    for (const MeshRay& r : nan_rays) {
      SCOPED_TRACE(testing::Message() << "ray " << r.o.x << " " << r.o.y << " " << r.d.x << " "
                                      << r.d.y << " " << r.tmin << " " << r.tmax);
      MeshBvhHit h;
      EXPECT_FALSE(k.closest(r, h));
      EXPECT_FALSE(k.any(r));
      EXPECT_TRUE(k.every(r).empty());
    }
    // An infinite direction (the engine scales directions before they get here): as scalar.
    const MeshRay inf_dir{{0, 0, 0}, {kInf, 0, 0}, 0, kInf};
    MeshBvhHit hi, hsi;
    EXPECT_EQ(k.closest(inf_dir, hi), s.closest(inf_dir, hsi));
    EXPECT_EQ(k.every(inf_dir), s.every(inf_dir));
    // Infinite ray ranges with finite rays: the whole line, both directions.
    const MeshRay line{{0.1f, 0.2f, 0}, {0, 0, 1}, -kInf, kInf};
    MeshBvhHit h, hs;
    ASSERT_TRUE(k.closest(line, h));
    ASSERT_TRUE(s.closest(line, hs));
    EXPECT_EQ(h.t, hs.t);
    EXPECT_LT(h.t, 0);  // the nearest hit of the whole line is the one behind the origin
    EXPECT_EQ(k.every(line).size(), 2u);
  }
}

// Rays from inside closed meshes at every scale aimed exactly at shared vertices and at points
// on shared edges: none may slip through (nearest and any-hit), and the tied triangles resolve
// as on the scalar path.
TEST_P(WideKernels, ClosedMeshesAtEveryScale_RaysAtEdgesAndVertices_NeverMiss) {
  const TriangleSoup unit = make_octa_sphere(10);  // 800 triangles
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> along(0, 1), inside(-0.3f, 0.3f);
  int rays = 0, misses = 0;
  for (const bool quantised : kBothFormats)
    for (float scale : {1e-6f, 1e-3f, 1.0f, 1e3f, 1e6f}) {
      TriangleSoup soup = unit;
      const Vec3f shift{0.37f * scale, -0.21f * scale, 3.1f * scale};
      for (Vec3f& p : soup.positions) p = p * scale + shift;
      const MeshBvh bvh =
          build_mesh_bvh(soup.positions, soup.triangles, with_format({}, quantised));
      Kernels k{*kernels_, bvh}, s{kMeshKernelsScalar, bvh};
      for (int o = 0; o < 4; ++o) {
        const Vec3f origin = shift + Vec3f{inside(rng), inside(rng), inside(rng)} * scale;
        auto shoot = [&](const Vec3f& target) {
          const MeshRay r{origin, target - origin, 0, kInf};
          MeshBvhHit h, hs;
          misses += !k.closest(r, h);
          misses += !k.any(r);
          // The tie between the triangles that meet there resolves as on the scalar path.
          if (s.closest(r, hs)) {
            EXPECT_EQ(h.triangle, hs.triangle);
            EXPECT_EQ(h.t, hs.t);
          }
          ++rays;
        };
        for (const Vec3f& p : soup.positions) shoot(p);
        for (const auto& t : soup.triangles)
          for (int e = 0; e < 3; ++e) {
            const Vec3f a = soup.positions[t[e]], b = soup.positions[t[(e + 1) % 3]];
            shoot(a + 0.5f * (b - a));
            shoot(a + along(rng) * (b - a));
          }
      }
    }
  EXPECT_EQ(misses, 0) << "of " << rays << " rays";
  EXPECT_GT(rays, 40000);
}

TEST_P(WideKernels, DeepTree_StackSizedFromDepth_EveryHitFound) {
  // Triangles at geometrically shrinking spacing along a line make a deep SAH tree; a ray along
  // the line meets them all, so every level pushes children.
  TriangleSoup soup;
  float x = 1;
  for (int i = 0; i < 120; ++i, x *= 0.8f) {
    const auto base = static_cast<std::uint32_t>(soup.positions.size());
    soup.positions.insert(soup.positions.end(), {{x, -1, -1}, {x, 1, -1}, {x, 0, 1}});
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  MeshBvhConfig config;
  config.max_leaf_size = 1;
  for (const bool quantised : kBothFormats) {
    SCOPED_TRACE(quantised ? "quantised nodes" : "float nodes");
    const MeshBvh bvh =
        build_mesh_bvh(soup.positions, soup.triangles, with_format(config, quantised));
    Kernels k{*kernels_, bvh}, s{kMeshKernelsScalar, bvh};
    const MeshRay r{{2, 0, 0}, {-1, 0, 0}, 0, kInf};
    EXPECT_EQ(k.every(r).size(), soup.triangles.size()) << "depth " << bvh.depth;
    EXPECT_EQ(k.every(r), s.every(r));
    MeshBvhHit h;
    ASSERT_TRUE(k.closest(r, h));
    EXPECT_EQ(h.triangle, 0u);
  }
}

// Packets of eight rays under random masks give every active ray exactly its single-ray hit (t,
// barycentrics, triangle: bit for bit, ties at shared edges and vertices included) and leave the
// idle lanes alone; bundles around one direction (one packet) and scattered rays (traced one by
// one inside the packet call).
TEST_P(WideKernels, PacketsWithMixedMasks_EqualSingleRays) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> jitter(-0.05f, 0.05f), along(0, 1);
  const TriangleSoup sphere = make_octa_sphere(12);
  for (int run = 0; run < 6; ++run) {  // three meshes, each with both node formats
    const int mesh = run % 3;
    SCOPED_TRACE("mesh " + std::to_string(mesh) + (run < 3 ? ", float" : ", quantised"));
    const TriangleSoup soup =
        mesh == 0 ? sphere : random_soup(rng, 1500, 3, mesh == 1 ? 0.3f : 1.5f);
    MeshBvhConfig config;
    config.max_leaf_size = mesh == 2 ? 3 : 8;
    const MeshBvh bvh =
        build_mesh_bvh(soup.positions, soup.triangles, with_format(config, run >= 3));
    Kernels k{*kernels_, bvh}, s{kMeshKernelsScalar, bvh};
    int packet_hits = 0;
    for (int i = 0; i < 300; ++i) {
      MeshRay rays[8];
      const MeshRay base = random_ray(rng, 3);
      for (int l = 0; l < 8; ++l) {
        rays[l] = base;
        if (i % 3 == 0) {
          rays[l] = random_ray(rng, 3);  // scattered
        } else if (i % 3 == 1) {         // at a shared vertex or edge point of the mesh
          const auto& t = soup.triangles[rng() % soup.triangles.size()];
          const Vec3f a = soup.positions[t[0]], b = soup.positions[t[1]];
          rays[l].d = (l % 2 ? a : a + along(rng) * (b - a)) - base.o;
        } else {
          rays[l].d = base.d + Vec3f{jitter(rng), jitter(rng), jitter(rng)};
        }
      }
      const int mask = static_cast<int>(rng() & 0xFF);
      MeshBvhHit hits[8];
      for (MeshBvhHit& h : hits) h.triangle = 12345;  // idle lanes must keep this
      std::vector<PacketEntry> packet_stack(traversal_stack_size(bvh));
      const int found = k.k.closest8(bvh, rays, mask, hits, packet_stack.data(), k.stack.data());
      EXPECT_EQ(found & ~mask, 0);
      for (int l = 0; l < 8; ++l) {
        if (!(mask >> l & 1)) {
          EXPECT_EQ(hits[l].triangle, 12345u);
          continue;
        }
        MeshBvhHit one, scalar;
        const bool hit = k.closest(rays[l], one);
        ASSERT_EQ(s.closest(rays[l], scalar), hit);
        ASSERT_EQ((found >> l & 1) != 0, hit) << "packet " << i << " lane " << l;
        if (!hit) continue;
        ++packet_hits;
        EXPECT_EQ(hits[l].t, one.t);
        EXPECT_EQ(hits[l].b1, one.b1);
        EXPECT_EQ(hits[l].b2, one.b2);
        EXPECT_EQ(hits[l].triangle, one.triangle);
        EXPECT_EQ(one.triangle, scalar.triangle);
        EXPECT_EQ(one.t, scalar.t);
      }
      if (HasFailure()) return;
    }
    EXPECT_GT(packet_hits, 100);
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, WideKernels, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& info) {
                           return std::string(isa_name(info.param));
                         });

TEST(Isa, Names_RoundTrip) {
  for (Isa isa : kAllIsas) EXPECT_EQ(parse_isa(isa_name(isa)), isa);
  EXPECT_FALSE(parse_isa("avx9"));
  EXPECT_FALSE(parse_isa(""));
  EXPECT_TRUE(isa_supported(Isa::kScalar));
  EXPECT_TRUE(isa_supported(best_isa()));
  EXPECT_TRUE(isa_supported(active_isa()));
  EXPECT_EQ(active_mesh_kernels().isa, active_isa());
}

}  // namespace
}  // namespace raycast
