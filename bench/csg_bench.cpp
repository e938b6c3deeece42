// CSG and instancing throughput: rays per second through a 5-level tree of 32 primitives, and
// through 10^6 instances of one CSG object (with the memory each instance costs).
//   build/release/bench/csg_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "load/loader.h"
#include "objects/prototype.h"

namespace raycast {
namespace {

// Resident set size in bytes (Linux), for the memory an instance costs.
std::size_t rss_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * 4096;
}

// A full binary tree of `levels` operations over 2^levels spheres; the operation cycles by level
// (union at the root, then intersection, difference, union, ...) and spheres overlap enough that
// every operation keeps something.
std::string tree_yaml(int level, int levels, Vec3 centre, double size, const std::string& indent,
                      int& leaf) {
  if (level == levels) {
    ++leaf;
    return indent + "- sphere: {center: [" + std::to_string(centre.x) + ", " +
           std::to_string(centre.y) + ", " + std::to_string(centre.z) +
           "], radius: " + std::to_string(size) + "}\n";
  }
  const char* ops[] = {"union", "intersection", "difference"};
  std::string s = indent + "- " + ops[level % 3] + ":\n";
  const int axis = level % 3;
  // Union spreads its operands apart; intersection and difference offset them a little.
  const double offset = level % 3 == 0 ? 0.5 * size : 0.25 * size;
  Vec3 a = centre, b = centre;
  a[axis] -= offset;
  b[axis] += offset;
  const double child = level % 3 == 0 ? 0.7 * size : 0.9 * size;
  s += tree_yaml(level + 1, levels, a, child, indent + "    ", leaf);
  s += tree_yaml(level + 1, levels, b, level % 3 == 2 ? 0.6 * child : child, indent + "    ", leaf);
  return s;
}

std::vector<Ray> grid_rays(const Aabb& box, int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Ray> rays;
  const Vec3 e = box.extent();
  for (int i = 0; i < n; ++i) {
    const Vec3 target = box.lo + Vec3{u(rng) * e.x, u(rng) * e.y, u(rng) * e.z};
    const Vec3 from = box.centre() + Vec3{0.3, 0.5, -2.5} * length(e);
    rays.push_back({from, target - from});
  }
  return rays;
}

void BM_CsgTree_5Levels_32Spheres(benchmark::State& state) {
  int leaves = 0;
  const Scene scene = load_scene_text("objects:\n" + tree_yaml(0, 5, {0, 0, 0}, 1, "  ", leaves));
  const std::vector<Ray> rays = grid_rays(scene.bounds(), 1 << 14, 1);
  std::size_t hits = 0, done = 0;
  for (auto _ : state) {
    for (const Ray& r : rays) {
      SceneHit h;
      hits += scene.intersect(r, h);
    }
    done += rays.size();
  }
  state.counters["rays/s"] = benchmark::Counter(double(done), benchmark::Counter::kIsRate);
  state.counters["hit_fraction"] = double(hits) / double(done);
  state.counters["leaves"] = leaves;
}
BENCHMARK(BM_CsgTree_5Levels_32Spheres)->Unit(benchmark::kMillisecond);

void BM_CsgTree_5Levels_32Spheres_All(benchmark::State& state) {
  int leaves = 0;
  const Scene scene = load_scene_text("objects:\n" + tree_yaml(0, 5, {0, 0, 0}, 1, "  ", leaves));
  const std::vector<Ray> rays = grid_rays(scene.bounds(), 1 << 14, 1);
  std::vector<Crossing> all;
  std::size_t done = 0;
  for (auto _ : state) {
    for (const Ray& r : rays) scene.intersect_all(r, all);
    done += rays.size();
  }
  state.counters["rays/s"] = benchmark::Counter(double(done), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CsgTree_5Levels_32Spheres_All)->Unit(benchmark::kMillisecond);

// The seed's cube (six planes) minus a sphere, as one prototype placed `count` times on a grid.
Scene instanced_scene(int count, bool share) {
  const Scene proto_scene = load_scene_text(
      "objects:\n"
      "  - difference:\n"
      "      - intersection:\n"
      "          - plane: {normal: [1, 0, 0], point: [0.4, 0, 0]}\n"
      "          - plane: {normal: [-1, 0, 0], point: [-0.4, 0, 0]}\n"
      "          - plane: {normal: [0, 1, 0], point: [0, 0.4, 0]}\n"
      "          - plane: {normal: [0, -1, 0], point: [0, -0.4, 0]}\n"
      "          - plane: {normal: [0, 0, 1], point: [0, 0, 0.4]}\n"
      "          - plane: {normal: [0, 0, -1], point: [0, 0, -0.4]}\n"
      "      - sphere: {radius: 0.52}\n");
  Scene scene;
  scene.materials.emplace_back();
  const auto proto = make_prototype({proto_scene.objects[0]});
  const int side = static_cast<int>(std::ceil(std::cbrt(double(count))));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0, 360);
  scene.objects.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    Object o;
    if (share)
      o.shape = InstanceShape{proto};
    else
      o.shape = proto_scene.objects[0].shape;  // the CSG object itself (its tree is shared too)
    o.xf =
        Transform::translate({double(i % side), double(i / side % side), double(i / side / side)}) *
        Transform::rotate({1, 1, 0.3}, angle(rng));
    o.entry = i;
    scene.objects.push_back(std::move(o));
  }
  scene.entries = count;
  scene.build();
  return scene;
}

