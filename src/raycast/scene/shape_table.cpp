#include "scene/shape_parsers.h"

namespace raycast {

const std::map<std::string, ShapeParser>& shape_parsers() {
  static const std::map<std::string, ShapeParser> table = {
      {"plane", parse_plane},
      {"sphere", parse_sphere},
      {"torus", parse_torus},
      {"algebraic", parse_algebraic},
      {"implicit", parse_implicit},
      {"revolution", parse_revolution},
  };
  return table;
}

}  // namespace raycast
