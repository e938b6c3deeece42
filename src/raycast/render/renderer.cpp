#include "render/renderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <stdexcept>

#include "math/lane_array.h"
#include "render/antialias.h"
#include "render/camera.h"
#include "render/camera_packets.h"
#include "render/integrator.h"

namespace raycast {

namespace {

constexpr int kTileSize = 16;

/// CPU seconds used so far by the whole process (every thread).
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// Starts oneTBB's scheduler and its worker threads, before the render's clock starts. The
/// first parallel job of a process loads the scheduler and creates the workers (0.5 ms, 1-2 % of
/// a 640x480 render on 2 threads); POV-Ray's Trace Time likewise starts inside each render
/// thread once it runs, so the comparison of bench/povray/suite.sh is like for like.
void start_threads() {
  tbb::parallel_for(0, 64, [](int) {});
}

/// A one-line bar on stderr, redrawn when the percentage changes; silent unless enabled.
class Progress {
 public:
  Progress(bool enabled, std::size_t total) : enabled_(enabled), total_(total) {}
  void advance() {
    if (!enabled_) return;  // no shared counter for the threads to pass around
    const std::size_t done = ++done_;
    const int percent = int(100 * done / total_);
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock || percent == shown_) return;
    shown_ = percent;
    char bar[41];
    for (int i = 0; i < 40; ++i) bar[i] = i < percent * 40 / 100 ? '#' : '.';
    bar[40] = 0;
    std::fprintf(stderr, "\rrendering [%s] %3d%%", bar, percent);
    std::fflush(stderr);
  }
  void finish() {
    if (!enabled_) return;
    std::fprintf(stderr, "\r%60s\r", "");
    std::fflush(stderr);
  }

 private:
  bool enabled_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  std::mutex mutex_;
  int shown_ = -1;
};

}  // namespace

void sample_offset(int k, int n, double jitter_x, double jitter_y, double& x, double& y) {
  if (n <= 1) {
    x = y = 0.5;
    return;
  }
  int sx = 1;
  for (int d = 1; d * d <= n; ++d)
    if (n % d == 0) sx = d;
  const int sy = n / sx;
  x = ((k % sx) + jitter_x) / sx;
  y = ((k / sx) + jitter_y) / sy;
}

namespace {

// The image's size, samples and the region to render, from the scene and the options; throws
// std::invalid_argument on values out of range.
struct RenderFrame {
  int width = 0, height = 0, spp = 0;
  PixelRect rect;
};

RenderFrame resolve_frame(const Scene& scene, const RenderOptions& options) {
  if (options.width < 0 || options.height < 0 || options.spp < 0 || options.threads < 0)
    throw std::invalid_argument("render: width, height, spp and threads must not be negative");
  RenderFrame f;
  const int width = options.width > 0 ? options.width : scene.image.width;
  const int height = options.height > 0 ? options.height : scene.image.height;
  const int spp = options.spp > 0 ? options.spp : scene.image.samples;
  if (width <= 0 || height <= 0 || spp <= 0)
    throw std::invalid_argument("render: image width, height and samples must be positive");
  if (static_cast<long long>(width) * height > kMaxImagePixels)
    throw std::invalid_argument("render: width * height must be at most " +
                                std::to_string(kMaxImagePixels) + " pixels");

  const PixelRect rect = options.region.value_or(PixelRect{0, 0, width, height});
  if (rect.x0 < 0 || rect.y0 < 0 || rect.x1 > width || rect.y1 > height || rect.x0 >= rect.x1 ||
      rect.y0 >= rect.y1)
    throw std::invalid_argument("render: the region must be a non-empty part of the image");
  f.width = width, f.height = height, f.spp = spp, f.rect = rect;
  return f;
}

// What both pixel loops share.
struct RenderJob {
  const RenderOptions& options;
  const Camera& camera;
  const Integrator& integrator;
  const ScenePackets& packets;
  bool use_packets;
  unsigned seed;
  RenderFrame frame;

