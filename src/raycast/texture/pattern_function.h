#pragma once
// The function of POV-Ray's `function` pattern (docs/textures.md "Patterns"): a scalar function of
// the pattern-space point, given by whoever reads the scene (a formula of the YAML form, a
// POV-Ray user function).
#include <memory>

#include "math/formula.h"
#include "math/vec3.h"

namespace raycast::texture {

class PatternFunction {
 public:
  virtual ~PatternFunction() = default;
  /// The function's value at p (the pattern's own space); NaN outside its domain.
  virtual double value(const Vec3& p) const = 0;
};

/// A compiled formula in x, y, z as a pattern function.
std::shared_ptr<const PatternFunction> formula_function(Formula formula);

/// The function pattern's raw value: POV-Ray keeps values up to 1 and wraps larger ones to
/// their fractional part (negative ones are wrapped by the ramp wave like any pattern's).
double function_pattern_value(const PatternFunction* f, const Vec3& p);

}  // namespace raycast::texture
