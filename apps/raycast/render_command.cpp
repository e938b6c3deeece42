// `raycast render [SCENE] [-o out.png] ...` (docs/cli.md): renders a scene, or the
// built-in demo, to an image whose format follows the extension; AOVs go beside it.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "commands.h"
#include "distributed/distributed.h"
#include "distributed/launch.h"
#include "io/image.h"
#include "load/demo_scene.h"
#include "load/loader.h"
#include "load/validate.h"
#include "output_file.h"
#include "pov_options.h"
#include "render/renderer.h"
#include "render_frames.h"
#include "render_output.h"
#include "render_recorded.h"

namespace raycast::cli {

namespace {

struct Options {
  std::string scene, output = "out.png", integrator, aovs, antialias, frames, max_depth;
  int width = 0, height = 0, spp = 0, threads = 0;
  bool stats = false, heatmap = false;
};

/// `--max-depth N` or `A-B` (a sweep), or nothing: false for anything else or numbers outside
/// [0, 64].
bool parse_depths(const std::string& text, int& first, int& last) {
  constexpr int kMaxSweepDepth = 64;
  if (text.empty()) return true;  // not given: first and last stay -1
  char dash = 0, extra = 0;
  const int n = std::sscanf(text.c_str(), "%d%c%d%c", &first, &dash, &last, &extra);
  if (n == 1)
    last = first;
  else if (n != 3 || dash != '-')
    return false;
  return first >= 0 && last >= first && last <= kMaxSweepDepth;
}

/// An output that cannot be written is not bad input (docs/cli.md: exit 1).
int output_error(const std::string& message) {
  std::fprintf(stderr, "raycast render: %s\n", message.c_str());
  return 1;
}

/// `--antialias none` or `METHOD[,THRESHOLD[,DEPTH]]` (METHOD 1, 2, neighbour, subdivide or
/// variance; defaults as render.antialias). Returns false with a message for anything else.
bool parse_antialias(const std::string& text, AntialiasSettings& aa, std::string& error) {
  std::vector<std::string> parts;
  std::stringstream list(text);
  for (std::string part; std::getline(list, part, ',');) parts.push_back(part);
  error =
      "--antialias must be none or METHOD[,THRESHOLD[,DEPTH]] with METHOD 1, 2, neighbour, "
      "subdivide or variance, THRESHOLD >= 0 and DEPTH in [1, 16]; got '" +
      text + "'";
  if (parts.empty() || parts.size() > 3) return false;
  const std::string& m = parts[0];
  if (m == "none" && parts.size() == 1) {
    aa.method = AntialiasMethod::kNone;
    return true;
  }
  if (m == "1" || m == "neighbour")
    aa.method = AntialiasMethod::kNeighbour;
  else if (m == "2" || m == "subdivide")
    aa.method = AntialiasMethod::kSubdivide;
  else if (m == "variance")
    aa.method = AntialiasMethod::kVariance;
  else
    return false;
  if (parts.size() > 1) {
    char* end = nullptr;
    aa.threshold = std::strtod(parts[1].c_str(), &end);
    if (parts[1].empty() || *end != 0 || !std::isfinite(aa.threshold) || aa.threshold < 0)
      return false;
  }
  if (parts.size() > 2) {
    char* end = nullptr;
    const long depth = std::strtol(parts[2].c_str(), &end, 10);
    if (parts[2].empty() || *end != 0 || depth < 1 || depth > 16) return false;
    aa.depth = int(depth);
  }
  return true;
}

/// --heatmap, --stats and --max-depth (docs/rendering.md "Term outputs" to "Depth sweep").
void add_recording_flags(CLI::App& cmd, Options& opt) {
  cmd.add_flag("--heatmap", opt.heatmap,
               "Also write the shadowed and cost outputs as false-colour OUT.<name>.png with a "
               "colour bar");
  cmd.add_flag("--stats", opt.stats,
               "Print a statistics report: rays by kind, time by phase, the BVHs' shape");
  cmd.add_option("--max-depth", opt.max_depth,
                 "Secondary ray depth (overrides the scene); A-B renders each depth and writes "
                 "them side by side as one contact sheet");
}

/// The scene at `path` (the demo for an empty path), and the seconds its loading took.
Scene load_timed(const std::string& path, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  Scene scene = path.empty() ? load_demo_scene() : load_scene_file(path);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return scene;
}

/// Renders the image and the depth, normal, id and albedo outputs, writes them and prints the
/// summary line. Returns the exit code.
int render_and_save(const Scene& scene, const RenderOptions& options, const std::string& source,
                    const std::string& output,
                    const std::vector<std::pair<std::string, RenderMode>>& aovs) {
  RenderStats stats;
  const Image image = render(scene, options, &stats);
  const bool depth = render_mode(scene, options) == RenderMode::kDepth;
  try {
    save_render(image, output, depth);
    for (const auto& [name, aov] : aovs) {
      RenderOptions aov_options = options;
      aov_options.aov = aov;
      aov_options.progress = false;
      RenderStats aov_stats;
      save_image(render(scene, aov_options, &aov_stats), aov_path(output, name));
      stats.rays += aov_stats.rays;
      stats.seconds += aov_stats.seconds;
    }
  } catch (const ImageError& e) {
    return output_error(e.what());
  }
  std::fprintf(stderr, "raycast render: %s -> %s: %s\n", source.empty() ? "<demo>" : source.c_str(),
               is_stdout(output) ? "<stdout>" : output.c_str(), format_summary(stats).c_str());
  return 0;
}

}  // namespace

Action add_render_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a scene (or the built-in demo) to an image");
  auto opt = std::make_shared<Options>();
  cmd->add_option("SCENE", opt->scene,
                  "Scene file (YAML or JSON; - reads standard input); none renders the built-in "
                  "demo");
  cmd->add_option("-o,--output", opt->output,
                  "Output image: .png (8-bit sRGB), .pfm or .exr (linear float), - for PNG on "
                  "standard output; default out.png");
  auto* width =
      cmd->add_option("--width", opt->width, "Image width in pixels (overrides the scene)");
  auto* height =
      cmd->add_option("--height", opt->height, "Image height in pixels (overrides the scene)");
  auto* spp = cmd->add_option("--spp", opt->spp,
                              "Samples per pixel (overrides the scene, and turns off its adaptive "
                              "antialiasing)");
  auto* antialias =
      cmd->add_option("--antialias", opt->antialias,
                      "Adaptive antialiasing: none, or METHOD[,THRESHOLD[,DEPTH]] with METHOD 1 "
                      "(neighbour), 2 (subdivide) or variance (overrides the scene and --spp)");
  auto* threads =
      cmd->add_option("--threads", opt->threads, "Worker threads (default and 0: all cores)");
  add_pov_options(cmd);
  cmd->add_option("--integrator", opt->integrator,
                  "whitted, raycast, depth, normal or id (overrides the scene)");
  cmd->add_option("--aov", opt->aovs,
                  "Comma-separated extra outputs written beside the image as OUT.<name>.pfm: "
                  "depth, normal, id, albedo; the Whitted terms ambient, diffuse, specular, "
                  "reflection, refraction, shadowed; the costs cost.rays, cost.depth, cost.time");
  add_recording_flags(*cmd, *opt);
  cmd->add_option("--frames", opt->frames,
                  "Render frames A-B: {frame} / {frame:04d} in the scene's data paths and in -o");
  return [opt, width, height, spp, threads, antialias] {
    // Validate everything before the (possibly long) render.
    constexpr int kMaxSize = kMaxImageSide;  // also the --spp limit, like image.samples
    const std::tuple<const char*, CLI::Option*, int, int, int> limits[] = {
        {"--width", width, opt->width, 1, kMaxSize},
        {"--height", height, opt->height, 1, kMaxSize},
        {"--spp", spp, opt->spp, 1, kMaxSize},
        {"--threads", threads, opt->threads, 0, kMaxThreads}};
    for (const auto& [name, option, value, lo, hi] : limits)
      if (option->count() > 0 && (value < lo || value > hi)) {
        std::ostringstream message;
        message << name << " must be in [" << lo << ", " << hi << "], got " << value;
        return usage_error(message.str());
      }
    RenderOptions options;
    options.width = opt->width;
    options.height = opt->height;
    options.spp = opt->spp;
    options.threads = opt->threads;
    if (antialias->count() > 0) {
      AntialiasSettings aa;
      std::string error;
      if (!parse_antialias(opt->antialias, aa, error)) return usage_error(error);
      options.antialias = aa;
    }
    if (!opt->integrator.empty()) {
      options.integrator = integrator_named(opt->integrator);
      if (!options.integrator)
        return usage_error(std::string("--integrator must be ") + kIntegratorNames + ", got '" +
                           opt->integrator + "'");
    }
    std::vector<std::pair<std::string, RenderMode>> aovs;
    RecordedRequest recorded{{}, opt->heatmap, opt->stats, 0};
    const std::string plain_aovs = take_recorded_outputs(opt->aovs, recorded.outputs);
    if (std::string bad; !parse_aov_list(plain_aovs, aovs, bad))
      return usage_error(std::string("--aov takes a comma-separated list of ") + kAovNames + ", " +
                         kRecordedOutputNames + "; got '" + bad + "'");
    int depth_first = -1, depth_last = -1;
    if (!parse_depths(opt->max_depth, depth_first, depth_last))
      return usage_error("--max-depth must be N or A-B, 0 <= A <= B <= 64: " + opt->max_depth);
    const bool records = recorded.stats || !recorded.outputs.empty();
    if (const std::string problem = recording_problem(
            recorded, antialias->count() > 0 || !opt->frames.empty() || !aovs.empty(),
            depth_last > depth_first, options.integrator.value_or(RenderMode::kWhitted),
            is_stdout(opt->output));
        !problem.empty())
      return usage_error(problem);
    if (is_stdout(opt->output)) {
      if (!aovs.empty()) return usage_error("--aov writes files beside -o: it needs a file, not -");
      if (!opt->frames.empty()) return usage_error("--frames writes one file per frame, not -");
    } else {
      try {
        image_format_for(opt->output);
      } catch (const ImageError& e) {
        return usage_error(e.what());
      }
    }

    // Refuse an image too large to allocate before loading (and building) the scene.
    if (opt->width > 0 && opt->height > 0 &&
        static_cast<long long>(opt->width) * opt->height > kMaxImagePixels)
      return usage_error("--width * --height must be at most " + std::to_string(kMaxImagePixels) +
                         " pixels, got " + std::to_string(opt->width) + " x " +
                         std::to_string(opt->height));
    if (!opt->frames.empty()) return render_frames(opt->scene, opt->output, opt->frames, options);
    if (const std::string problem = output_problem(opt->output); !problem.empty())
      return output_error(problem);
    if (distributed::active() && (records || !opt->max_depth.empty()))
      return usage_error("--stats, the outputs it records and --max-depth need one process");
    if (distributed::active())  // under mpirun: tiles over the ranks (docs/distributed.md)
      return distributed::render_image(opt->scene, opt->output, options, aovs);
    Scene scene = load_timed(opt->scene, recorded.load_seconds);
    if (depth_first >= 0) scene.render.max_depth = depth_first;
    if (const std::string warning = no_lights_warning(scene, render_mode(scene, options));
        !warning.empty())
      std::fprintf(stderr, "raycast render: warning: %s\n", warning.c_str());
    const long long pixels =
        static_cast<long long>(opt->width > 0 ? opt->width : scene.image.width) *
        (opt->height > 0 ? opt->height : scene.image.height);
    if (pixels > kMaxImagePixels)
      return usage_error("the image must be at most " + std::to_string(kMaxImagePixels) +
                         " pixels, got " + std::to_string(pixels));
    if (depth_last > depth_first)
      return render_depth_sweep(scene, options, opt->output, depth_first, depth_last);
    if (records) return render_and_record(scene, options, opt->output, recorded);
    return render_and_save(scene, options, opt->scene, opt->output, aovs);
  };
}

}  // namespace raycast::cli
