#pragma once
// Scene objects for the tests: a shape, optionally placed by a transform, with the default
// material (the fields a test does not set keep Object's defaults).
#include <optional>
#include <utility>

#include "objects/object.h"

namespace raycast::testing {

inline Object object_of(ShapeVariant shape, std::optional<Transform> xf = std::nullopt) {
  Object o;
  o.shape = std::move(shape);
  o.xf = std::move(xf);
  return o;
}

}  // namespace raycast::testing
