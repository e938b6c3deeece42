#include "load/pov_loader.h"

#include <filesystem>

#include "load/loader.h"
#include "pov/import.h"

namespace raycast {

namespace {

// The loader's positions are lines of the generated YAML: each maps to the POV-Ray construct
// it was written for.
SourceMark remap(const pov::Imported& im, const SourceMark& m) {
  if (m.line <= 0 || m.line > static_cast<int>(im.yaml.line_pos.size())) return {};
  const pov::Pos& p = im.yaml.line_pos[static_cast<std::size_t>(m.line - 1)];
  return p.file == 0 ? SourceMark{p.line, p.column} : SourceMark{};
}

Scene load_imported(const pov::Imported& im, const std::string& dir, int frame) {
  const std::string& name = im.sources.names.front();
  Scene scene;
  try {
    scene = load_scene_text(im.yaml.text, name, dir, frame);
  } catch (const SceneError& e) {
    const int line = e.line();
    if (line <= 0 || line > static_cast<int>(im.yaml.line_pos.size()))
      throw SceneError(name, 0, 0, e.message());
    const pov::Pos& p = im.yaml.line_pos[static_cast<std::size_t>(line - 1)];
    const std::string& file = im.sources.names[static_cast<std::size_t>(p.file)];
    throw SceneError(file, p.line, p.column, e.message() + " (after conversion from POV-Ray)");
  }
  scene.marks.camera = remap(im, scene.marks.camera);
  for (SourceMark& m : scene.marks.lights) m = remap(im, m);
  for (SourceMark& m : scene.marks.entries) m = remap(im, m);
  for (std::size_t i = 1; i < im.sources.paths.size(); ++i)
    scene.marks.files.push_back(im.sources.paths[i]);
  return scene;
}

}  // namespace

Scene load_pov_scene_file(const std::string& path, int frame) {
  const pov::Imported im = pov::import_pov_file(path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return load_imported(im, dir.empty() ? "." : dir, frame);
}

Scene load_pov_scene_text(const std::string& text, const std::string& name, const std::string& dir,
                          int frame) {
  return load_imported(pov::import_pov_text(text, name, dir), dir, frame);
}

std::string convert_pov_file(const std::string& path) {
  const pov::Imported im = pov::import_pov_file(path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  load_imported(im, dir.empty() ? "." : dir, -1);  // the same checks as `render`
  return im.yaml.text;
}

}  // namespace raycast
