#include "distributed/work_queue.h"

#include <mpi.h>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <exception>
#include <mutex>
#include <new>
#include <thread>
#include <utility>
#include <vector>

namespace raycast::cli::distributed {

namespace {

constexpr int kTagReport = 1;  // worker -> 0: what happened to its last item, and "next please"
constexpr int kTagOrder = 2;   // 0 -> worker: the next item, or kStop
constexpr std::int32_t kStop = -1;

enum Kind : std::int32_t { kReady = 0, kDone = 1, kFailed = 2 };

/// A report: kind, item, then the result or the error message.
std::vector<char> report(std::int32_t kind, std::int32_t item, const std::string& body) {
  std::vector<char> bytes(8 + body.size());
  std::memcpy(bytes.data(), &kind, 4);
  std::memcpy(bytes.data() + 4, &item, 4);
  std::memcpy(bytes.data() + 8, body.data(), body.size());
  return bytes;
}

/// Runs one item, turning an exception into its message.
bool attempt(const WorkQueue& queue, int item, std::string& out) {
  try {
    out = queue.work(item);
    return true;
  } catch (const std::bad_alloc&) {
    out = "out of memory";
  } catch (const std::exception& e) {
    out = e.what();
  }
  return false;
}

void worker(const WorkQueue& queue) {
  std::vector<char> message = report(kReady, kStop, "");
  for (;;) {
    std::int32_t item = kStop;
    MPI_Request requests[2];
    MPI_Irecv(&item, 1, MPI_INT32_T, 0, kTagOrder, MPI_COMM_WORLD, &requests[0]);
    MPI_Isend(message.data(), int(message.size()), MPI_CHAR, 0, kTagReport, MPI_COMM_WORLD,
              &requests[1]);
    wait_idle(requests[1]);
    wait_idle(requests[0]);
    if (item == kStop) return;
    std::string out;
    const bool ok = attempt(queue, item, out);
    message = report(ok ? kDone : kFailed, item, out);
  }
}

/// Rank 0's own share of the work: a thread that takes items from the same counter as the
/// other ranks and leaves its outcomes for the main thread, which alone calls MPI.
class LocalWorker {
 public:
  struct Outcome {
    int item;
    bool ok;
    std::string body;
  };

  LocalWorker(const WorkQueue& queue, std::atomic<int>& next, std::atomic<bool>& stop)
      : thread_([this, &queue, &next, &stop] {
          for (;;) {
            const int item = stop ? queue.count : next++;
            if (item >= queue.count) break;
            std::string out;
            const bool ok = attempt(queue, item, out);
            std::lock_guard lock(mutex_);
            outcomes_.push_back({item, ok, std::move(out)});
          }
          running_ = false;
        }) {}
  ~LocalWorker() { thread_.join(); }

  bool running() const { return running_; }
  std::vector<Outcome> take() {
    std::lock_guard lock(mutex_);
    return std::exchange(outcomes_, {});
  }

 private:
  std::mutex mutex_;
  std::vector<Outcome> outcomes_;
  std::atomic<bool> running_{true};
  std::thread thread_;  // last: starts once the members above exist
};

bool schedule(const MpiSession& session, const WorkQueue& queue) {
  std::atomic<int> next{0};
  std::atomic<bool> stop{false};
  bool all_ok = true;
  auto outcome = [&](int item, int rank, bool ok, const std::string& body) {
    if (ok) {
      queue.done(item, rank, body);
    } else {
      all_ok = false;
      if (!queue.failed(item, rank, body)) stop = true;
    }
  };
  int remote = session.size() - 1;  // ranks not yet told to stop
  LocalWorker local(queue, next, stop);
  std::vector<char> buffer;
  IdleBackoff backoff;
  try {
    for (;;) {
      bool idle = true;
      for (const auto& o : local.take()) {
        outcome(o.item, 0, o.ok, o.body);
        idle = false;
      }
      if (remote == 0 && !local.running()) {
        for (const auto& o : local.take()) outcome(o.item, 0, o.ok, o.body);
        break;
      }
      int flag = 0;
      MPI_Status status;
      if (remote > 0) MPI_Iprobe(MPI_ANY_SOURCE, kTagReport, MPI_COMM_WORLD, &flag, &status);
      if (flag) {
        idle = false;
        int bytes = 0;
        MPI_Get_count(&status, MPI_CHAR, &bytes);
        buffer.resize(std::size_t(bytes));
        MPI_Recv(buffer.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kTagReport, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        std::int32_t kind = kReady, item = kStop;
        std::memcpy(&kind, buffer.data(), 4);
        std::memcpy(&item, buffer.data() + 4, 4);
        if (kind != kReady)
          outcome(item, status.MPI_SOURCE, kind == kDone,
                  std::string(buffer.data() + 8, buffer.size() - 8));
        std::int32_t order = stop ? kStop : next++;
        if (order >= queue.count) order = kStop;
        if (order == kStop) --remote;
        MPI_Send(&order, 1, MPI_INT32_T, status.MPI_SOURCE, kTagOrder, MPI_COMM_WORLD);
      }
      // OpenMPI's blocking receive spins on the CPU; sleeping between probes leaves rank 0's core
      // to its render thread.
      if (idle)
        backoff.pause();
      else
        backoff.reset();
    }
  } catch (...) {
    stop = true;  // the local thread ends after its current item; the caller aborts the job
    throw;
  }
  return all_ok;
}

}  // namespace

bool run_work_queue(const MpiSession& session, const WorkQueue& queue) {
  int ok = 1;
  if (session.rank() == 0)
    ok = schedule(session, queue) ? 1 : 0;
  else
    worker(queue);
  MPI_Request request;
  MPI_Ibcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  wait_idle(request);  // the ranks done first do not spin while the others finish
  return ok == 1;
}

}  // namespace raycast::cli::distributed
