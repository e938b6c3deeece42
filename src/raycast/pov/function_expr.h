#pragma once
// User functions (`function (a, b) { ... }`): a tree over their parameters (x, y, z by default),
// evaluated in expressions (F(1, 2, 3)) and written in raycast's formula syntax for
// isosurfaces (docs/shapes-algebraic.md "Formula text").
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raycast::pov {

struct FunctionValue;

struct FnNode {
  enum Kind { Number, Variable, Negate, Add, Subtract, Multiply, Divide, Power, Call, Param, User };
  Kind kind = Number;
  double number = 0;     // Number; Param: the parameter's index
  char variable = 'x';   // Variable (x, y or z of an isosurface's space)
  std::string function;  // Call: the built-in's name (sin, min, lt, select, ...)
  std::shared_ptr<const FunctionValue> callee;  // User
  std::vector<std::shared_ptr<const FnNode>> args;
};

/// A function value: its parameter names and body. `opaque` names what raycast reads but does
/// not evaluate yet (a pigment or pattern function, an `internal` function).
struct FunctionValue {
  std::vector<std::string> params;
  std::shared_ptr<const FnNode> body;
  std::string opaque;
};

/// The function's value at `args` (one per parameter). Unknown built-ins give NaN.
double evaluate(const FunctionValue& f, const std::vector<double>& args);

/// The formula text of `f` called with x, y, z for its first three parameters; with `mirror_z`
/// every z is written as (-z). Empty when the function uses what formulas cannot express.
std::string formula_text(const FunctionValue& f, bool mirror_z);
std::string formula_text(const FnNode& f, bool mirror_z);

}  // namespace raycast::pov
