// Nanoseconds per ray for the quadric family and the planar solids, hit and miss rays measured
// separately (each shape in object space, no transform, no BVH):
//   cmake --build --preset release --target quadric_bench && build/release/bench/quadric_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/cone.h"
#include "geometry/cylinder.h"
#include "geometry/ellipsoid.h"
#include "geometry/polygon.h"
#include "geometry/polyhedron.h"
#include "geometry/quadric.h"
#include "geometry/slab.h"

namespace raycast {
namespace {

constexpr std::size_t kRays = 4096;

// kRays rays from a shell around the origin towards [-1, 1]^3 that hit (or miss) the shape.
template <class S>
std::vector<Ray> make_rays(const S& s, bool want_hit) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ray> rays;
  for (int tries = 0; rays.size() < kRays && tries < 10'000'000; ++tries) {
    Vec3 o{u(rng), u(rng), u(rng)};
    o = 4.0 * o / length(o);
    const Vec3 target{1.2 * u(rng), 1.2 * u(rng), 1.2 * u(rng)};
    const Ray ray{o, target - o};
    LocalHit h;
    if (intersect(s, ray, h) == want_hit) rays.push_back(ray);
  }
  return rays;
}

template <class S>
void run(benchmark::State& state, const S& shape, bool hit) {
  const std::vector<Ray> rays = make_rays(shape, hit);
  if (rays.size() < kRays) {
    state.SkipWithError("could not generate the rays");
    return;
  }
  for (auto _ : state) {
    for (const Ray& r : rays) {
      LocalHit h;
      benchmark::DoNotOptimize(intersect(shape, r, h));
      benchmark::DoNotOptimize(h);
    }
  }
  // Rays per second, inverted: seconds per ray, shown scaled (e.g. "12.3n" is 12.3 ns per ray).
  state.counters["per_ray"] =
      benchmark::Counter(static_cast<double>(state.iterations() * rays.size()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rays.size()));
}

std::vector<Vec3> star(int points) {
  std::vector<Vec3> v;
  for (int i = 0; i < 2 * points; ++i) {
    const double a = i * std::numbers::pi / points, r = i % 2 ? 0.4 : 1.0;
    v.push_back({r * std::cos(a), r * std::sin(a), 0.1 * r * std::cos(a)});
  }
  return v;
}

std::vector<std::array<double, 4>> dodecahedron() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 4>> p;
  for (double s1 : {-1.0, 1.0})
    for (double s2 : {-1.0, 1.0}) {
      p.push_back({0, s1, s2 * phi, -1.2});
      p.push_back({s1, s2 * phi, 0, -1.2});
      p.push_back({s2 * phi, 0, s1, -1.2});
    }
  return p;
}

#define RAYCAST_SHAPE_BENCH(name, make)                                       \
  void BM_##name##_Hit(benchmark::State& state) { run(state, make, true); }   \
  void BM_##name##_Miss(benchmark::State& state) { run(state, make, false); } \
  BENCHMARK(BM_##name##_Hit);                                                 \
  BENCHMARK(BM_##name##_Miss);

RAYCAST_SHAPE_BENCH(Ellipsoid, make_ellipsoid({0, 0, 0}, {1, 0.7, 0.5}))
RAYCAST_SHAPE_BENCH(QuadricEllipsoid,
                    make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 0.7, 0.5)))
RAYCAST_SHAPE_BENCH(QuadricHyperboloidBounded,
                    make_quadric(quadric_of_kind(QuadricKind::kHyperboloid1, 0.4, 0.4, 1),
                                 Aabb{{-1, -1, -1}, {1, 1, 1}}))
RAYCAST_SHAPE_BENCH(QuadricParaboloidOpen,
                    make_quadric(quadric_of_kind(QuadricKind::kParaboloid, 0.5, 0.5, 1),
                                 Aabb{{-1, -1, 0}, {1, 1, 1}}, true))
RAYCAST_SHAPE_BENCH(Cylinder, make_cylinder(0.8, -1, 1))
RAYCAST_SHAPE_BENCH(CylinderPartial, make_cylinder(0.8, -1, 1, 270))
RAYCAST_SHAPE_BENCH(CylinderFromTo, make_cylinder({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, 0.6))
RAYCAST_SHAPE_BENCH(Cone, make_cone(0.9, 1.5))
RAYCAST_SHAPE_BENCH(ConePartial, make_cone(0.9, 1.5, 270))
RAYCAST_SHAPE_BENCH(ConeFromTo, make_cone({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, 0.8, 0.3))
RAYCAST_SHAPE_BENCH(Polygon10, make_polygon(star(5)))
RAYCAST_SHAPE_BENCH(Slab, make_slab({0.3, 1, 0.2}, -0.3, 0.4))
RAYCAST_SHAPE_BENCH(PolyhedronCube, make_polyhedron({{1, 0, 0, -0.8},
                                                     {-1, 0, 0, -0.8},
                                                     {0, 1, 0, -0.8},
                                                     {0, -1, 0, -0.8},
                                                     {0, 0, 1, -0.8},
                                                     {0, 0, -1, -0.8}}))
RAYCAST_SHAPE_BENCH(PolyhedronDodecahedron, make_polyhedron(dodecahedron()))

}  // namespace
}  // namespace raycast

BENCHMARK_MAIN();
