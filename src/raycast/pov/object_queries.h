#pragma once
// What a scene may ask about its own objects while it is read: POV-Ray's trace, inside,
// min_extent and max_extent. The interpreter only describes objects, so the answers come from
// whoever builds them (load/pov_loader.cpp); without one, the functions warn and answer 0.
#include <memory>
#include <optional>
#include <utility>

#include "math/vec3.h"

namespace raycast::pov {

struct Node;
struct PovScene;

class ObjectQueries {
 public:
  virtual ~ObjectQueries() = default;

  struct Trace {
    Vec3 point;
    Vec3 normal;  // the unit geometric normal, out of the solid (texture normals excluded)
  };
  /// The nearest point where the ray from `origin` along `direction` meets the object, in the
  /// scene's own coordinates; `scene` is the description read so far (for error positions).
  virtual std::optional<Trace> trace(const PovScene& scene,
                                     const std::shared_ptr<const Node>& object, const Vec3& origin,
                                     const Vec3& direction) = 0;
  /// Whether the point is inside the object (POV-Ray's `inside`).
  virtual bool inside(const PovScene& scene, const std::shared_ptr<const Node>& object,
                      const Vec3& point) = 0;
  /// The corners (min, max) of the object's bounding box; an unbounded side is +-2e10 as in
  /// POV-Ray, an empty object <0, 0, 0> for both.
  virtual std::pair<Vec3, Vec3> extent(const PovScene& scene,
                                       const std::shared_ptr<const Node>& object) = 0;
};

}  // namespace raycast::pov
