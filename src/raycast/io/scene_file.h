#pragma once
// A scene file read whole (YAML, JSON or POV-Ray's language), with the errors every scene reader
// gives for a path that is a directory or cannot be read.
#include <filesystem>
#include <fstream>
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
  // Read in large blocks into one string: a stringstream's copy costs as much as parsing a large
  // scene's text.
  std::string text;
  if (const auto size = std::filesystem::file_size(path, ec); !ec) text.reserve(size);
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0)
    text.append(block, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw SceneError(path, 0, 0, "cannot read the scene file");
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return {std::move(text), dir.empty() ? "." : dir};
}

}  // namespace raycast
