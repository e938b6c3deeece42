#include "serve/file_watcher.h"

#include <algorithm>
#include <system_error>

namespace raycast::serve {

FileWatcher::Stamp FileWatcher::stamp(const std::string& path) {
  std::error_code ec;
  Stamp s;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::is_regular_file(status)) return s;
  s.time = std::filesystem::last_write_time(path, ec);
  if (ec) return Stamp{};
  s.size = std::filesystem::file_size(path, ec);
  if (ec) return Stamp{};
  s.exists = true;
  return s;
}

void FileWatcher::watch(const std::vector<std::string>& paths) {
  std::vector<std::string> new_paths;
  std::vector<Stamp> new_stamps;
  for (const std::string& p : paths) {
    if (p.empty() || std::find(new_paths.begin(), new_paths.end(), p) != new_paths.end()) continue;
    new_paths.push_back(p);
    // A path watched already keeps its stamp: a change made while the scene was being reloaded
    // is still seen.
    const auto known = std::find(paths_.begin(), paths_.end(), p);
    new_stamps.push_back(known != paths_.end() ? stamps_[std::size_t(known - paths_.begin())]
                                               : stamp(p));
  }
  paths_ = std::move(new_paths);
  stamps_ = std::move(new_stamps);
}

bool FileWatcher::changed() {
  bool any = false;
  for (std::size_t i = 0; i < paths_.size(); ++i) {
    const Stamp now = stamp(paths_[i]);
    if (!(now == stamps_[i])) {
      stamps_[i] = now;
      any = true;
    }
  }
  return any;
}

}  // namespace raycast::serve
