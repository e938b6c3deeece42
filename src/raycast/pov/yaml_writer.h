#pragma once
// A parsed POV-Ray scene written as raycast's scene format (docs/scene-format.md), with the
// position in the POV-Ray files that each line of YAML came from, so that the scene loader's
// errors can be reported where the user wrote the construct. The mapping of coordinates and
// materials is described in docs/pov-import.md.
#include <string>
#include <vector>

#include "pov/pov_scene.h"

namespace raycast::pov {

struct YamlScene {
  std::string text;
  std::vector<Pos> line_pos;  // by 0-based line of `text`
  bool mirrored = false;      // z was negated (the POV-Ray camera was left-handed)
};

/// Throws SceneError (at the construct) for what raycast's scene model cannot express.
YamlScene write_yaml(const PovScene& scene, const std::string& source_name);

}  // namespace raycast::pov
