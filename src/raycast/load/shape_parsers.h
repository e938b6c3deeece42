#pragma once
// One parser per shape key of docs/scene-format.md's table; each reads its fields and validates
// them.
#include <map>
#include <string>
#include <type_traits>

#include "load/yaml_reader.h"
#include "objects/object.h"

namespace raycast {

/// Reads one shape from its mapping; throws SceneError at the offending field.
using ShapeParser = ShapeVariant (*)(Fields& fields);

/// Every shape key the loader knows (each shape's `kName`), with its parser. Made from
/// ShapeVariant: a shape added to the variant without a `parse_shape` overload does not compile.
const std::map<std::string, ShapeParser>& shape_parsers();

// One parser per shape (parse_basic_shapes.cpp, parse_quadric_shapes.cpp,
// parse_algebraic_shapes.cpp, parse_mesh.cpp, parse_volume.cpp), chosen by the shape's type.
ShapeVariant parse_shape(std::type_identity<Plane>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Sphere>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Box>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Triangle>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Parallelogram>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Disk>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Ellipsoid>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Quadric>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Cylinder>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Cone>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Polygon>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Slab>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Polyhedron>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Torus>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Algebraic>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Implicit>, Fields& f);
ShapeVariant parse_shape(std::type_identity<MeshShape>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Revolution>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Isosurface>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Prism>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Text>, Fields& f);
ShapeVariant parse_shape(std::type_identity<Blob>, Fields& f);

}  // namespace raycast
