#pragma once
// POV-Ray INI files (`raycast render scene.ini`): Input_File_Name, Width, Height, Antialias,
// Antialias_Threshold, Antialias_Depth, the clock keys, Declare=NAME=VALUE and Library_Path,
// and lines of `+W160 +H120 +A0.3 +KFI1 +KFF10 +KI0 +KF1 +Iscene.pov +Ldir` switches.
#include <string>

#include "pov/options.h"

namespace raycast::pov {

/// Reads `path` into `options` and returns the scene file it names (relative paths resolve
/// against the INI file's folder). Throws SceneError for an unreadable file or a bad value.
std::string read_ini_file(const std::string& path, Options& options);

/// Applies one `key=value` setting or `+X`/`-X` switch; false when the key is not one raycast
/// reads (POV-Ray's other settings are ignored).
bool apply_ini_setting(const std::string& setting, Options& options, std::string& scene);

}  // namespace raycast::pov
