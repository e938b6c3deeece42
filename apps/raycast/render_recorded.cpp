#include "render_recorded.h"

#include <chrono>
#include <cstdio>
#include <sstream>

#include "output_file.h"
#include "render/contact_sheet.h"
#include "render/heatmap.h"
#include "render/ray_stats.h"
#include "render_output.h"

namespace raycast::cli {

namespace {

/// "out.png" + "cost.rays" -> "out.cost.rays.png".
std::string heatmap_path(const std::string& output, const std::string& name) {
  std::string pfm = aov_path(output, name);
  return pfm.substr(0, pfm.size() - 4) + ".png";
}

bool is_grey(RecordedOutput k) { return k >= RecordedOutput::kShadowed; }

}  // namespace

std::string take_recorded_outputs(const std::string& list,
                                  std::vector<std::pair<std::string, RecordedOutput>>& recorded) {
  std::string rest;
  std::stringstream names(list);
  for (std::string name; std::getline(names, name, ',');) {
    if (const auto k = recorded_output_named(name)) {
      recorded.emplace_back(name, *k);
      continue;
    }
    rest += (rest.empty() ? "" : ",") + name;
  }
  return rest;
}

std::string recording_problem(const RecordedRequest& request, bool others, bool sweep,
                              RenderMode integrator, bool to_stdout) {
  const bool records = request.stats || !request.outputs.empty();
  if (records && (others || sweep))
    return "--stats and the term and cost outputs render fixed samples one image at a time: "
           "not with --antialias, --frames, the depth, normal, id or albedo outputs or a "
           "--max-depth sweep";
  if (request.heatmap && request.outputs.empty())
    return "--heatmap draws the shadowed and cost outputs: add --aov cost.rays ...";
  if (records && integrator != RenderMode::kWhitted)
    return "--stats and the term and cost outputs record the whitted integrator";
  if ((records || sweep) && to_stdout)
    return "--stats, the term and cost outputs and a --max-depth sweep need a file, not -";
  return "";
}

int render_and_record(const Scene& scene, const RenderOptions& options, const std::string& output,
                      const RecordedRequest& request) {
  std::vector<RecordedOutput> kinds;
  for (const auto& [name, kind] : request.outputs) kinds.push_back(kind);
  RenderStats stats;
  const RecordedRender result = render_recorded(scene, options, kinds, &stats);
  const auto write_start = std::chrono::steady_clock::now();
  try {
    save_render(result.image, output, false);
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      const std::string& name = request.outputs[k].first;
      save_image(result.outputs[k], aov_path(output, name));
      if (!request.heatmap || !is_grey(kinds[k])) continue;
      const HeatmapScale scale = heatmap_scale(result.outputs[k]);
      save_image(make_heatmap(result.outputs[k], scale), heatmap_path(output, name));
      std::fprintf(stderr, "raycast render: %s heatmap %s: %s (blue) to %s (red)\n", name.c_str(),
                   heatmap_path(output, name).c_str(), scale_label(scale.lo).c_str(),
                   scale_label(scale.hi).c_str());
    }
  } catch (const ImageError& e) {
    std::fprintf(stderr, "raycast render: %s\n", e.what());
    return 1;
  }
  const double write_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
  if (request.stats) {
    const std::string report =
        format_stats(scene, stats, result.counts,
                     PhaseTimes{request.load_seconds, stats.seconds, write_seconds});
    std::fputs(report.c_str(), stderr);
  }
  std::fprintf(stderr, "raycast render: %s -> %s: %s\n", scene.source.c_str(), output.c_str(),
               format_summary(stats).c_str());
  return 0;
}

int render_depth_sweep(Scene& scene, const RenderOptions& options, const std::string& output,
                       int first, int last) {
  std::vector<Image> images;
  std::vector<std::string> captions;
  RenderOptions quiet = options;
  quiet.progress = false;
  for (int depth = first; depth <= last; ++depth) {
    scene.render.max_depth = depth;
    images.push_back(render(scene, quiet));
    captions.push_back("d=" + std::to_string(depth));
  }
  try {
    write_output_image(make_contact_sheet(images, captions), output);
  } catch (const ImageError& e) {
    std::fprintf(stderr, "raycast render: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "raycast render: %s -> %s: max_depth %d to %d, left to right\n",
               scene.source.c_str(), output.c_str(), first, last);
  return 0;
}

}  // namespace raycast::cli
