// `raycast explain SCENE --pixel X Y [--sample N] [--json | --svg FILE]` (docs/explain.md): the
// ray tree of one pixel, as text, JSON or an SVG drawing.
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.h"
#include "load/demo_scene.h"
#include "load/loader.h"
#include "render/explain.h"
#include "render/explain_format.h"
#include "render/explain_svg.h"

namespace raycast::cli {

namespace {

struct ExplainArgs {
  std::string scene, svg;
  std::vector<int> pixel;
  int sample = 0, width = 0, height = 0, spp = 0, max_depth = -1;
  bool json = false;
};

int explain_usage_error(const std::string& message) {
  std::fprintf(stderr, "raycast explain: %s\n", message.c_str());
  return 2;
}

}  // namespace

Action add_explain_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("explain", "Explain one pixel: its whole ray tree");
  auto opt = std::make_shared<ExplainArgs>();
  cmd->add_option("SCENE", opt->scene,
                  "Scene file (YAML, JSON or POV-Ray); none explains the built-in demo");
  cmd->add_option("--pixel", opt->pixel, "The pixel: X from the left, Y from the top")
      ->expected(2)
      ->required();
  cmd->add_option("--sample", opt->sample, "Which of the pixel's samples (default 0)");
  cmd->add_option("--width", opt->width, "Image width in pixels (overrides the scene)");
  cmd->add_option("--height", opt->height, "Image height in pixels (overrides the scene)");
  cmd->add_option("--spp", opt->spp, "Samples per pixel (overrides the scene)");
  cmd->add_option("--max-depth", opt->max_depth, "Secondary ray depth (overrides the scene)");
  auto* json = cmd->add_flag("--json", opt->json, "Write the tree as JSON");
  cmd->add_option("--svg", opt->svg,
                  "Write the tree drawn in the camera ray's plane over the scene's "
                  "cross-section to this SVG file (- for standard output)")
      ->excludes(json);
  return [opt] {
    for (const auto& [name, value] :
         {std::pair{"--width", opt->width}, std::pair{"--height", opt->height},
          std::pair{"--spp", opt->spp}})
      if (value < 0 || value > kMaxImageSide)
        return explain_usage_error(std::string(name) + " must be in [1, " +
                                   std::to_string(kMaxImageSide) + "], got " +
                                   std::to_string(value));
    if (opt->max_depth < -1 || opt->max_depth > 1000)
      return explain_usage_error("--max-depth must be in [0, 1000], got " +
                                 std::to_string(opt->max_depth));
    Scene scene = opt->scene.empty() ? load_demo_scene() : load_scene_file(opt->scene);
    if (opt->max_depth >= 0) scene.render.max_depth = opt->max_depth;
    ExplainOptions options;
    options.x = opt->pixel[0];
    options.y = opt->pixel[1];
    options.sample = opt->sample;
    options.width = opt->width;
    options.height = opt->height;
    options.spp = opt->spp;
    Explanation e;
    try {
      e = explain_pixel(scene, options);
    } catch (const std::invalid_argument& error) {
      return explain_usage_error(error.what());
    }
    if (!opt->svg.empty()) {
      const std::string svg = explain_svg(scene, e);
      if (opt->svg == "-") {
        std::fwrite(svg.data(), 1, svg.size(), stdout);
        return 0;
      }
      std::ofstream out(opt->svg, std::ios::binary);
      out << svg;
      if (!out) {
        std::fprintf(stderr, "raycast explain: cannot write %s\n", opt->svg.c_str());
        return 1;
      }
      return 0;
    }
    const std::string text = opt->json ? explain_json(scene, e) : explain_text(scene, e);
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
  };
}

}  // namespace raycast::cli
