#pragma once
// Scenes written in POV-Ray's language (docs/pov-import.md): interpreted by pov/ and built here
// into the engine's objects, materials, lights and camera through the same constructors the
// YAML loader uses, with every error at its position in the POV-Ray files.
#include <string>
#include <vector>

#include "pov/options.h"
#include "scene/scene.h"

namespace raycast {

/// Loads a .pov scene; its warnings (what raycast does not render yet) go to `warnings` when
/// given, else to standard error. Throws SceneError.
Scene load_pov_scene_file(const std::string& path, int frame = -1, const pov::Options& options = {},
                          std::vector<std::string>* warnings = nullptr);
Scene load_pov_scene_text(const std::string& text, const std::string& name, const std::string& dir,
                          int frame = -1, const pov::Options& options = {},
                          std::vector<std::string>* warnings = nullptr);

/// The YAML that `raycast convert` writes for a .pov file (the interpreted scene written in
/// raycast's format; docs/pov-import.md says what it cannot express).
std::string convert_pov_file(const std::string& path, const pov::Options& options = {});

/// True for a path ending in .pov or .ini (any case).
bool is_pov_path(const std::string& path);

/// The options a user can pass through the environment for every command that loads scenes
/// (RAYCAST_POV_STRICT=1): the CLI adds its own on top.
pov::Options& default_pov_options();

}  // namespace raycast
