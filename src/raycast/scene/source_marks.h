#pragma once
// Where the parts of a loaded scene were written in its file and what it named them, for
// checks and explanations made after loading (`raycast validate`, `raycast explain`).

#include <string>
#include <vector>

namespace raycast {

/// A 1-based line and column in the scene file; 0 means "no position" (built in code).
struct SourceMark {
  int line = 0, column = 0;
};

struct SourceMarks {
  SourceMark camera;                // the `camera` mapping
  std::vector<SourceMark> lights;   // by index in Scene::lights
  std::vector<SourceMark> entries;  // by top-level `objects` entry (Object::entry)
  // By entry, the name the scene gave it (YAML `name:`, POV-Ray's declared name); shorter than
  // entries when the last ones have none. entry_name() reads it.
  std::vector<std::string> entry_names;
  std::vector<std::string> files;  // data files read (meshes, textures, particles, grids, sidecars)

  /// The name of a top-level entry, "" when it has none.
  const std::string& entry_name(int entry) const {
    static const std::string none;
    return entry >= 0 && std::size_t(entry) < entry_names.size() ? entry_names[std::size_t(entry)]
                                                                 : none;
  }
};

}  // namespace raycast
