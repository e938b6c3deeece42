// The demo scene rendered end to end (the pixel loop only: loading and writing excluded), per
// integrator, reporting rays per second.
#include <benchmark/benchmark.h>

#include "load/demo_scene.h"
#include "render/renderer.h"

namespace {

void render_demo(benchmark::State& state, raycast::RenderMode integrator) {
  const raycast::Scene scene = raycast::load_demo_scene();
  raycast::RenderOptions options;
  options.width = 200;
  options.height = 150;
  options.integrator = integrator;
  options.progress = false;
  std::uint64_t rays = 0;
  for (auto _ : state) {
    raycast::RenderStats stats;
    benchmark::DoNotOptimize(raycast::render(scene, options, &stats));
    rays += stats.rays;
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(render_demo, whitted, raycast::RenderMode::kWhitted)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(render_demo, raycast, raycast::RenderMode::kRaycast)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
