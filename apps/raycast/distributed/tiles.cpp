// `mpirun -np N raycast render [SCENE] -o OUT`: one image cut into tiles handed out dynamically.
// Every rank loads the whole scene; a rank sends back only the pixels of the tiles it rendered
// (as float RGB, bit for bit) and rank 0, which gathers them, writes the files.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "distributed/bytes.h"
#include "distributed/distributed.h"
#include "distributed/mpi_session.h"
#include "distributed/work_queue.h"
#include "load/demo_scene.h"
#include "load/loader.h"
#include "render/texture.h"
#include "render_output.h"

namespace raycast::cli::distributed {

namespace {

/// Tiles of 64 pixels keep the messages few (a 1920x1080 image has 510) and still give each rank
/// many, so that dynamic hand-out evens out busy and empty parts of the image; smaller ones (down
/// to 16) when the image has fewer than 8 tiles per rank. The pixels do not depend on the size.
int tile_side(int width, int height, int ranks) {
  int side = 64;
  auto tiles = [&](int s) {
    return static_cast<long long>((width + s - 1) / s) * ((height + s - 1) / s);
  };
  while (side > 16 && tiles(side) < 8LL * ranks) side /= 2;
  return side;
}

const char* const kRenderCommand = "raycast render";

/// Loads the scene on this rank with its image textures decoded once (not once per tile).
Scene load(const std::string& path, const RenderOptions& options) {
  Scene scene = path.empty() ? load_demo_scene() : load_scene_file(path);
  const auto textures = load_textures(scene);
  for (std::size_t i = 0; i < textures.size(); ++i)
    if (textures[i]) scene.materials[i].image = textures[i];
  const long long pixels =
      static_cast<long long>(options.width > 0 ? options.width : scene.image.width) *
      (options.height > 0 ? options.height : scene.image.height);
  if (pixels > kMaxImagePixels)
    throw std::invalid_argument("the image must be at most " + std::to_string(kMaxImagePixels) +
                                " pixels, got " + std::to_string(pixels));
  return scene;
}

/// Renders one pass (the image or an AOV) over all ranks; the image on rank 0, empty elsewhere.
/// Returns false on every rank when a tile failed (rank 0 has named it).
bool render_pass(const MpiSession& session, const Scene& scene, RenderOptions options,
                 bool report_progress, Image& image, RenderStats& total,
                 std::vector<int>& tiles_per_rank) {
  const int width = options.width > 0 ? options.width : scene.image.width;
  const int height = options.height > 0 ? options.height : scene.image.height;
  const int side = tile_side(width, height, session.size());
  const int tiles_x = (width + side - 1) / side;
  const int tiles_y = (height + side - 1) / side;
  options.width = width;
  options.height = height;
  options.progress = false;  // rank 0 reports for the whole job
  auto rect = [&](int item) {
    const int tx = item % tiles_x, ty = item / tiles_x;
    return PixelRect{tx * side, ty * side, std::min(width, (tx + 1) * side),
                     std::min(height, (ty + 1) * side)};
  };
  if (session.rank() == 0) image = Image(width, height);
  const bool tty = isatty(STDERR_FILENO);
  int finished = 0, shown = 0;

  WorkQueue queue;
  queue.count = tiles_x * tiles_y;
  queue.work = [&](int item) {
    RenderOptions tile = options;
    tile.region = rect(item);
    RenderStats stats;
    const Image part = render(scene, tile, &stats);
    std::string bytes;
    put(bytes, stats);
    bytes.append(reinterpret_cast<const char*>(part.rgb.data()), part.rgb.size() * sizeof(float));
    return bytes;
  };
  queue.done = [&](int item, int rank, const std::string& result) {
    ByteReader in(result);
    const auto stats = in.get<RenderStats>();
    const PixelRect r = rect(item);
    const std::size_t row = std::size_t(r.x1 - r.x0) * 3;
    for (int y = r.y0; y < r.y1; ++y)
      std::memcpy(&image.rgb[(std::size_t(y) * width + r.x0) * 3], in.take(row * sizeof(float)),
                  row * sizeof(float));
    total.rays += stats.rays;
    total.samples += stats.samples;
    total.cpu_seconds += stats.cpu_seconds;
    total.spp = stats.spp;
    total.antialias = stats.antialias;
    total.threads = stats.threads;
    ++tiles_per_rank[std::size_t(rank)];
    // Progress of the whole job: a bar on a terminal, else a line every 10%.
    const int percent = 100 * ++finished / queue.count;
    if (!report_progress) return;
    if (tty) {
      std::fprintf(stderr, "\rrendering on %d ranks [%3d%%]", session.size(), percent);
      if (finished == queue.count) std::fprintf(stderr, "\r%40s\r", "");
    } else if (percent / 10 > shown) {
      shown = percent / 10;
      std::fprintf(stderr, "raycast render: %3d%% (%d of %d tiles)\n", percent, finished,
                   queue.count);
    }
    std::fflush(stderr);
  };
  queue.failed = [&](int item, int rank, const std::string& error) {
    const PixelRect r = rect(item);
    std::fprintf(stderr, "%s: rank %d: tile %d (pixels %d,%d to %d,%d) failed: %s\n",
                 kRenderCommand, rank, item, r.x0, r.y0, r.x1 - 1, r.y1 - 1, error.c_str());
    return false;  // the image cannot be completed: hand out no more tiles
  };
  total.width = width;
  total.height = height;
  return run_work_queue(session, queue);
}

}  // namespace

int render_image(const std::string& scene_path, const std::string& output,
                 const RenderOptions& options,
                 const std::vector<std::pair<std::string, RenderMode>>& aovs) {
  return run_distributed(kRenderCommand, [&](MpiSession& session) {
    std::optional<Scene> scene;
    std::string error;
    try {
      scene = load(scene_path, options);
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!session.agree(error, kRenderCommand)) return 2;

    const auto start = std::chrono::steady_clock::now();
    RenderStats total;
    std::vector<int> tiles_per_rank(std::size_t(session.size()), 0);
    const bool depth = render_mode(*scene, options) == RenderMode::kDepth;
    // The image, then each AOV; rank 0 writes each file as soon as it is complete.
    for (std::size_t pass = 0; pass <= aovs.size(); ++pass) {
      RenderOptions pass_options = options;
      if (pass > 0) pass_options.aov = aovs[pass - 1].second;
      Image image;
      if (!render_pass(session, *scene, pass_options, pass == 0, image, total, tiles_per_rank))
        return 2;
      std::string save_error;
      if (session.rank() == 0) {
        try {
          if (pass == 0)
            save_render(image, output, depth);
          else
            save_image(image, aov_path(output, aovs[pass - 1].first));
        } catch (const std::exception& e) {
          save_error = e.what();
        }
      }
      if (!session.agree(save_error, kRenderCommand)) return 2;
    }
    if (session.rank() == 0) {
      total.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::string shares;
      for (std::size_t r = 0; r < tiles_per_rank.size(); ++r)
        shares += (r ? " + " : "") + std::to_string(tiles_per_rank[r]);
      std::fprintf(stderr, "%s: %s -> %s: %s; %d ranks, tiles per rank %s\n", kRenderCommand,
                   scene_path.empty() ? "<demo>" : scene_path.c_str(), output.c_str(),
                   format_summary(total).c_str(), session.size(), shares.c_str());
    }
    return 0;
  });
}

}  // namespace raycast::cli::distributed
