#include "texture/pattern_function.h"

#include <cmath>

namespace raycast::texture {

namespace {

class FormulaFunction final : public PatternFunction {
 public:
  explicit FormulaFunction(Formula f) : formula_(std::move(f)) {}
  double value(const Vec3& p) const override { return run(formula_, p.x, p.y, p.z); }

 private:
  Formula formula_;
};

}  // namespace

std::shared_ptr<const PatternFunction> formula_function(Formula formula) {
  return std::make_shared<FormulaFunction>(std::move(formula));
}

double function_pattern_value(const PatternFunction* f, const Vec3& p) {
  if (!f) return 0;
  const double v = f->value(p);
  return v > 1 ? std::fmod(v, 1.0) : v;
}

}  // namespace raycast::texture
