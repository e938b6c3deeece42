#pragma once
// The functions POV-Ray builds in and functions.inc names (`#declare f_sphere = function {
// internal(61) }`), defined by raycast from their documented parameters and the equations of the
// surfaces they are named after (docs/pov-import.md "functions.inc").
#include <memory>
#include <span>

#include "pov/function_expr.h"

namespace raycast::pov {

struct InternalFunctionInfo {
  int number;        // N of internal(N), as functions.inc declares it
  const char* name;  // functions.inc's name for it
  int extra;         // parameters after x, y, z
};

/// Every internal function raycast defines, by number.
std::span<const InternalFunctionInfo> internal_function_table();

/// The function value of internal(number): parameters x, y, z, P0, ...; null when raycast does
/// not define that number.
std::shared_ptr<const FunctionValue> internal_function(int number);

/// Musgrave's ridged multifractal (f_ridged_mf) at p: octaves of signed solid noise at
/// frequencies lacunarity^i, each ridge (offset - |noise|)^2 weighted by the one before times the
/// gain (clamped to [0, 1]) and by lacunarity^(-i H). `a` holds x, y, z, H, lacunarity, octaves,
/// offset, gain, generator.
double ridged_mf(const double a[9]);

/// The same as a function tree over the nodes x, y, z with the other parameters constant (the
/// octaves unrolled), for isosurface formulas.
std::shared_ptr<const FnNode> ridged_mf_tree(std::shared_ptr<const FnNode> x,
                                             std::shared_ptr<const FnNode> y,
                                             std::shared_ptr<const FnNode> z, const double a[9]);

}  // namespace raycast::pov
