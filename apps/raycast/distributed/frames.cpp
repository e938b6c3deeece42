// `mpirun -np N raycast render SCENE --frames A-B -o PATTERN`: frames handed out dynamically.
// Each rank loads its frame's scene (a frame's data files are read by the rank that renders it)
// and writes its image itself; rank 0 prints one line per frame and the job's summary.
#include <chrono>
#include <cstdio>
#include <string>

#include "distributed/bytes.h"
#include "distributed/distributed.h"
#include "distributed/mpi_session.h"
#include "distributed/work_queue.h"
#include "render_frames.h"

namespace raycast::cli::distributed {

int render_frames(const std::string& scene, const std::string& output, int first, int last,
                  const RenderOptions& options) {
  return run_distributed("raycast render", [&](MpiSession& session) {
    RenderOptions quiet = options;
    quiet.progress = false;  // rank 0 reports for the whole job
    const int count = last - first + 1;
    int finished = 0, failures = 0;
    RenderStats total;
    WorkQueue queue;
    queue.count = count;
    queue.work = [&](int item) {
      std::string written, bytes;
      const RenderStats stats = render_frame(scene, output, first + item, quiet, written);
      put(bytes, stats);
      put_string(bytes, written);
      return bytes;
    };
    queue.done = [&](int item, int rank, const std::string& result) {
      ByteReader in(result);
      const auto stats = in.get<RenderStats>();
      const std::string written = in.get_string();
      total.rays += stats.rays;
      total.cpu_seconds += stats.cpu_seconds;
      total.width = stats.width;
      total.height = stats.height;
      total.spp = stats.spp;
      total.threads = stats.threads;
      total.antialias = stats.antialias;
      total.samples += stats.samples;
      std::fprintf(stderr, "raycast render: frame %d (%d/%d, rank %d) -> %s: %s\n", first + item,
                   ++finished, count, rank, written.c_str(), format_summary(stats).c_str());
    };
    queue.failed = [&](int item, int rank, const std::string& error) {
      ++failures;
      std::fprintf(stderr, "raycast render: rank %d: frame %d (%d/%d) failed: %s\n", rank,
                   first + item, ++finished, count, error.c_str());
      return true;  // as without MPI, the other frames still render
    };
    const auto start = std::chrono::steady_clock::now();
    const bool ok = run_work_queue(session, queue);
    if (session.rank() == 0) {
      total.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "raycast render: %d of %d frames rendered on %d ranks%s: %s\n",
                   count - failures, count, session.size(),
                   failures ? " (see the failures above)" : "", format_summary(total).c_str());
    }
    return ok ? 0 : 2;
  });
}

}  // namespace raycast::cli::distributed
