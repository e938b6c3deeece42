#include "scene/shape_parsers.h"

namespace raycast {

const std::map<std::string, ShapeParser>& shape_parsers() {
  static const std::map<std::string, ShapeParser> table = {
      {"plane", parse_plane},
      {"sphere", parse_sphere},
      {"torus", parse_torus},
  };
  return table;
}

}  // namespace raycast
