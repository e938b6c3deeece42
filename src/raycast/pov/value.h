#pragma once
// The values of POV-Ray's language: floats, vectors of 2 to 5 components (colours are vectors
// marked as colours: rgb, filter, transmit), strings, arrays of 1 to 5 dimensions, and the
// things an identifier can name (objects, textures, pigments, finishes, interiors, cameras,
// lights, transforms, functions, splines, macros, and blocks raycast carries without building
// them yet: normals, media, colour maps ...).
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pov/pov_scene.h"

namespace raycast::pov {

/// v converted to the integer type T, saturating at T's range (NaN gives 0): a scene's number
/// where a plain conversion of a value out of range would be undefined behaviour.
template <class T>
T saturate(double v) {
  if (!(v == v)) return 0;
  if (v <= static_cast<double>(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
  if (v >= static_cast<double>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
  return static_cast<T>(v);
}

struct ArrayValue;
struct FunctionValue;
struct SplineValue;
struct MacroDef;

struct Value {
  enum Kind : unsigned char {
    Float,
    Vector,
    String,
    Array,
    Object,
    Texture,
    Pigment,
    Finish,
    Normal,
    Interior,
    Material,
    Camera,
    Light,
    Transform,
    Function,
    Spline,
    Macro,
    ColourMap,
    SkySphere,
    Fog,
    Opaque,  // a block raycast reads but does not build (normal, media, fog, ...): `text` names it
  };
  Kind kind = Float;
  bool colour = false;  // a Vector written as a colour (5 components: r g b filter transmit)
  int dims = 1;         // Float: 1; Vector: 2 to 5
  std::array<double, 5> v{};
  std::string text;  // String: the characters; Opaque: the block's keyword
  std::shared_ptr<ArrayValue> array;
  std::shared_ptr<const Node> object;           // Object (a light_source is an Object too)
  std::shared_ptr<const pov::Texture> texture;  // Texture, Material (with its interior)
  std::shared_ptr<const pov::Pigment> pigment;
  std::shared_ptr<const pov::Finish> finish;
  std::shared_ptr<const texture::Normal> normal;
  std::shared_ptr<const pov::Camera> camera;
  std::shared_ptr<const std::vector<XformOp>> transform;
  std::shared_ptr<const FunctionValue> function;
  std::shared_ptr<const SplineValue> spline;
  std::shared_ptr<const MacroDef> macro;
  std::shared_ptr<const std::vector<MapEntry>> colour_map;
  std::shared_ptr<const pov::SkySphere> sky_sphere;
  std::shared_ptr<const pov::Fog> fog;
  std::optional<pov::Interior> interior;  // Interior

  static Value number(double f) {
    Value r;
    r.v[0] = f;
    return r;
  }
  static Value vector(std::initializer_list<double> xs) {
    Value r;
    r.kind = Vector;
    r.dims = 0;
    for (double x : xs) r.v[static_cast<std::size_t>(r.dims++)] = x;
    return r;
  }
  static Value string(std::string s) {
    Value r;
    r.kind = String;
    r.text = std::move(s);
    return r;
  }
  bool is_numeric() const { return kind == Float || kind == Vector; }
};

/// The name of a value's kind in messages ("a float", "an object" ...).
const char* kind_name(const Value& v);

/// An array: its sizes per dimension and its elements in row-major order, each unset until
/// assigned.
struct ArrayValue {
  std::vector<int> sizes;
  std::vector<std::optional<Value>> elements;
};

/// A spline { } value: control points in order of their parameter.
struct SplineValue {
  enum Type { Linear, Quadratic, Cubic, Natural } type = Linear;
  std::vector<double> t;
  std::vector<std::array<double, 5>> p;
  int dims = 3;
};

/// A macro's definition: its parameters and where its body starts.
struct MacroDef {
  std::string name;
  std::vector<std::string> params;
  std::vector<bool> optional;
  int file = 0;                 // Sources index of the body
  std::size_t body_offset = 0;  // the cursor just after the parameter list
  int body_line = 1, body_column = 1;
};

}  // namespace raycast::pov
