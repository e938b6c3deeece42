#include "render/shadow_bounds.h"

#include "scene/bounding_ball.h"

namespace raycast {

ShadowBounds make_shadow_bounds(const Scene& scene) {
  ShadowBounds out;
  bool within = true;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    const Aabb box = bounds(o);
    if (box.is_empty()) continue;  // ObjectSet skips it too
    const auto index = static_cast<std::uint32_t>(i);
    if (!box.is_bounded()) {
      out.unbounded.push_back(index);
      continue;
    }
    // The object's own ball (scene/bounding_ball.h: often far tighter than the box's), widened.
    const Ball ball = bounding_ball(o);
    if (ball.is_empty()) continue;  // an empty CSG intersection: no crossing to find
    const Vec3 centre = ball.centre;
    const double radius = ball.radius;
    if (!(max_component(abs(centre)) + radius <= kShadowBallLimit)) within = false;
    out.bounded.push_back(index);
    out.x.push_back(centre.x);
    out.y.push_back(centre.y);
    out.z.push_back(centre.z);
    out.radius2.push_back(radius * radius * (1 + 1e-12));
  }
  const std::size_t count = out.bounded.size();
  if (count % 2 != 0) {  // an empty ball: |v|^2 - k^2 >= 0 > -1
    out.bounded.push_back(0);
    out.x.push_back(0);
    out.y.push_back(0);
    out.z.push_back(0);
    out.radius2.push_back(-1);
  }
  out.usable = within && scene.sole_mesh() < 0 && count <= ObjectSet::kFlatLimit;
  return out;
}

}  // namespace raycast
