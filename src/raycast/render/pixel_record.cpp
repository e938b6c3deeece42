#include "render/pixel_record.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "render/camera.h"
#include "render/integrator.h"

namespace raycast {

namespace {

/// CPU seconds used so far by the whole process (every thread).
double recorded_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

constexpr std::array<const char*, 9> kOutputNames = {"ambient",    "diffuse",    "specular",
                                                     "reflection", "refraction", "shadowed",
                                                     "cost.rays",  "cost.depth", "cost.time"};

/// What one sample's recorder gathers: the camera ray's terms (its rays by kind are the
/// integrator's RayRecorder::counts). Without terms to gather it asks for no events.
class SampleRecorder final : public RayRecorder {
 public:
  Color ambient_term, diffuse_term, specular_term, reflection_term, refraction_term;
  double lit = 0, unshadowed = 0;  // the direct light that arrived, and before shadows

  void reset() {
    ambient_term = diffuse_term = specular_term = reflection_term = refraction_term = Color{};
    lit = unshadowed = 0;
    open_.clear();
  }
  void child(RayKind kind, double weight, const Color& tint) override {
    next_ = {kind, weight, tint};
  }
  void begin_ray(const Ray&, int) override {
    open_.push_back(open_.empty() ? Open{RayKind::kCamera, 1, {1, 1, 1}} : next_);
  }
  // A camera ray that misses has the background as its one term: put with ambient.
  void miss(const Color& background) override {
    if (open_.size() == 1) ambient_term = background;
  }
  void hit(const SceneHit&, const SurfaceInfo&, std::size_t, bool, const Vec3&) override {}
  void ambient(const Color& term) override {
    if (open_.size() == 1) ambient_term = term;
  }
  void light(const LightSample& s) override {
    if (!s.shadow_ray || open_.size() != 1) return;
    const Color term = s.diffuse + s.specular;
    diffuse_term += mul(s.visibility, s.diffuse);
    specular_term += mul(s.visibility, s.specular);
    unshadowed += term.x + term.y + term.z;
    const Color got = mul(s.visibility, term);
    lit += got.x + got.y + got.z;
  }
  void split(double, double, bool, double, double) override {}
  void stop(RayStop) override {}
  void end_ray(const Color& radiance) override {
    const Open ray = open_.back();
    open_.pop_back();
    if (open_.size() != 1) return;  // only the camera ray's children are its terms
    const Color seen = ray.weight * mul(ray.tint, radiance);
    if (ray.kind == RayKind::kReflection) reflection_term += seen;
    if (ray.kind == RayKind::kRefraction) refraction_term += seen;
  }

