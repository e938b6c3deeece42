#include "io/plugin_library.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <vector>

namespace raycast {
namespace {

// The directories a plugin is looked for in (io/plugin_library.h), without duplicates.
std::vector<std::string> plugin_dirs() {
  std::vector<std::string> dirs;
  const auto add = [&](const std::string& d) {
    if (d.empty()) return;
    for (const auto& seen : dirs)
      if (seen == d) return;
    dirs.push_back(d);
  };
  if (const char* env = std::getenv("RAYCAST_PLUGIN_DIR")) {  // the user's choice, alone
    add(env);
    return dirs;
  }
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    add(exe.parent_path().string());
    add((exe.parent_path().parent_path() / RAYCAST_PLUGIN_LIBDIR / "raycast").string());
  }
  add(RAYCAST_PLUGIN_INSTALL_DIR);
  add(RAYCAST_PLUGIN_BUILD_DIR);
  return dirs;
}

struct Loaded {
  void* handle = nullptr;
  std::string why_not;  // when handle is null
};

Loaded load(const std::string& file) {
  Loaded out;
  std::string tried;
  for (const std::string& dir : plugin_dirs()) {
    const std::string path = dir + "/" + file;
    if (::access(path.c_str(), F_OK) != 0) {
      tried += "\n  " + path + ": not there";
      continue;
    }
    // RTLD_LOCAL: the plugin's libraries stay out of the global symbol scope.
    if (void* h = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      out.handle = h;
      return out;
    }
    const char* err = ::dlerror();
    tried += "\n  " + path + ": " + (err ? err : "cannot be loaded");
  }
  out.why_not = "the plugin " + file +
                " could not be loaded (set RAYCAST_PLUGIN_DIR to its directory); tried:" + tried;
  return out;
}

}  // namespace

void* plugin_symbol(const std::string& file, const char* symbol, std::string& why_not) {
  static std::mutex mutex;
  static std::map<std::string, Loaded> loaded;  // never unloaded: code and data stay valid
  std::lock_guard<std::mutex> lock(mutex);
  auto it = loaded.find(file);
  if (it == loaded.end()) it = loaded.emplace(file, load(file)).first;
  if (!it->second.handle) {
    why_not = it->second.why_not;
    return nullptr;
  }
  ::dlerror();
  void* address = ::dlsym(it->second.handle, symbol);
  if (!address) why_not = "the plugin " + file + " has no entry point " + symbol;
  return address;
}

}  // namespace raycast
