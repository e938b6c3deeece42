// Iso-surfaces: rays per second and memory on 128^3 and 512^3 grids, splatting time per million
// particles, and the export of a scene's density grid to POV-Ray's df3 format for
// bench/fluid_povray.sh.
// Run: build/release/bench/iso_bench [--benchmark_filter=...]
//      build/release/bench/iso_bench --export-df3 PARTICLES H OUT.df3   (prints the POV-Ray
//      parameters: domain, normalised iso, a max_gradient bound)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "volume/isosurface.h"
#include "volume/particle_file.h"
#include "volume/splat.h"

using namespace raycast;

namespace {

// A field of 40 soft blobs (sum of spheres' smooth bumps) on an n^3 grid over [-1, 1]^3.
const Isosurface& blobs(int n) {
  static std::map<int, Isosurface> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  ScalarGrid g;
  g.n = {n, n, n};
  g.lo = {-1, -1, -1};
  const double c = 2.0 / (n - 1);
  g.cell = {c, c, c};
  g.v.assign(std::size_t(n) * n * n, 0.0f);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.7, 0.7), r(0.05, 0.2);
  for (int b = 0; b < 40; ++b) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const double rad = r(rng), reach = 2 * rad;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, int((p[a] - reach + 1) / c));
      hi[a] = std::min(n - 1, int((p[a] + reach + 1) / c) + 1);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const Vec3 x{-1 + i * c, -1 + j * c, -1 + k * c};
          const double q = length(x - p) / reach;
          if (q < 1) g.v[g.index(i, j, k)] += float((1 - q * q) * (1 - q * q));
        }
  }
  return cache.emplace(n, make_isosurface(std::move(g), 0.3)).first->second;
}

void BM_IsoRays(benchmark::State& state) {
  const int n = int(state.range(0));
  const Isosurface& s = blobs(n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < 4096; ++i) {
    const Vec3 o = 3.0 * normalize(Vec3{u(rng), u(rng), u(rng)});
    rays.push_back(Ray{o, Vec3{0.6 * u(rng), 0.6 * u(rng), 0.6 * u(rng)} - o});
  }
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    LocalHit h;
    hits += intersect(s, rays[i++ & 4095], h);
    benchmark::DoNotOptimize(h);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_fraction"] = double(hits) / double(state.iterations());
  const IsoData& d = *s.data;
  state.counters["MiB"] = double(d.grid.v.size() * 4 + d.macro_min.size() * 8) / (1 << 20);
}
BENCHMARK(BM_IsoRays)->Arg(128)->Arg(512)->Unit(benchmark::kNanosecond);

void BM_SplatMillion(benchmark::State& state) {
  // 10^6 particles on a jittered lattice of spacing h / 1.3 (a block of water), all threads.
  const double h = 0.01, s = h / 1.3;
  std::vector<Vec3> p;
  std::mt19937 rng(1);
  std::normal_distribution<double> jitter(0, 0.05 * s);
  for (int k = 0; k < 100; ++k)
    for (int j = 0; j < 100; ++j)
      for (int i = 0; i < 100; ++i)
        p.push_back(Vec3{i * s + jitter(rng), j * s + jitter(rng), k * s + jitter(rng)});
  SplatParams sp;
  sp.h = h;
  for (auto _ : state) benchmark::DoNotOptimize(splat_particles(p, sp).v.data());
  state.SetItemsProcessed(state.iterations() * std::int64_t(p.size()));
}
BENCHMARK(BM_SplatMillion)->Unit(benchmark::kMillisecond)->UseRealTime();

// POV-Ray's df3: three big-endian uint16 sizes, then big-endian uint16 samples (x fastest)
// scaled to [0, 1] by the field's maximum.
int export_df3(const char* particles, double h, const char* out) {
  SplatParams sp;
  sp.h = h;
  const ScalarGrid g = splat_particles(read_particles(particles), sp);
  const float mx = *std::max_element(g.v.begin(), g.v.end());
  std::ofstream f(out, std::ios::binary);
  auto put16 = [&](unsigned v) {
    const char b[2] = {char(v >> 8), char(v & 255)};
    f.write(b, 2);
  };
  for (int a = 0; a < 3; ++a) put16(unsigned(g.n[a]));
  for (float v : g.v) put16(unsigned(std::lround(std::max(0.0f, v) / mx * 65535)));
  // The greatest gradient of the normalised trilinear field, in the unit cube's coordinates (the
  // density_file's own), over all cells: per axis the largest edge difference times n - 1.
  double grad2 = 0;
  for (int k = 0; k + 1 < g.n[2]; ++k)
    for (int j = 0; j + 1 < g.n[1]; ++j)
      for (int i = 0; i + 1 < g.n[0]; ++i) {
        double e[3] = {0, 0, 0};
        for (int c = 0; c < 8; ++c) {
          const int ci = i + (c & 1), cj = j + ((c >> 1) & 1), ck = k + (c >> 2);
          const float v = g.at(ci, cj, ck);
          if (!(c & 1)) e[0] = std::max(e[0], double(std::abs(g.at(ci + 1, cj, ck) - v)));
          if (!(c & 2)) e[1] = std::max(e[1], double(std::abs(g.at(ci, cj + 1, ck) - v)));
          if (!(c & 4)) e[2] = std::max(e[2], double(std::abs(g.at(ci, cj, ck + 1) - v)));
        }
        double s2 = 0;
        for (int a = 0; a < 3; ++a) s2 += std::pow(e[a] / mx * (g.n[a] - 1), 2);
        grad2 = std::max(grad2, s2);
      }
  const Vec3 hi = g.hi();
  std::printf(
      "dims %d %d %d\nmin %.9g %.9g %.9g\nmax %.9g %.9g %.9g\niso %.9g\nmax_gradient %.6g\n",
      g.n[0], g.n[1], g.n[2], g.lo.x, g.lo.y, g.lo.z, hi.x, hi.y, hi.z, 500.0 / mx,
      std::sqrt(grad2));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::strcmp(argv[1], "--export-df3") == 0)
    return export_df3(argv[2], std::atof(argv[3]), argv[4]);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
