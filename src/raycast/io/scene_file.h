#pragma once
// A scene file read whole (YAML, JSON or POV-Ray's language), with the errors every scene reader
// gives for a path that is a directory or cannot be read.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/scene_error.h"

namespace raycast {

struct SceneFileText {
  std::string text;
  std::string dir;  // the folder relative paths inside the scene resolve against ("." for none)
};

inline SceneFileText read_scene_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(path, 0, 0, "is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, 0, 0, "cannot open the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw SceneError(path, 0, 0, "cannot read the scene file");
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return {ss.str(), dir.empty() ? "." : dir};
}

}  // namespace raycast
