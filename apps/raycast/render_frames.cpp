#include "render_frames.h"

#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "distributed/distributed.h"
#include "distributed/launch.h"
#include "load/frame_pattern.h"
#include "load/loader.h"
#include "output_file.h"

namespace raycast::cli {

namespace {

bool parse_int(const std::string& s, int& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && !s.empty();
}

}  // namespace

RenderStats render_frame(const std::string& scene, const std::string& output, int frame,
                         const RenderOptions& options, std::string& written) {
  written = expand_frame_pattern(output, frame);
  const Scene s = load_scene_file(scene, frame);
  RenderStats stats;
  const Image image = render(s, options, &stats);
  save_image(image, written);
  return stats;
}

int render_frames(const std::string& scene, const std::string& output, const std::string& frames,
                  const RenderOptions& options) {
  const std::size_t dash = frames.find('-', 1);
  int first = 0, last = 0;
  const bool ok = dash == std::string::npos ? parse_int(frames, first) && (last = first, true)
                                            : parse_int(frames.substr(0, dash), first) &&
                                                  parse_int(frames.substr(dash + 1), last);
  if (!ok || first < 0 || last < first)
    return usage_error("--frames must be A-B with 0 <= A <= B (or one frame A), got '" + frames +
                       "'");
  if (scene.empty()) return usage_error("--frames needs a SCENE");
  if (last > first && !has_frame_pattern(output))
    return usage_error(
        "--frames renders several images: -o needs a {frame} pattern, e.g. "
        "out_{frame:04d}.png");
  std::string probe;
  try {
    probe = expand_frame_pattern(output, first);
  } catch (const std::invalid_argument& e) {
    return usage_error(std::string("-o: ") + e.what());
  }
  if (const std::string problem = output_problem(probe); !problem.empty()) {
    std::fprintf(stderr, "raycast render: %s\n", problem.c_str());
    return 1;  // an output that cannot be written (docs/cli.md)
  }
  if (distributed::active()) return distributed::render_frames(scene, output, first, last, options);
  const int count = last - first + 1;
  int failed = 0;
  RenderStats total;
  for (int f = first; f <= last; ++f) {
    std::string out;
    try {
      const RenderStats stats = render_frame(scene, output, f, options, out);
      total.rays += stats.rays;
      total.seconds += stats.seconds;
      total.width = stats.width;
      total.height = stats.height;
      total.spp = stats.spp;
      total.threads = stats.threads;
      std::fprintf(stderr, "raycast render: frame %d (%d/%d) -> %s: %s\n", f, f - first + 1, count,
                   out.c_str(), format_summary(stats).c_str());
    } catch (const std::exception& e) {  // SceneError, ImageError: this frame only
      ++failed;
      std::fprintf(stderr, "raycast render: frame %d (%d/%d) failed: %s\n", f, f - first + 1, count,
                   e.what());
    }
  }
  std::fprintf(stderr, "raycast render: %d of %d frames rendered%s: %s\n", count - failed, count,
               failed ? " (see the failures above)" : "", format_summary(total).c_str());
  return failed ? 2 : 0;
}

int usage_error(const std::string& message) {
  std::fprintf(stderr, "raycast render: %s\n", message.c_str());
  return 2;
}

}  // namespace raycast::cli
