#pragma once
// The CLI's subcommands: each registers its options on the app and runs when selected.
#include <CLI/CLI.hpp>

#include <functional>

namespace raycast::cli {

/// A subcommand's action, run after parsing; returns the exit code.
using Action = std::function<int()>;

Action add_cast_command(CLI::App& app);
Action add_info_command(CLI::App& app);
Action add_render_command(CLI::App& app);
Action add_bench_command(CLI::App& app);
Action add_validate_command(CLI::App& app);
Action add_convert_command(CLI::App& app);
Action add_explain_command(CLI::App& app);  // one pixel's ray tree (docs/explain.md)  // POV-Ray
                                            // scenes to YAML (docs/pov-import.md)
Action add_compare_command(CLI::App& app);  // image differences (docs/cli.md)
Action add_serve_command(CLI::App& app);    // built with cpp-httplib (RAYCAST_HAVE_SERVE)

}  // namespace raycast::cli
