// `raycast convert SCENE.pov [-o SCENE.yaml]`: a POV-Ray scene as raycast's scene format
// (docs/pov-import.md). The output is checked by loading it, so it loads wherever render would.
#include <cstdio>
#include <fstream>
#include <string>

#include "commands.h"
#include "io/scene_error.h"
#include "load/pov_loader.h"
#include "pov/import.h"

namespace raycast::cli {

Action add_convert_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "convert", "Convert a POV-Ray scene (.pov, a documented subset) to raycast's YAML format");
  auto scene = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>("-");
  cmd->add_option("SCENE", *scene, "POV-Ray scene file (.pov)")->required();
  cmd->add_option("-o,--output", *output, "YAML file to write (default -: standard output)");
  return [scene, output]() -> int {
    if (!pov::is_pov_path(*scene))
      throw SceneError(*scene, 0, 0,
                       "convert reads POV-Ray scenes: the file name must end in .pov");
    const std::string yaml = convert_pov_file(*scene);
    if (*output == "-") {
      std::fwrite(yaml.data(), 1, yaml.size(), stdout);
      return 0;
    }
    std::ofstream out(*output, std::ios::binary);
    out << yaml;
    out.close();
    if (!out) {
      std::fprintf(stderr, "raycast convert: cannot write %s\n", output->c_str());
      return 1;
    }
    return 0;
  };
}

}  // namespace raycast::cli
