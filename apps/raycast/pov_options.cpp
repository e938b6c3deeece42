#include "pov_options.h"

#include <string>
#include <vector>

#include "load/pov_loader.h"

namespace raycast::cli {

void add_pov_options(CLI::App* cmd) {
  pov::Options& o = default_pov_options();
  // CLI11 keeps a reference to the option's storage: it lives as long as the options do.
  static std::vector<std::string> declares;
  cmd->add_option("--library-path", o.library_paths,
                  "Folder searched for POV-Ray #include files (repeatable; after the scene's "
                  "folder, before povray.ini's Library_Path)")
      ->group("POV-Ray scenes")
      ->allow_extra_args(false);  // one folder per option: the SCENE may follow
  cmd->add_flag("--strict", o.strict,
                "POV-Ray scenes: what raycast does not render yet is an error, not a warning")
      ->group("POV-Ray scenes");
  cmd->add_option("-D,--declare", declares,
                  "POV-Ray scenes: NAME=VALUE declared before the scene is read (repeatable)")
      ->group("POV-Ray scenes")
      ->allow_extra_args(false)
      ->each([&o](const std::string& s) {
        const auto eq = s.find('=');
        if (eq == std::string::npos || eq == 0)
          throw CLI::ValidationError("--declare", "expected NAME=VALUE, got '" + s + "'");
        o.declares.emplace_back(s.substr(0, eq), s.substr(eq + 1));
      });
  cmd->add_option("--pov-max-iterations", o.limits.loop_iterations,
                  "POV-Ray scenes: #while/#for iterations allowed in all")
      ->group("POV-Ray scenes")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--pov-max-recursion", o.limits.macro_depth,
                  "POV-Ray scenes: macro calls allowed nested")
      ->group("POV-Ray scenes")
      ->check(CLI::Range(1, 100000));
}

}  // namespace raycast::cli
