// Every ISA's queries (nearest, any and every hit; packets of eight) against brute force, exactly,
// on rays at the node boxes' boundaries of axis-aligned grid meshes, whose boxes' faces lie in the
// triangles' planes and on their edges, at scales 1e-6 to 1e6, both node formats:
// - origins exactly on the faces, edges and vertices of the grid (so on the boxes' planes; tmin
//   = 0: hits at t = 0);
// - rays lying in the boxes' planes (a direction component +0 or -0, or two of them: along a grid
//   line), and rays from a grid plane aimed at vertices and edge points in the same plane: they
//   meet triangles exactly at their edges (the node test's 1/d = +-infinity, mesh/wide_traverse.inl
//   prepare);
// - ranges ending exactly at the nearest hit (t == tmax, which the node test must not cull) and
//   one float before it.
// Brute force is the watertight test on every triangle (mesh/triangle.h: the same operations as
// the kernels' leaf test), nearest ties to the least triangle index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include "mesh/procedural.h"
#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

namespace raycast {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Grid coordinate i of the cube [shift, shift + n * step]: one expression, so every vertex, box
// plane and ray origin on grid line i has the same float.
float grid(float i, float step, float shift) { return i * step + shift; }

// The surface of the cube [shift, shift + n * step]^3, n x n quads (two triangles each) per face.
TriangleSoup grid_cube(int n, float step, float shift) {
  TriangleSoup s;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const auto base = static_cast<std::uint32_t>(s.positions.size());
          for (int k = 0; k < 4; ++k) {
            float p[3];
            p[axis] = grid(float(side * n), step, shift);
            p[(axis + 1) % 3] = grid(float(i + (k & 1)), step, shift);
            p[(axis + 2) % 3] = grid(float(j + (k >> 1)), step, shift);
            s.positions.push_back({p[0], p[1], p[2]});
          }
          s.triangles.push_back({base, base + 1, base + 3});
          s.triangles.push_back({base, base + 3, base + 2});
        }
  return s;
}

// Every watertight hit in [tmin, tmax], sorted by (t, triangle): the first is the nearest.
std::vector<std::pair<float, std::uint32_t>> brute_hits(const TriangleSoup& s, const MeshRay& r) {
  const WatertightRay w = make_watertight_ray(r.o, r.d);
  std::vector<std::pair<float, std::uint32_t>> hits;
  for (std::uint32_t i = 0; i < s.triangles.size(); ++i) {
    const auto& t = s.triangles[i];
    TriangleHit h;
    if (intersect_watertight(w, s.positions[t[0]], s.positions[t[1]], s.positions[t[2]], r.tmin,
                             r.tmax, h))
      hits.emplace_back(h.t, i);
  }
  std::sort(hits.begin(), hits.end());
  return hits;
}

class BoxBoundary : public testing::TestWithParam<Isa> {};

