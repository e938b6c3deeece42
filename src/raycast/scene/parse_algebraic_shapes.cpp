// Parsers for the higher-degree shapes: torus, algebraic, implicit, revolution.
#include <cmath>
#include <stdexcept>

#include "scene/shape_parsers.h"

namespace raycast {

ShapeVariant parse_torus(Fields& f) {
  const double R = f.positive("major_radius");
  const double r = f.positive("minor_radius");
  return make_torus(R, r);
}

}  // namespace raycast
