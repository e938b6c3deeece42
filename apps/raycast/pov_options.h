#pragma once
// The options of commands that read POV-Ray scenes (docs/pov-import.md): --library-path,
// --strict, --declare NAME=VALUE and the interpreter's bounds. They fill default_pov_options(),
// which every scene load of the process uses.
#include <CLI/CLI.hpp>

namespace raycast::cli {

void add_pov_options(CLI::App* cmd);

}  // namespace raycast::cli
