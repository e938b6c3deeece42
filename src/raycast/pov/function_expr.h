#pragma once
// The function of an isosurface (`function { ... }`) as a tree over x, y and z, written out in
// raycast's formula syntax (docs/shapes-algebraic.md "Formula text").
#include <memory>
#include <string>
#include <vector>

namespace raycast::pov {

struct FnNode {
  enum Kind { Number, Variable, Negate, Add, Subtract, Multiply, Divide, Power, Call };
  Kind kind = Number;
  double number = 0;
  char variable = 'x';
  std::string function;  // Call: raycast's name (sqrt exp log sin cos tan abs min max pow)
  std::vector<std::shared_ptr<const FnNode>> args;
};

/// The formula text; with `mirror_z` every z is written as (-z) (the scene is mirrored).
std::string formula_text(const FnNode& f, bool mirror_z);

}  // namespace raycast::pov
