#pragma once
// `raycast validate`: load a scene and check it without rendering (docs/cli.md).
#include <string>
#include <vector>

#include "scene/scene.h"

namespace raycast {

enum class Severity { kNote, kWarning, kError };

/// One thing found: where (line and column 0 when it has no position) and what.
struct Finding {
  Severity severity = Severity::kWarning;
  std::string file;
  int line = 0, column = 0;
  std::string message;
};

/// Loads the scene file and checks it. Never throws for bad input: a file that does not load is
/// one kError finding (the loader stops at the first error), else check_scene's findings.
std::vector<Finding> validate_scene_file(const std::string& path);

/// Checks a loaded scene for what loads but is likely a mistake: no lights, the camera inside a
/// solid, a light inside an opaque solid, degenerate triangles dropped from a mesh (warnings), and
/// unbounded shapes outside CSG, which every ray must test (notes).
std::vector<Finding> check_scene(const Scene& scene);

/// The warning for a whitted render of a scene without lights (it shows only ambient light and
/// the background), else "". Shared by `validate` and `render`.
std::string no_lights_warning(const Scene& scene, RenderMode mode);

/// "error", "warning" or "note".
const char* severity_name(Severity s);

}  // namespace raycast
