#pragma once
// Positions in POV-Ray scene files (the scene and the .inc files it includes) and the positioned
// error every mistake becomes.
#include <string>
#include <vector>

#include "io/scene_error.h"

namespace raycast::pov {

/// A 1-based line and column in one of the files read (an index into Sources::names).
struct Pos {
  int file = 0;
  int line = 0, column = 0;
};

/// The files read for one import, in the order they were opened (the scene first).
struct Sources {
  std::vector<std::string> names;  // as written in messages
  std::vector<std::string> paths;  // as opened (for `raycast serve` to watch)
};

[[noreturn]] inline void fail(const Sources& s, const Pos& p, const std::string& message) {
  const std::string& name = p.file >= 0 && p.file < static_cast<int>(s.names.size())
                                ? s.names[static_cast<std::size_t>(p.file)]
                                : std::string("<pov>");
  throw SceneError(name, p.line, p.column, message);
}

/// The message for anything outside the documented subset (docs/pov-import.md).
inline std::string unsupported(const std::string& construct) {
  return "'" + construct + "' is not supported by the POV-Ray import";
}

}  // namespace raycast::pov