 private:
  struct Open {
    RayKind kind;
    double weight;
    Color tint;
  };
  std::vector<Open> open_;
  Open next_{RayKind::kCamera, 1, {1, 1, 1}};
};

/// The sample's value of output k (per-sample values are averaged over the pixel).
double grey_value(RecordedOutput k, const SampleRecorder& r, std::uint64_t rays, int depth) {
  switch (k) {
    case RecordedOutput::kShadowed:
      return r.unshadowed > 0 ? 1 - r.lit / r.unshadowed : 0;
    case RecordedOutput::kCostRays:
      return double(rays);
    case RecordedOutput::kCostDepth:
      return depth;
    default:
      return 0;
  }
}

Color term_value(RecordedOutput k, const SampleRecorder& r) {
  switch (k) {
    case RecordedOutput::kAmbient:
      return r.ambient_term;
    case RecordedOutput::kDiffuse:
      return r.diffuse_term;
    case RecordedOutput::kSpecular:
      return r.specular_term;
    case RecordedOutput::kReflection:
      return r.reflection_term;
    case RecordedOutput::kRefraction:
      return r.refraction_term;
    default:
      return {};
  }
}

bool is_term(RecordedOutput k) { return k <= RecordedOutput::kRefraction; }

}  // namespace

std::optional<RecordedOutput> recorded_output_named(std::string_view name) {
  for (std::size_t k = 0; k < kOutputNames.size(); ++k)
    if (name == kOutputNames[k]) return RecordedOutput(k);
  return std::nullopt;
}

const char* recorded_output_name(RecordedOutput output) {
  return kOutputNames[std::size_t(output)];
}

RecordedRender render_recorded(const Scene& scene, const RenderOptions& options,
                               const std::vector<RecordedOutput>& outputs, RenderStats* stats) {
  const int width = options.width > 0 ? options.width : scene.image.width;
  const int height = options.height > 0 ? options.height : scene.image.height;
  const int spp = options.spp > 0 ? options.spp : scene.image.samples;
  if (width <= 0 || height <= 0 || spp <= 0 ||
      static_cast<long long>(width) * height > kMaxImagePixels)
    throw std::invalid_argument("render: image width, height and samples must be positive");
  std::optional<tbb::global_control> limit;
  if (options.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
  const Camera camera(camera_or_default(scene), width, height);
  const Integrator integrator(scene, RenderMode::kWhitted);
  RecordedRender result;
  result.image = Image(width, height);
  for (std::size_t k = 0; k < outputs.size(); ++k) result.outputs.emplace_back(width, height);
  tbb::enumerable_thread_specific<RayCounts> counts;
  const bool timed =
      std::find(outputs.begin(), outputs.end(), RecordedOutput::kCostTime) != outputs.end();
  const bool terms = std::any_of(outputs.begin(), outputs.end(),
                                 [](RecordedOutput k) { return k <= RecordedOutput::kShadowed; });
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = recorded_cpu_seconds();
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    SampleRecorder recorder;
    recorder.events = terms;
    recorder.camera_ray_only = true;  // the terms are the camera ray's
    std::vector<Color> sums(outputs.size());
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        // The clock only where cost.time asks for it (two reads per pixel are 10 % of a render).
        const auto pixel_start =
            timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
        SampleState state{Rng::for_pixel(x, y, scene.render.seed), 0, &recorder};
        std::fill(sums.begin(), sums.end(), Color{});
        Color sum{0, 0, 0};
        for (int k = 0; k < spp; ++k) {
          double ox = 0.5, oy = 0.5;
          if (spp > 1) {
            const double jx = state.rng.uniform();
            const double jy = state.rng.uniform();
            sample_offset(k, spp, jx, jy, ox, oy);
          }
          recorder.reset();
          const std::uint64_t rays_before = state.rays;
          const int deepest = recorder.counts.max_depth;
          recorder.counts.max_depth = 0;  // the sample's own deepest ray, below
          const Color c = integrator.li(camera.ray(x + ox, y + oy), state);
          const int depth = recorder.counts.max_depth;
          recorder.counts.max_depth = std::max(deepest, depth);
          sum += c;
          for (std::size_t o = 0; o < outputs.size(); ++o) {
            if (is_term(outputs[o])) {
              sums[o] += term_value(outputs[o], recorder);
              continue;
            }
            const double g = grey_value(outputs[o], recorder, state.rays - rays_before, depth);
            sums[o] += Color{g, g, g};
          }
        }
        // As the renderer's fixed-sample loop: one sample's value as it is, else the mean.
        result.image.set(x, y, Vec3f(spp == 1 ? sum : sum / double(spp)));
        const double micros = timed ? std::chrono::duration<double, std::micro>(
                                          std::chrono::steady_clock::now() - pixel_start)
                                          .count()
                                    : 0;
        for (std::size_t o = 0; o < outputs.size(); ++o) {
          const Color v = outputs[o] == RecordedOutput::kCostTime ? Color{micros, micros, micros}
                                                                  : sums[o] / double(spp);
          result.outputs[o].set(x, y, Vec3f(v));
        }
      }
    RayCounts& mine = counts.local();
    mine.camera += recorder.counts.camera;
    mine.reflection += recorder.counts.reflection;
    mine.refraction += recorder.counts.refraction;
    mine.shadow += recorder.counts.shadow;
    mine.max_depth = std::max(mine.max_depth, recorder.counts.max_depth);
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const RayCounts& c : counts) {
    result.counts.camera += c.camera;
    result.counts.reflection += c.reflection;
    result.counts.refraction += c.refraction;
    result.counts.shadow += c.shadow;
    result.counts.max_depth = std::max(result.counts.max_depth, c.max_depth);
  }
  if (stats) {
    stats->width = width;
    stats->height = height;
    stats->spp = spp;
    stats->threads =
        int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    stats->seconds = seconds;
    stats->cpu_seconds = recorded_cpu_seconds() - cpu_start;
    stats->samples = std::uint64_t(width) * height * spp;
    stats->rays = result.counts.total();
  }
  return result;
}

}  // namespace raycast