  bool cancelled() const {
    return options.cancel && options.cancel->load(std::memory_order_relaxed);
  }
};

// Adaptive antialiasing: render_adaptive's passes, their batches traced as camera-ray packets
// where the scene takes them.
Image render_antialiased(const RenderJob& job, const AntialiasSettings& aa, RenderStats* stats) {
  const RenderOptions& options = job.options;
  const Camera& camera = job.camera;
  const Integrator& integrator = job.integrator;
  const ScenePackets& packets = job.packets;
  const bool use_packets = job.use_packets;
  const PixelRect rect = job.frame.rect;
  const int width = job.frame.width, height = job.frame.height;
  const int region_width = rect.x1 - rect.x0, region_height = rect.y1 - rect.y0;
  const auto cancelled = [&] { return job.cancelled(); };
  Image image(region_width, region_height);
  Progress rows(options.progress && isatty(STDERR_FILENO), 2 * std::size_t(region_height));
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  AdaptiveStats adaptive;
  const RasterSampler sample = [&](double x, double y, SampleState& state) {
    if (cancelled()) return Color{};
    return integrator.li(camera.ray(x, y), state);
  };
  // The passes' batches: packets of packets.width() rays, or one ray at a time.
  const RasterBatchSampler batch = [&](const RasterSample* at, int count, Color* values) {
    if (cancelled()) {
      for (int i = 0; i < count; ++i) values[i] = Color{};
      return;
    }
    if (!use_packets) {
      const Camera cam = camera;  // a copy kept in registers, as in the 1-spp loop below
      for (int i = 0; i < count; ++i)
        values[i] = integrator.li(cam.ray(at[i].x, at[i].y), *at[i].state);
      return;
    }
    LaneArray<Ray, kMaxRasterBatch> ray;
    LaneArray<SceneHit, kMaxRasterBatch> hit;
    for (int b = 0; b < count; b += packets.width()) {
      const int lanes = std::min(packets.width(), count - b);
      for (int l = 0; l < lanes; ++l) ray[l] = camera.ray(at[b + l].x, at[b + l].y);
      const int found = packets.intersect(ray.data(), (1 << lanes) - 1, hit.data());
      for (int l = 0; l < lanes; ++l)
        values[b + l] = integrator.li_hit(ray[l], found >> l & 1, hit[l], *at[b + l].state);
    }
  };
  render_adaptive(
      aa, job.seed, sample, image, adaptive, [&] { rows.advance(); },
      RasterWindow{rect.x0, rect.y0, width, height}, batch);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  rows.finish();
  if (stats) {
    stats->width = region_width;
    stats->height = region_height;
    stats->spp = 0;
    stats->antialias = aa.method;
    stats->samples = adaptive.samples;
    stats->threads =
        int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    stats->seconds = seconds;
    stats->cpu_seconds = cpu_seconds;
    stats->rays = adaptive.rays;
  }
  return image;
}

// The fixed-sample loop over tiles: each pixel's samples stratified and jittered (the centre at
// one sample), or each tile traced as camera-ray packets where the scene takes them.
Image render_fixed(const RenderJob& job, RenderStats* stats) {
  const Camera& camera = job.camera;
  const Integrator& integrator = job.integrator;
  const ScenePackets& packets = job.packets;
  const bool use_packets = job.use_packets;
  const unsigned seed = job.seed;
  const int spp = job.frame.spp;
  const PixelRect rect = job.frame.rect;
  const int region_width = rect.x1 - rect.x0, region_height = rect.y1 - rect.y0;
  const auto cancelled = [&] { return job.cancelled(); };
  Image image(region_width, region_height);
  tbb::enumerable_thread_specific<std::uint64_t> rays(0);
  const int tiles_x = (region_width + kTileSize - 1) / kTileSize;
  const int tiles_y = (region_height + kTileSize - 1) / kTileSize;
  Progress progress(job.options.progress && isatty(STDERR_FILENO), std::size_t(tiles_x) * tiles_y);
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  tbb::parallel_for(
      tbb::blocked_range2d<int>(0, tiles_y, 1, 0, tiles_x, 1), [&](const auto& range) {
        std::uint64_t& counter = rays.local();
        // Copies the pixel loop keeps in registers and hoists the row's camera terms from: the
        // integrator's calls could, as far as the compiler knows, change what the lambda
        // captures by reference, which made it reload them at every pixel.
        const Camera cam = camera;
        const PixelRect area = rect;
        const int samples = spp;
        for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty) {
          for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
            if (cancelled()) return;
            const int y1 = std::min(rect.y1, rect.y0 + (ty + 1) * kTileSize);
            const int x1 = std::min(rect.x1, rect.x0 + (tx + 1) * kTileSize);
            if (use_packets) {
              const PixelRect tile{rect.x0 + tx * kTileSize, rect.y0 + ty * kTileSize, x1, y1};
              render_packet_tile(packets, camera, integrator, spp, seed, tile, rect, image,
                                 counter);
              progress.advance();
              continue;
            }
            std::uint64_t traced = 0;
            for (int y = area.y0 + ty * kTileSize; y < y1; ++y) {
              for (int x = area.x0 + tx * kTileSize; x < x1; ++x) {
                SampleState state{Rng::for_pixel(x, y, seed), 0};
                if (samples == 1) {  // the centre, as sample_offset gives for n = 1
                  image.set(x - area.x0, y - area.y0,
                            Vec3f(integrator.li(cam.ray(x + 0.5, y + 0.5), state)));
                  traced += state.rays;
                  continue;
                }
                Color sum{0, 0, 0};
                for (int k = 0; k < samples; ++k) {
                  double ox, oy;
                  const double jx = samples > 1 ? state.rng.uniform() : 0.5;
                  const double jy = samples > 1 ? state.rng.uniform() : 0.5;
                  sample_offset(k, samples, jx, jy, ox, oy);
                  sum += integrator.li(cam.ray(x + ox, y + oy), state);
                }
                image.set(x - area.x0, y - area.y0, Vec3f(sum / double(samples)));
                traced += state.rays;
              }
            }
            counter += traced;
            progress.advance();
          }
        }
      });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  progress.finish();

  if (stats) {
    stats->width = region_width;
    stats->height = region_height;
    stats->spp = spp;
    stats->threads =
        int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    stats->seconds = seconds;
    stats->cpu_seconds = cpu_seconds;
    stats->samples = std::uint64_t(region_width) * region_height * spp;
    stats->rays = rays.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
  }
  return image;
}

}  // namespace

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats) {
  const RenderFrame frame = resolve_frame(scene, options);
  std::optional<tbb::global_control> limit;
  if (options.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
  start_threads();  // first, so that the workers start while the image is allocated

  const Camera camera(camera_or_default(scene), frame.width, frame.height);
  const Integrator integrator(scene, render_mode(scene, options));
  const AntialiasSettings aa = options.antialias ? *options.antialias
                               : options.spp > 0 ? AntialiasSettings{}
                                                 : scene.render.antialias;
  // Camera-ray packets where the scene has meshes that ScenePackets can trace as packets.
  const ScenePackets packets(scene);
  const RenderJob job{
      options,           camera, integrator, packets, options.camera_packets && packets.usable(),
      scene.render.seed, frame};
  if (aa.method != AntialiasMethod::kNone) return render_antialiased(job, aa, stats);
  return render_fixed(job, stats);
}

std::string format_summary(const RenderStats& s) {
  char line[256];
  if (s.antialias != AntialiasMethod::kNone) {
    static const char* const kNames[] = {"none", "method 1", "method 2", "variance"};
    const double per_pixel =
        s.width > 0 && s.height > 0 ? double(s.samples) / (double(s.width) * s.height) : 0;
    std::snprintf(line, sizeof line,
                  "%dx%d, adaptive %s (%.2f spp), %d threads: %.3f s (cpu %.3f s), %llu rays, "
                  "%.2f Mrays/s",
                  s.width, s.height, kNames[int(s.antialias)], per_pixel, s.threads, s.seconds,
                  s.cpu_seconds, static_cast<unsigned long long>(s.rays), s.mrays_per_second());
    return line;
  }
  std::snprintf(line, sizeof line,
                "%dx%d, %d spp, %d threads: %.3f s (cpu %.3f s), %llu rays, %.2f Mrays/s", s.width,
                s.height, s.spp, s.threads, s.seconds, s.cpu_seconds,
                static_cast<unsigned long long>(s.rays), s.mrays_per_second());
  return line;
}

}  // namespace raycast
