#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "cast/cast.h"
#include "commands.h"
#include "distributed/distributed.h"
#include "distributed/launch.h"
#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast::cli {

Action add_cast_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("cast", "Answer ray queries on a scene: nearest hit, --any or --all");
  struct Options {
    std::string scene, rays, output;
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
  cmd->add_option("-o,--output", opt->output, "Answer file (default and -: standard output)");
  return [opt] {
    const bool rays_from_stdin = opt->rays.empty() || opt->rays == "-";
    if (opt->scene == "-" && rays_from_stdin) {
      std::fprintf(stderr,
                   "raycast cast: the scene and the rays cannot both come from standard input: "
                   "give --rays FILE\n");
      return 2;
    }
    CastOptions c;
    c.mode = opt->any ? CastMode::kAny : (opt->all ? CastMode::kAll : CastMode::kNearest);
    c.binary = opt->binary;
    if (distributed::active())  // under mpirun: a slice of the rays per rank (docs/distributed.md)
      return distributed::cast(opt->scene, opt->rays, opt->output, c);
    const bool to_stdout = opt->output.empty() || opt->output == "-";
    std::ofstream file;
    if (!to_stdout) {
      file.open(opt->output, std::ios::binary | std::ios::trunc);
      if (!file) {  // an output that cannot be written: exit 1 (docs/cli.md)
        std::fprintf(stderr, "raycast cast: %s: cannot open the output file\n",
                     opt->output.c_str());
        return 1;
      }
    }
    std::ostream& out = to_stdout ? std::cout : file;
    const Scene scene = load_scene_file(opt->scene);
    std::ios::sync_with_stdio(false);
    if (rays_from_stdin) {
      c.source = "<stdin>";
      run_cast(scene, std::cin, out, c);
    } else {
      std::ifstream in(opt->rays, std::ios::binary);
      if (!in) throw SceneError(opt->rays, 0, 0, "cannot open the ray file");
      c.source = opt->rays;
      run_cast(scene, in, out, c);
    }
    return out.good() ? 0 : 1;
  };
}

}  // namespace raycast::cli
