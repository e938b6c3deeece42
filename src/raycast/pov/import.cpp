#include "pov/import.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pov/parser.h"

namespace raycast::pov {

Imported import_pov_text(const std::string& text, const std::string& name, const std::string& dir) {
  PovScene scene = parse_pov(text, name, dir);
  Imported out;
  out.yaml = write_yaml(scene, name);
  out.sources = std::move(scene.sources);
  return out;
}

Imported import_pov_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(path, 0, 0, "is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, 0, 0, "cannot open the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw SceneError(path, 0, 0, "cannot read the scene file");
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return import_pov_text(ss.str(), path, dir.empty() ? "." : dir);
}

bool is_pov_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".pov";
}

}  // namespace raycast::pov