TEST_P(BoxBoundary, RaysOnAndInBoxPlanes_RangesEndingAtHits_MatchBruteForce) {
  const MeshKernels* kernels = mesh_kernels(GetParam());
  if (!kernels) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  const int n = 6;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(-1, n + 1), vertex(0, n), quarter(0, 4), coin(0, 1);
  std::normal_distribution<float> dir;
  int rays = 0, wrong_closest = 0, wrong_any = 0, wrong_every = 0, wrong_packet = 0;
  for (const auto& scale :
       {std::pair{1.0f, 0.0f}, std::pair{0.37f, -1.1f}, std::pair{1e-6f, 3e-6f},
        std::pair{1e-3f, 0.0f}, std::pair{1e3f, -2.5e3f}, std::pair{1e6f, 1e6f}})
    for (const bool quantised : {false, true}) {
      // Plain variables, not a structured binding: the lambdas below capture them (clang 14
      // rejects capturing a binding).
      const float step = scale.first, shift = scale.second;
      const TriangleSoup soup = grid_cube(n, step, shift);
      MeshBvhConfig config;
      config.max_leaf_size = 2;  // more boxes, more boundaries
      config.quantise_above = quantised ? 0 : std::numeric_limits<std::size_t>::max();
      const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles, config);
      std::vector<TraversalEntry> stack(traversal_stack_size(bvh)),
          single(traversal_stack_size(bvh));
      std::vector<PacketEntry> packet_stack(traversal_stack_size(bvh));
      // A grid point (quarter steps: on a face, an edge or a vertex of a quad), inside, on or
      // outside the cube.
      const auto point = [&] {
        Vec3f p;
        for (int a = 0; a < 3; ++a)
          p[a] = grid(float(cell(rng) * 4 + quarter(rng) - 2) * 0.25f, step, shift);
        return p;
      };
      // One ray checked against brute force: closest, any, every.
      const auto check = [&](const MeshRay& r) {
        const auto hits = brute_hits(soup, r);
        MeshBvhHit h;
        const bool found = kernels->closest(bvh, r, h, stack.data());
        wrong_closest += found != !hits.empty() ||
                         (found && (h.t != hits[0].first || h.triangle != hits[0].second));
        wrong_any += kernels->any(bvh, r, stack.data()) != !hits.empty();
        std::vector<MeshBvhHit> all;
        kernels->every(bvh, r, all, stack.data());
        std::vector<std::pair<float, std::uint32_t>> got;
        for (const MeshBvhHit& e : all) got.emplace_back(e.t, e.triangle);
        std::sort(got.begin(), got.end());
        wrong_every += got != hits;
        ++rays;
        return hits.empty() ? -1.0f : hits[0].first;
      };
      // A ray and, when it hits at t > 0, the same ray ending exactly at t and one float before.
      const auto check_ranges = [&](MeshRay r) {
        const float t = check(r);
        if (!(t > 0)) return;
        for (const float tmax : {t, std::nextafter(t, 0.0f)}) {
          r.tmax = tmax;
          check(r);
        }
      };
      for (int k = 0; k < 600; ++k) {
        MeshRay r;
        r.o = point();
        r.tmin = 0;
        r.tmax = k % 2 ? kInf : grid(float(n) * 0.5f, step, 0);
        // A random direction with zero, one or two components +0 or -0 (lying in one or two
        // grid planes).
        do r.d = {dir(rng), dir(rng), dir(rng)};
        while (!(length_squared(r.d) > 0.01f));
        const int zeros = k % 3;
        for (int z = 0; z < zeros; ++z)
          r.d[std::size_t((k / 3 + z) % 3)] = coin(rng) ? 0.0f : -0.0f;
        check_ranges(r);
        // Aimed at a grid vertex or an edge's midpoint on the cube; from a point in the same
        // grid plane when k is odd (one direction component exactly 0: the ray lies in a plane
        // of the boxes and meets the triangles at their edges).
        Vec3f target;
        for (int a = 0; a < 3; ++a) target[a] = grid(float(vertex(rng)), step, shift);
        target[std::size_t(k % 3)] = grid(float(k / 3 % 2 * n), step, shift);  // on a face
        if (coin(rng)) {
          const std::size_t a = std::size_t((k + 1) % 3);
          target[a] = grid(float(vertex(rng) % n) + 0.5f, step, shift);
        }
        if (k % 2) r.o[std::size_t((k + 2) % 3)] = target[std::size_t((k + 2) % 3)];
        r.d = target - r.o;
        if (!(length_squared(r.d) > 0)) continue;
        r.tmax = kInf;
        check_ranges(r);
      }
      // Packets of eight rays from a grid point below the cube on every axis (one direction
      // octant: one packet) to grid vertices and edge points of the cube, ending at infinity or
      // exactly at their nearest hits: the packet's node test, its lanes' own slab tests and its
      // pop, each lane against brute force.
      for (int k = 0; k < 80; ++k) {
        MeshRay lanes[8];
        Vec3f o;
        for (int a = 0; a < 3; ++a) o[a] = grid(float(quarter(rng) - 8) * 0.25f, step, shift);
        for (MeshRay& r : lanes) {
          Vec3f target;
          for (int a = 0; a < 3; ++a) target[a] = grid(float(vertex(rng)), step, shift);
          target[std::size_t(rng() % 3)] = grid(float(vertex(rng) % n) + 0.5f, step, shift);
          r = {o, target - o, 0, kInf};
          if (k % 2) {
            const auto b = brute_hits(soup, r);
            if (!b.empty()) r.tmax = b[0].first;
          }
        }
        MeshBvhHit hits[8];
        const int found =
            kernels->closest8(bvh, lanes, 0xFF, hits, packet_stack.data(), single.data());
        for (int l = 0; l < 8; ++l) {
          const auto b = brute_hits(soup, lanes[l]);
          const bool hit = found >> l & 1;
          wrong_packet += hit != !b.empty() ||
                          (hit && (hits[l].t != b[0].first || hits[l].triangle != b[0].second));
          ++rays;
        }
      }
    }
  EXPECT_EQ(wrong_closest, 0) << "of " << rays << " rays";
  EXPECT_EQ(wrong_any, 0) << "of " << rays << " rays";
  EXPECT_EQ(wrong_every, 0) << "of " << rays << " rays";
  EXPECT_EQ(wrong_packet, 0) << "of " << rays << " rays";
  EXPECT_GT(rays, 20000);
}

INSTANTIATE_TEST_SUITE_P(AllIsas, BoxBoundary, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& i) {
                           return std::string(isa_name(i.param));
                         });

}  // namespace
}  // namespace raycast
