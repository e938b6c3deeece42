#include "pov/import.h"

#include <algorithm>
#include <cctype>

#include "io/scene_file.h"
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
  const SceneFileText file = read_scene_file(path);
  return import_pov_text(file.text, path, file.dir);
}

bool is_pov_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".pov";
}

}  // namespace raycast::pov
