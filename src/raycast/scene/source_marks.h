#pragma once
// Where the parts of a loaded scene were written in its file, for checks made after loading
// (`raycast validate`).

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
  std::vector<std::string> files;  // data files read (meshes, textures, particles, grids, sidecars)
};

}  // namespace raycast
