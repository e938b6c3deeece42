#pragma once
// User functions (`function (a, b) { ... }`): a tree over their parameters (x, y, z by default),
// evaluated in expressions (F(1, 2, 3)) and written in raycast's formula syntax for
// isosurfaces (docs/shapes-algebraic.md "Formula text").
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "texture/pattern_function.h"
#include "texture/pigment.h"

namespace raycast::pov {

struct FunctionValue;
struct SplineValue;

struct FnNode {
  enum Kind { Number, Variable, Negate, Add, Subtract, Multiply, Divide, Power, Call, Param, User };
  Kind kind = Number;
  double number = 0;     // Number; Param: the parameter's index; Call component: its index
  char variable = 'x';   // Variable (x, y or z of an isosurface's space)
  std::string function;  // Call: the built-in's name (sin, min, lt, select, ...)
  std::shared_ptr<const FunctionValue> callee;  // User
  std::vector<std::shared_ptr<const FnNode>> args;
};

/// A function value: its parameter names and body. `opaque` names what raycast reads but does
/// not evaluate yet (a transform or spline function, an `internal` function). A pigment function
/// (`function { pigment { ... } }`) has no body: its value at (x, y, z) is the pigment's colour
/// there, a pattern function's the pattern's value.
struct FunctionValue {
  std::vector<std::string> params;
  std::shared_ptr<const FnNode> body;
  std::string opaque;
  std::shared_ptr<const texture::Pigment> pigment;
  std::shared_ptr<const texture::Pattern> pattern;
  std::shared_ptr<const SplineValue> spline;  // `function { spline { ... } }`: the point at t = x
};

/// The spline's point at t: linear between points, or through them by Catmull-Rom segments with
/// end tangents from the end segments (the points sorted by t; outside them the end points); a
/// cubic_spline of 4 points or more runs from its second point to its last but one.
std::array<double, 5> spline_at(const SplineValue& s, double t);

/// The index a component name selects in a colour or vector function's value (x red r u: 0,
/// y green g v: 1, z blue b: 2, filter f t: 3, transmit: 4), kGrayComponent for gray / grey,
/// or -1.
inline constexpr int kGrayComponent = 5;
int component_index(const std::string& name);

/// A pigment, pattern or spline function's value at (x, y, z): rgb, filter, transmit (a
/// pattern's value in every place; a spline's point at t = x). False for other functions.
bool vector_value(const FunctionValue& f, double x, double y, double z, double out[5]);

/// The function's value at `args` (one per parameter). Unknown built-ins give NaN.
double evaluate(const FunctionValue& f, const std::vector<double>& args);

/// `f` as the function of a `function` pattern: called with the pattern-space point as x, y, z.
std::shared_ptr<const texture::PatternFunction> pattern_function(
    std::shared_ptr<const FunctionValue> f);

/// The formula text of `f` called with x, y, z for its first three parameters; with `mirror_z`
/// every z is written as (-z). Empty when the function uses what formulas cannot express.
std::string formula_text(const FunctionValue& f, bool mirror_z);
std::string formula_text(const FnNode& f, bool mirror_z);

}  // namespace raycast::pov