void BM_Instances(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  const std::size_t before = rss_bytes();
  const Scene scene = instanced_scene(count, true);
  const std::size_t after = rss_bytes();
  const std::vector<Ray> rays = grid_rays(scene.bounds(), 1 << 15, 2);
  std::size_t hits = 0, done = 0;
  for (auto _ : state) {
    for (const Ray& r : rays) {
      SceneHit h;
      hits += scene.intersect(r, h);
    }
    done += rays.size();
  }
  state.counters["rays/s"] = benchmark::Counter(double(done), benchmark::Counter::kIsRate);
  state.counters["hit_fraction"] = double(hits) / double(done);
  state.counters["rss_bytes/instance"] = double(after - before) / count;
  state.counters["object_bytes"] = double(sizeof(Object));
  state.counters["bvh_bytes/instance"] = double(scene.accel_bytes()) / count;
  state.counters["build_ms"] = scene.build_ms();
}
BENCHMARK(BM_Instances)->Arg(1000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(3);

// Memory per copy of an 8-object group (a CSG object and seven spheres): instanced (one Object
// per copy, the group stored once) against flattened (eight Objects per copy).
void BM_GroupMemory(benchmark::State& state) {
  const bool instanced = state.range(0) == 1;
  const int copies = 100000;
  const Scene parts = load_scene_text(
      "objects:\n"
      "  - difference: [{sphere: {radius: 0.3}}, {sphere: {center: [0.2, 0, 0], radius: 0.2}}]\n"
      "  - group:\n"
      "      - {sphere: {center: [0.3, 0, 0], radius: 0.1}}\n"
      "      - {sphere: {center: [-0.3, 0, 0], radius: 0.1}}\n"
      "      - {sphere: {center: [0, 0.3, 0], radius: 0.1}}\n"
      "      - {sphere: {center: [0, -0.3, 0], radius: 0.1}}\n"
      "      - {sphere: {center: [0, 0, 0.3], radius: 0.1}}\n"
      "      - {sphere: {center: [0, 0, -0.3], radius: 0.1}}\n"
      "      - {sphere: {center: [0.2, 0.2, 0.2], radius: 0.1}}\n");
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::size_t before = rss_bytes();
    {
      Scene scene;
      scene.materials.emplace_back();
      const auto proto = make_prototype(parts.objects);
      for (int i = 0; i < copies; ++i) {
        const Transform xf =
            Transform::translate({double(i % 100), double(i / 100 % 100), double(i / 10000)});
        if (instanced) {
          Object o;
          o.shape = InstanceShape{proto};
          o.xf = xf;
          o.entry = i;
          scene.objects.push_back(std::move(o));
        } else {
          for (Object o : parts.objects) {
            o.xf = o.xf ? xf * *o.xf : xf;
            o.entry = i;
            scene.objects.push_back(std::move(o));
          }
        }
      }
      scene.objects.shrink_to_fit();
      scene.build();
      bytes = rss_bytes() - before;
      benchmark::DoNotOptimize(scene.objects.data());
    }
  }
  state.counters["rss_bytes/copy"] = double(bytes) / copies;
}
BENCHMARK(BM_GroupMemory)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("instanced")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace raycast

BENCHMARK_MAIN();
