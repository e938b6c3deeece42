#pragma once
// Scenes written in POV-Ray's language (docs/pov-import.md): converted to the scene format and
// loaded by the one scene loader, with its errors moved back to the POV-Ray file's positions.
#include <string>

#include "scene/scene.h"

namespace raycast {

Scene load_pov_scene_file(const std::string& path, int frame = -1);
Scene load_pov_scene_text(const std::string& text, const std::string& name, const std::string& dir,
                          int frame = -1);

/// The YAML that `raycast convert` writes for a .pov file; it loads to the same scene
/// (checked: a scene error in it is reported at the POV-Ray file's position).
std::string convert_pov_file(const std::string& path);

}  // namespace raycast
