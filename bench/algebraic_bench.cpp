// Nanoseconds per ray for the higher-degree shapes, hit and miss rays separately.
// Run: build/release/bench/algebraic_bench   (ns/ray is the time per iteration: one ray each).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/algebraic.h"
#include "geometry/implicit.h"
#include "geometry/revolution.h"
#include "geometry/torus.h"

using namespace raycast;

namespace {

// 1024 rays from a sphere of radius 3 * extent around the shape towards random points of its
// box, sorted into those that hit and those that miss.
template <class S>
void make_rays(const S& s, std::vector<Ray>& hits, std::vector<Ray>& misses) {
  const Aabb b = bounds(s);
  const Vec3 c = b.centre(), e = b.extent();
  const double radius = 1.5 * length(e);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  while (hits.size() < 1024 || misses.size() < 1024) {
    Vec3 dir{u(rng), u(rng), u(rng)};
    if (length_squared(dir) > 1 || length_squared(dir) < 1e-4) continue;
    const Vec3 o = c + radius * normalize(dir);
    const Vec3 target = c + 0.5 * Vec3{e.x * u(rng), e.y * u(rng), e.z * u(rng)};
    const Ray r{o, target - o};
    LocalHit h;
    auto& bucket = intersect(s, r, h) ? hits : misses;
    if (bucket.size() < 1024) bucket.push_back(r);
  }
}

template <class S>
void run(benchmark::State& state, const S& s, bool want_hits) {
  std::vector<Ray> hits, misses;
  make_rays(s, hits, misses);
  const std::vector<Ray>& rays = want_hits ? hits : misses;
  std::size_t i = 0;
  for (auto _ : state) {
    LocalHit h;
    benchmark::DoNotOptimize(intersect(s, rays[i++ & 1023], h));
    benchmark::DoNotOptimize(h);
  }
  state.SetItemsProcessed(state.iterations());
}

const Torus& torus() {
  static const Torus s = make_torus(1, 0.3);
  return s;
}
const Algebraic& heart() {
  static const Algebraic s = make_algebraic("(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3",
                                            Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}});
  return s;
}
const Algebraic& torus_algebraic() {
  static const Algebraic s = make_algebraic("(x^2 + y^2 + z^2 - 1 - 0.09)^2 - 4*(0.09 - z^2)",
                                            Aabb{{-1.3, -1.3, -0.3}, {1.3, 1.3, 0.3}});
  return s;
}
const Algebraic& degree12() {
  static const Algebraic s = make_algebraic(
      "(x^2+y^2+z^2-0.25)*(x^2+y^2+z^2-0.5625)*(x^2+y^2+z^2-1)*(x^2+y^2+z^2-1.5625)*"
      "(x^2+y^2+z^2-2.25)*(x^2+y^2+z^2-3.0625)",
      Aabb{{-2, -2, -2}, {2, 2, 2}});
  return s;
}
const Implicit& seed_implicit() {
  static const Implicit s = make_implicit(
      "(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)", Aabb{{-4, -4, -4}, {4, 4, 4}});
  return s;
}
const Algebraic& degree8() {
  static const Algebraic s = make_algebraic(
      "((x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + y^2)) * "
      "(((x-1)^2 + y^2 + z^2 + 0.84)^2 - 4*((x-1)^2 + z^2))",
      Aabb{{-1.5, -1.5, -1.5}, {2.5, 1.5, 1.5}});
  return s;
}
const Implicit& gyroid() {
  static const Implicit s =
      make_implicit("sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", Aabb{{-4, -4, -4}, {4, 4, 4}});
  return s;
}
const Implicit& heart_implicit() {
  static const Implicit s = make_implicit("(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3",
                                          Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}});
  return s;
}
const Implicit& sphere_implicit() {
  static const Implicit s =
      make_implicit("x^2 + y^2 + z^2 - 1", Aabb{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}});
  return s;
}
const Revolution& vase() {
  static const Revolution s = make_revolution({{0, 0},
                                               {0, 0},
                                               {0, 0},
                                               {0.8, 0},
                                               {1.2, 0.6},
                                               {0.5, 1.6},
                                               {0.4, 2.4},
                                               {0.8, 3.0},
                                               {0.8, 3.0},
                                               {0.8, 3.0}},
                                              ProfileCurve::kBSpline);
  return s;
}
const Revolution& goblet() {
  static const Revolution s = make_revolution(
      {{0, 0}, {0.7, 0}, {0.7, 0.1}, {0.1, 0.3}, {0.1, 1.2}, {0.8, 1.6}, {0.9, 2.4}},
      ProfileCurve::kLinear);
  return s;
}

#define RAYCAST_SHAPE_BENCH(name, shape)                              \
  void name##_Hit(benchmark::State& st) { run(st, shape(), true); }   \
  void name##_Miss(benchmark::State& st) { run(st, shape(), false); } \
  BENCHMARK(name##_Hit);                                              \
  BENCHMARK(name##_Miss)

RAYCAST_SHAPE_BENCH(Torus, torus);
RAYCAST_SHAPE_BENCH(AlgebraicTorus, torus_algebraic);
RAYCAST_SHAPE_BENCH(AlgebraicHeart, heart);
RAYCAST_SHAPE_BENCH(AlgebraicDegree8, degree8);
RAYCAST_SHAPE_BENCH(AlgebraicDegree12, degree12);
RAYCAST_SHAPE_BENCH(ImplicitSphere, sphere_implicit);
RAYCAST_SHAPE_BENCH(ImplicitSeed, seed_implicit);
RAYCAST_SHAPE_BENCH(ImplicitGyroid, gyroid);
RAYCAST_SHAPE_BENCH(ImplicitHeart, heart_implicit);
RAYCAST_SHAPE_BENCH(RevolutionLinear, goblet);
RAYCAST_SHAPE_BENCH(RevolutionBSpline, vase);

}  // namespace

BENCHMARK_MAIN();
