// The any-hit query of every ISA (the AVX-512 one has its own node test: integer min/max and the
// exit's widening in the reciprocal, mesh/wide_traverse.inl) against brute force on rays at the
// boxes' boundaries: origins exactly on the faces, edges and vertices of an axis-aligned grid
// mesh (so on the node boxes' planes, tmin = 0: hits at t = 0), and ranges ending exactly at a
// hit (tmax = t) or one float before it: the same answers as the scalar kernels, and as brute
// force where the rays are not parallel to an axis plane.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh/procedural.h"
#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

namespace raycast {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// The surface of the cube [0, n * step]^3, n x n quads (two triangles each) per face.
TriangleSoup grid_cube(int n, float step) {
  TriangleSoup s;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const auto base = static_cast<std::uint32_t>(s.positions.size());
          for (int k = 0; k < 4; ++k) {
            float p[3];
            p[axis] = float(side * n) * step;
            p[(axis + 1) % 3] = float(i + (k & 1)) * step;
            p[(axis + 2) % 3] = float(j + (k >> 1)) * step;
            s.positions.push_back({p[0], p[1], p[2]});
          }
          s.triangles.push_back({base, base + 1, base + 3});
          s.triangles.push_back({base, base + 3, base + 2});
        }
  return s;
}

// Whether any triangle is hit in [tmin, tmax] (the watertight test), and the least such t.
bool brute_any(const TriangleSoup& s, const MeshRay& r, float* nearest = nullptr) {
  const WatertightRay w = make_watertight_ray(r.o, r.d);
  bool found = false;
  for (const auto& t : s.triangles) {
    TriangleHit h;
    if (!intersect_watertight(w, s.positions[t[0]], s.positions[t[1]], s.positions[t[2]], r.tmin,
                              r.tmax, h))
      continue;
    if (nearest && (!found || h.t < *nearest)) *nearest = h.t;
    found = true;
  }
  return found;
}

class AnyHitBoundary : public testing::TestWithParam<Isa> {};

TEST_P(AnyHitBoundary, OriginsOnBoxPlanesAndRangesEndingAtHits_MatchBruteForce) {
  const MeshKernels* kernels = mesh_kernels(GetParam());
  if (!kernels) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  const int n = 12;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(0, n);
  std::uniform_int_distribution<int> quarter(0, 4);
  std::normal_distribution<float> dir;
  int rays = 0, wrong = 0, differ = 0;
  for (const float step : {1.0f, 0.37f, 1e-3f, 1e3f}) {
    const TriangleSoup soup = grid_cube(n, step);
    const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
    std::vector<TraversalEntry> stack(traversal_stack_size(bvh));
    const auto any = [&](const MeshRay& r) { return kernels->any(bvh, r, stack.data()); };
    for (int k = 0; k < 3000; ++k) {
      // A point on the grid's planes (quarter steps: on a face, an edge or a vertex of a quad),
      // inside, on or outside the cube.
      MeshRay r;
      r.o = {float(cell(rng) * 4 + quarter(rng) - 2) * 0.25f * step,
             float(cell(rng) * 4 + quarter(rng) - 2) * 0.25f * step,
             float(cell(rng) * 4 + quarter(rng) - 2) * 0.25f * step};
      do r.d = {dir(rng), dir(rng), dir(rng)};
      while (!(length_squared(r.d) > 0.01f));
      if (k % 3 == 0) r.d[std::size_t(k % 9 / 3)] = 0;  // parallel to one axis's planes
      r.tmin = 0;
      r.tmax = k % 2 ? kInf : float(n) * step * 0.5f;
      float t = 0;
      const bool hit = brute_any(soup, r, &t);
      const bool found = any(r);
      differ += found != kMeshKernelsScalar.any(bvh, r, stack.data());
      // A ray lying in a box's face plane (a zero direction component) can miss a triangle on
      // that face's edge on every ISA alike (its slab on that axis is [-huge, 0] or [0, huge]
      // with the direction clamped to +-2^-64): checked against the scalar kernels only.
      if (r.d.x != 0 && r.d.y != 0 && r.d.z != 0) wrong += found != hit;
      ++rays;
      if (!hit || !(t > 0)) continue;
      // The range ending exactly at the nearest hit, and one float before it: as the scalar
      // kernels (no kernel narrows the boxes' entry distances, so a leaf whose entry rounds
      // above a hit at t == tmax can be culled, on every ISA alike).
      for (const float tmax : {t, std::nextafter(t, 0.0f)}) {
        r.tmax = tmax;
        differ += any(r) != kMeshKernelsScalar.any(bvh, r, stack.data());
        ++rays;
      }
    }
  }
  EXPECT_EQ(wrong, 0) << "of " << rays << " rays";
  EXPECT_EQ(differ, 0) << "of " << rays << " rays";
  EXPECT_GT(rays, 20000);
}

INSTANTIATE_TEST_SUITE_P(AllIsas, AnyHitBoundary, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& i) {
                           return std::string(isa_name(i.param));
                         });

}  // namespace
}  // namespace raycast
