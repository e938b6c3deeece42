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

}  // namespace raycast
