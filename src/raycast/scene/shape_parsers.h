#pragma once
// One parser per shape key of docs/scene-format.md's table; each reads its fields and validates
// them.
#include <map>
#include <string>

#include "scene/object.h"
#include "scene/yaml_reader.h"

namespace raycast {

/// Reads one shape from its mapping; throws SceneError at the offending field.
using ShapeParser = ShapeVariant (*)(Fields& fields);

/// Every shape key the loader knows, with its parser.
const std::map<std::string, ShapeParser>& shape_parsers();

ShapeVariant parse_plane(Fields& f);
ShapeVariant parse_sphere(Fields& f);
ShapeVariant parse_box(Fields& f);
ShapeVariant parse_triangle(Fields& f);
ShapeVariant parse_parallelogram(Fields& f);
ShapeVariant parse_disk(Fields& f);
ShapeVariant parse_ellipsoid(Fields& f);
ShapeVariant parse_quadric(Fields& f);
ShapeVariant parse_cylinder(Fields& f);
ShapeVariant parse_cone(Fields& f);
ShapeVariant parse_polygon(Fields& f);
ShapeVariant parse_slab(Fields& f);
ShapeVariant parse_polyhedron(Fields& f);
ShapeVariant parse_torus(Fields& f);
ShapeVariant parse_algebraic(Fields& f);
ShapeVariant parse_implicit(Fields& f);
ShapeVariant parse_mesh(Fields& f);
ShapeVariant parse_revolution(Fields& f);
ShapeVariant parse_isosurface(Fields& f);

}  // namespace raycast
