#pragma once
// Optional parts of raycast that pull in large libraries (OpenVDB) are built as plugins, shared
// modules loaded the first time they are needed, so that every other command starts without
// loading and relocating those libraries (docs/architecture.md "Plugins").
#include <string>

namespace raycast {

/// The address of `symbol` in the plugin module `file` (a bare file name such as
/// "libraycast_openvdb.so"), loading the module on first use and keeping it loaded. Looks in
/// $RAYCAST_PLUGIN_DIR when it is set, else, in order: the directory of the running executable
/// and its ../<libdir>/raycast; the install directory; the build directory. Returns nullptr and
/// sets `why_not` (the directories tried and the loader's messages) when no module could be loaded
/// or the symbol is missing. Thread-safe.
void* plugin_symbol(const std::string& file, const char* symbol, std::string& why_not);

/// The interface table a plugin's entry point `entry` returns (a struct whose first member is
/// `int abi_version`), or nullptr with `why_not` set when the plugin cannot be loaded or is from
/// another build (its abi_version differs from `abi_version`).
template <class Plugin>
const Plugin* load_plugin(const std::string& file, const char* entry, int abi_version,
                          std::string& why_not) {
  void* address = plugin_symbol(file, entry, why_not);
  if (!address) return nullptr;
  const Plugin* plugin = reinterpret_cast<const Plugin* (*)()>(address)();
  if (!plugin || plugin->abi_version != abi_version) {
    why_not = "the plugin " + file + " is from another build of raycast";
    return nullptr;
  }
  return plugin;
}

}  // namespace raycast
