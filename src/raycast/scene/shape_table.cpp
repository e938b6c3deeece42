#include "scene/shape_parsers.h"

namespace raycast {

const std::map<std::string, ShapeParser>& shape_parsers() {
  static const std::map<std::string, ShapeParser> table = {
      {"plane", parse_plane},
      {"sphere", parse_sphere},
      {"mesh", parse_mesh},
  };
  return table;
}

}  // namespace raycast
