#pragma once
// A progress bar for one stage of loading a large scene (reading a mesh file, checking its
// triangles, building its BVH), drawn on stderr only when stderr is a terminal, in the style of
// the render progress bar. Safe to advance from any number of threads.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>

namespace raycast {

class StageProgress {
 public:
  /// Stages with fewer than `min_total` units draw nothing (small scenes load silently).
  StageProgress(std::string what, std::uint64_t total, std::uint64_t min_total = 1u << 20)
      : what_(std::move(what)),
        total_(total),
        on_(total >= min_total && total > 0 && isatty(STDERR_FILENO)),
        start_(std::chrono::steady_clock::now()) {}
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;
  ~StageProgress() { finish(); }

  /// Whether the bar is drawn (callers may skip counting when it is not).
  bool on() const { return on_; }

  /// Adds `units` done.
  void advance(std::uint64_t units) {
    if (!on_) return;
    set(done_.fetch_add(units, std::memory_order_relaxed) + units);
  }

  /// Sets the units done so far.
  void set(std::uint64_t done) {
    if (!on_) return;
    const int percent = static_cast<int>(100 * std::min(done, total_) / total_);
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock || percent <= shown_) return;
    shown_ = percent;
    char bar[41];
    for (int i = 0; i < 40; ++i) bar[i] = i < percent * 40 / 100 ? '#' : '.';
    bar[40] = 0;
    std::fprintf(stderr, "\r%s [%s] %3d%%", what_.c_str(), bar, percent);
    std::fflush(stderr);
  }

  /// Ends the bar with the stage's wall time on its own line (once).
  void finish() {
    if (!on_ || finished_) return;
    finished_ = true;
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%s: %.2f s%50s\n", what_.c_str(), s, "");
    std::fflush(stderr);
  }

 private:
  std::string what_;
  std::uint64_t total_;
  bool on_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::atomic<std::uint64_t> done_{0};
  std::mutex mutex_;
  int shown_ = -1;
};

}  // namespace raycast
