#pragma once
// Notices edits to the scene file and the data files it names by polling their modification times
// and sizes (simple and portable; no inotify). The owner calls changed() every ~100 ms.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raycast::serve {

class FileWatcher {
 public:
  /// Watches exactly these files from now on (duplicates are ignored); a missing file is watched
  /// too, so that its appearance counts as a change. Files watched already keep their last stamp.
  void watch(const std::vector<std::string>& paths);

  /// Whether any watched file changed (time, size, appeared or vanished) since the last call that
  /// returned true, or since watch().
  bool changed();

  const std::vector<std::string>& paths() const { return paths_; }

 private:
  struct Stamp {
    bool exists = false;
    std::filesystem::file_time_type time{};
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp(const std::string& path);

  std::vector<std::string> paths_;
  std::vector<Stamp> stamps_;
};

}  // namespace raycast::serve
