#include "scene/shape_parsers.h"

namespace raycast {

const std::map<std::string, ShapeParser>& shape_parsers() {
  static const std::map<std::string, ShapeParser> table = {
      {"plane", parse_plane},
      {"sphere", parse_sphere},
      {"box", parse_box},
      {"triangle", parse_triangle},
      {"parallelogram", parse_parallelogram},
      {"disk", parse_disk},
      {"ellipsoid", parse_ellipsoid},
      {"quadric", parse_quadric},
      {"cylinder", parse_cylinder},
      {"cone", parse_cone},
      {"polygon", parse_polygon},
      {"slab", parse_slab},
      {"polyhedron", parse_polyhedron},
      {"torus", parse_torus},
      {"algebraic", parse_algebraic},
      {"implicit", parse_implicit},
      {"mesh", parse_mesh},
      {"revolution", parse_revolution},
      {"isosurface", parse_isosurface},
  };
  return table;
}

}  // namespace raycast
