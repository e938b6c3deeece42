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

}  // namespace raycast::pov
