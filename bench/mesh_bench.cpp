// Kernel benchmarks of the mesh layer: BVH build, closest-hit and any-hit traversal, and the two
// ray/triangle tests (watertight against Moller-Trumbore). Peer comparisons: `raycast bench`.
#include <benchmark/benchmark.h>

#include <limits>
#include <random>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "mesh/triangle.h"
#include "mesh/wide_kernels.h"

namespace raycast {
namespace {

std::vector<MeshRay> random_rays(std::size_t n) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<MeshRay> rays(n);
  for (auto& r : rays) {
    r.o = {u(rng) * 0.5f, u(rng) * 0.5f, u(rng) * 0.5f};
    r.d = {u(rng), u(rng), u(rng)};
    r.tmin = 0;
    r.tmax = 1e30f;
  }
  return rays;
}

void BM_BuildMeshBvh(benchmark::State& state) {
  const TriangleSoup soup =
      make_procedural_mesh("sphere", static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(build_mesh_bvh(soup.positions, soup.triangles));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(soup.triangles.size()));
}
BENCHMARK(BM_BuildMeshBvh)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_IntersectClosest(benchmark::State& state) {
  const TriangleSoup soup =
      make_procedural_mesh("sphere", static_cast<std::size_t>(state.range(0)));
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
  const auto rays = random_rays(1 << 16);
  std::size_t i = 0;
  for (auto _ : state) {
    MeshBvhHit h;
    benchmark::DoNotOptimize(intersect_closest(bvh, rays[i++ & 0xFFFF], h));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_IntersectClosest)->Arg(10000)->Arg(1000000);

void BM_IntersectAny(benchmark::State& state) {
  const TriangleSoup soup =
      make_procedural_mesh("sphere", static_cast<std::size_t>(state.range(0)));
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
  const auto rays = random_rays(1 << 16);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(intersect_any(bvh, rays[i++ & 0xFFFF]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_IntersectAny)->Arg(1000000);

// The closest-hit kernels of one ISA (argument: 0 scalar, 1 sse4, 2 avx2, 3 avx512).
void BM_ClosestPerIsa(benchmark::State& state) {
  const Isa isa = static_cast<Isa>(state.range(0));
  const MeshKernels* k = mesh_kernels(isa);
  if (!k) {
    state.SkipWithError("ISA not supported here");
    return;
  }
  state.SetLabel(isa_name(isa));
  const TriangleSoup soup = make_procedural_mesh("sphere", 1000000);
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
  std::vector<TraversalEntry> stack(traversal_stack_size(bvh));
  const auto rays = random_rays(1 << 16);
  std::size_t i = 0;
  for (auto _ : state) {
    MeshBvhHit h;
    benchmark::DoNotOptimize(k->closest(bvh, rays[i++ & 0xFFFF], h, stack.data()));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClosestPerIsa)->DenseRange(0, 3);

// Watertightness at scale, once: 10^6 rays from inside a closed 80,000-triangle sphere aimed at
// its shared vertices and at points on its shared edges, through the active ISA's kernels
// (nearest and any-hit). The counter `misses` must be 0 (the tests do 10^5 rays per ISA).
void BM_WatertightMillionRays(benchmark::State& state) {
  const TriangleSoup soup = make_octa_sphere(100);
  const MeshBvh bvh = build_mesh_bvh(soup.positions, soup.triangles);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> along(0, 1), inside(-0.3f, 0.3f);
  double misses = 0, rays = 0;
  for (auto _ : state) {
    while (rays < 1e6) {
      const Vec3f o{inside(rng), inside(rng), inside(rng)};
      const auto& t = soup.triangles[rng() % soup.triangles.size()];
      const Vec3f a = soup.positions[t[0]], b = soup.positions[t[1]];
      for (const Vec3f& target : {a, a + 0.5f * (b - a), a + along(rng) * (b - a)}) {
        const MeshRay r{o, target - o, 0, std::numeric_limits<float>::infinity()};
        MeshBvhHit h;
        misses += !intersect_closest(bvh, r, h);
        misses += !intersect_any(bvh, r);
        rays += 1;
      }
    }
  }
  state.counters["rays"] = rays;
  state.counters["misses"] = misses;
}
BENCHMARK(BM_WatertightMillionRays)->Iterations(1)->Unit(benchmark::kMillisecond);

template <bool kWatertight>
void BM_TriangleTest(benchmark::State& state) {
  const TriangleSoup soup = make_octa_sphere(32);
  const auto rays = random_rays(1024);
  std::vector<WatertightRay> prepared;
  for (const MeshRay& r : rays) prepared.push_back(make_watertight_ray(r.o, r.d));  // once per ray
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    const MeshRay& r = rays[i & 1023];
    const auto& t = soup.triangles[i % soup.triangles.size()];
    ++i;
    TriangleHit h;
    if constexpr (kWatertight)
      hits += intersect_watertight(prepared[(i - 1) & 1023], soup.positions[t[0]],
                                   soup.positions[t[1]], soup.positions[t[2]], r.tmin, r.tmax, h);
    else
      hits += intersect_moller_trumbore(r.o, r.d, soup.positions[t[0]], soup.positions[t[1]],
                                        soup.positions[t[2]], r.tmin, r.tmax, h);
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TriangleTest<true>)->Name("BM_TriangleWatertight");
BENCHMARK(BM_TriangleTest<false>)->Name("BM_TriangleMollerTrumbore");

}  // namespace
}  // namespace raycast
BENCHMARK_MAIN();
