// raycast: the command line (SPEC.md "Command line"). Thin: every piece of logic is in the library.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>
#include <vector>

#include "commands.h"
#include "scene/scene_error.h"

int main(int argc, char** argv) {
  CLI::App app{"raycast: a ray-casting engine and Whitted-style renderer"};
  app.require_subcommand(1);
  std::vector<std::pair<CLI::App*, raycast::cli::Action>> actions;
  for (auto add : {raycast::cli::add_cast_command, raycast::cli::add_info_command,
                   raycast::cli::add_bench_command}) {
    auto action = add(app);
    actions.emplace_back(app.get_subcommands({}).back(), std::move(action));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad usage
  }
  try {
    for (auto& [sub, action] : actions)
      if (sub->parsed()) return action();
  } catch (const raycast::SceneError& e) {
    std::fprintf(stderr, "raycast: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "raycast: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raycast: internal error: %s\n", e.what());
    return 1;
  }
  return 1;
}
