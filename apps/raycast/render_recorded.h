#pragma once
// The parts of `raycast render` that take the image apart (docs/rendering.md "Term outputs",
// "Cost outputs", "Statistics", "Depth sweep"): renders with a recorder per sample, heatmaps,
// the statistics report and the --max-depth contact sheet.
#include <string>
#include <utility>
#include <vector>

#include "render/pixel_record.h"
#include "render/renderer.h"

namespace raycast::cli {

/// What a recorded render writes besides the image.
struct RecordedRequest {
  std::vector<std::pair<std::string, RecordedOutput>> outputs;  // OUT.<name>.pfm each
  bool heatmap = false;  // also OUT.<name>.png in false colour for the grey outputs
  bool stats = false;    // the statistics report on standard error
  double load_seconds = 0;
};

/// Renders through render_recorded, writes the image, the outputs and their heatmaps, prints
/// the heatmaps' scales and the report. Returns the exit code (1: a file cannot be written).
int render_and_record(const Scene& scene, const RenderOptions& options, const std::string& output,
                      const RecordedRequest& request);

/// Renders the scene at each max_depth in [first, last] and writes them side by side, captioned
/// `d=N`, to `output`. Returns the exit code.
int render_depth_sweep(Scene& scene, const RenderOptions& options, const std::string& output,
                       int first, int last);

/// Why the request cannot be rendered, or an empty string: `others` (adaptive antialiasing,
/// frames or the depth, normal, id and albedo outputs), a depth `sweep`, an `integrator` other
/// than whitted, or `to_stdout` conflict with recording; --heatmap needs an output to draw.
std::string recording_problem(const RecordedRequest& request, bool others, bool sweep,
                              RenderMode integrator, bool to_stdout);

/// Splits the `--aov` list into the names render_recorded makes (appended to `recorded`) and
/// the others (returned, comma-separated, for parse_aov_list).
std::string take_recorded_outputs(const std::string& list,
                                  std::vector<std::pair<std::string, RecordedOutput>>& recorded);

}  // namespace raycast::cli
