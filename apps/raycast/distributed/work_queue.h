#pragma once
// Dynamic scheduling of independent items (frames, tiles) over the ranks of a job: rank 0 hands
// out one item at a time to whichever rank asks, so a rank that finishes early takes the next
// one, and renders items itself on a second thread (docs/distributed.md, "Scheduling").
#include <functional>
#include <string>

#include "distributed/mpi_session.h"

namespace raycast::cli::distributed {

struct WorkQueue {
  int count = 0;  // items 0 .. count-1
  /// Every rank: does one item, returns the bytes rank 0 needs from it (pixels, statistics).
  /// An exception marks the item failed (its message goes to rank 0).
  std::function<std::string(int item)> work;
  /// Rank 0, main thread, in completion order: an item done by `rank`.
  std::function<void(int item, int rank, const std::string& result)> done;
  /// Rank 0, main thread: an item that failed on `rank`. Returns true to go on with the other
  /// items (frames), false to hand out no more (the tiles of one image).
  std::function<bool(int item, int rank, const std::string& error)> failed;
};

/// Collective: runs every item once on some rank. Returns true on every rank when every item
/// succeeded (the decision is rank 0's, broadcast).
bool run_work_queue(const MpiSession& session, const WorkQueue& queue);

}  // namespace raycast::cli::distributed
