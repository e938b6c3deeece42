#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "api/cast.h"
#include "commands.h"
#include "scene/loader.h"
#include "scene/scene_error.h"

namespace raycast::cli {

Action add_cast_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("cast", "Answer ray queries on a scene: nearest hit, --any or --all");
  struct Options {
    std::string scene, rays;
    bool any = false, all = false, binary = false;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("SCENE", opt->scene, "Scene file (YAML or JSON; - reads standard input)")
      ->required();
  cmd->add_option("--rays", opt->rays, "Ray file (default and -: standard input)");
  auto* any = cmd->add_flag("--any", opt->any, "Write 1 when something blocks the segment, else 0");
  auto* all = cmd->add_flag("--all", opt->all, "Write every surface crossing along the ray");
  any->excludes(all);
  cmd->add_flag("--binary", opt->binary, "Read 8 and write 11 little-endian float64 per ray");
  return [opt] {
    const bool rays_from_stdin = opt->rays.empty() || opt->rays == "-";
    if (opt->scene == "-" && rays_from_stdin) {
      std::fprintf(stderr,
                   "raycast cast: the scene and the rays cannot both come from standard input: "
                   "give --rays FILE\n");
      return 2;
    }
    const Scene scene = load_scene_file(opt->scene);
    CastOptions c;
    c.mode = opt->any ? CastMode::kAny : (opt->all ? CastMode::kAll : CastMode::kNearest);
    c.binary = opt->binary;
    std::ios::sync_with_stdio(false);
    if (rays_from_stdin) {
      c.source = "<stdin>";
      run_cast(scene, std::cin, std::cout, c);
    } else {
      std::ifstream in(opt->rays, std::ios::binary);
      if (!in) throw SceneError(opt->rays, 0, 0, "cannot open the ray file");
      c.source = opt->rays;
      run_cast(scene, in, std::cout, c);
    }
    return std::cout.good() ? 0 : 1;
  };
}

}  // namespace raycast::cli
