#pragma once
// The POV-Ray import's entry point: a .pov file (and the local .inc files it includes) to
// raycast's scene format, as text for `raycast convert` and for the scene loader.
#include <string>

#include "pov/yaml_writer.h"

namespace raycast::pov {

struct Imported {
  YamlScene yaml;
  Sources sources;  // the files read: names[0] is the scene
};

/// Parses and converts; throws SceneError with the position in the POV-Ray file.
Imported import_pov_text(const std::string& text, const std::string& name, const std::string& dir);
Imported import_pov_file(const std::string& path);

/// True for a path ending in .pov (any case).
bool is_pov_path(const std::string& path);

}  // namespace raycast::pov
