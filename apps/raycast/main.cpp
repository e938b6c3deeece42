// raycast: the command line (docs/cli.md). Thin: every piece of logic is in the library.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "commands.h"
#include "io/scene_error.h"
#include "load/did_you_mean.h"

namespace {

// What `raycast --version` prints: the version, the build type and the optional parts built in.
std::string version_text() {
  std::string text = "raycast " RAYCAST_VERSION " (" RAYCAST_BUILD_TYPE " build)\noptional parts:";
  const std::vector<std::pair<const char*, bool>> parts = {
#ifdef RAYCAST_HAVE_OPENEXR
      {"openexr", true},
#endif
#ifdef RAYCAST_HAVE_ASSIMP
      {"assimp", true},
#endif
#ifdef RAYCAST_HAVE_EMBREE
      {"embree-peer", true},
#endif
#ifdef RAYCAST_MPI
      {"mpi", true},
#endif
#ifdef RAYCAST_HAVE_SERVE
      {"serve", true},
#endif
  };
  for (const auto& [name, present] : parts)
    if (present) text += std::string(" ") + name;
  if (parts.empty()) text += " none";
  return text;
}

// The names the user could have meant by an unknown word: subcommands, or the flags of the
// subcommand being parsed.
std::vector<std::string> flag_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// CLI11 says "The following arguments were not expected: ..." or "A subcommand is required";
// name the first unknown word and the nearest valid one instead.
int report_unknown(CLI::App& app, const std::vector<std::string>& unknown) {
  const std::string& word = unknown.front();
  const CLI::App* scope = &app;
  for (const CLI::App* sub : app.get_subcommands())
    if (sub->parsed()) scope = sub;
  if (scope == &app && (word.empty() || word[0] != '-')) {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    std::fprintf(stderr, "raycast: unknown command '%s'%s; run 'raycast --help' for the commands\n",
                 word.c_str(), raycast::did_you_mean(word, commands).c_str());
    return 2;
  }
  const std::string command = scope == &app ? "raycast" : "raycast " + scope->get_name();
  if (word.empty() || word[0] != '-') {
    std::fprintf(stderr, "%s: unexpected argument '%s'; run '%s --help'\n", command.c_str(),
                 word.c_str(), command.c_str());
    return 2;
  }
  const std::string flag = word.substr(0, word.find('='));
  std::fprintf(stderr, "%s: unknown option '%s'%s; run '%s --help'\n", command.c_str(),
               flag.c_str(), raycast::did_you_mean(flag, flag_names(*scope)).c_str(),
               command.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raycast: a ray-casting engine and Whitted-style renderer"};
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);
  app.allow_extras();  // unknown words are reported below with a suggestion
  std::vector<std::pair<CLI::App*, raycast::cli::Action>> actions;
  for (auto add : {raycast::cli::add_render_command, raycast::cli::add_cast_command,
                   raycast::cli::add_info_command, raycast::cli::add_validate_command,
                   raycast::cli::add_bench_command, raycast::cli::add_convert_command,
                   raycast::cli::add_explain_command, raycast::cli::add_compare_command}) {
    auto action = add(app);
    actions.emplace_back(app.get_subcommands({}).back(), std::move(action));
  }
#ifdef RAYCAST_HAVE_SERVE
  actions.emplace_back(nullptr, raycast::cli::add_serve_command(app));
  actions.back().first = app.get_subcommands({}).back();
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::RequiredError& e) {
    // "A subcommand is required" for `raycast rendr`: the unknown word is the real mistake.
    if (!app.remaining().empty()) return report_unknown(app, app.remaining());
    app.exit(e);
    return 2;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad usage
  }
  std::vector<std::string> unknown = app.remaining();
  for (const CLI::App* sub : app.get_subcommands())
    for (const std::string& w : sub->remaining()) unknown.push_back(w);
  if (!unknown.empty()) return report_unknown(app, unknown);
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
