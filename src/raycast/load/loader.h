#pragma once
// Scene files (docs/scene-format.md): YAML, JSON accepted. Every mistake is a SceneError naming
// file:line:column and what was expected.
#include <string>

#include "scene/scene.h"

namespace raycast {

/// Loads and builds a scene from a file; relative paths inside resolve against its folder. The
/// path `-` reads standard input (named `<stdin>` in messages; relative paths from the current
/// folder).
/// `frame` (>= 0) is what `{frame}` patterns in data file paths expand to (docs/iso-surfaces.md).
Scene load_scene_file(const std::string& path, int frame = -1);
/// Loads and builds a scene from text; `name` is used in messages, `dir` for relative paths.
Scene load_scene_text(const std::string& text, const std::string& name = "<string>",
                      const std::string& dir = ".", int frame = -1);

/// The deepest nesting of objects (groups, CSG) and of YAML collections a scene may have.
inline constexpr int kMaxNesting = 256;

}  // namespace raycast
