#include "render/shadow_bounds.h"

#include <algorithm>
#include <cmath>

namespace raycast {

namespace {

/// An upper bound on the operator norm of the transform's linear part A: the square root of
/// Gershgorin's bound on the largest eigenvalue of A^T A (1 for a rotation, up to rounding).
double norm_bound(const Transform& xf) {
  const auto& m = xf.matrix().m;
  double widest = 0;
  for (int i = 0; i < 3; ++i) {
    double row = 0;
    for (int j = 0; j < 3; ++j) {
      double g = 0;
      for (int k = 0; k < 3; ++k) g += m[k][i] * m[k][j];
      row += std::abs(g);
    }
    widest = std::max(widest, row);
  }
  return std::sqrt(widest) * (1 + 1e-12);
}

}  // namespace

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
    // The box's circumscribed ball, or a sphere's own (carried through the transform), whichever
    // is smaller.
    Vec3 centre = box.centre();
    double radius = 0.5 * length(box.extent());
    if (const auto* s = std::get_if<Sphere>(&o.shape)) {
      const Vec3 c = o.xf ? o.xf->point(s->center) : s->center;
      const double r = o.xf ? s->radius * norm_bound(*o.xf) : s->radius;
      if (r < radius) {
        centre = c;
        radius = r;
      }
    }
    // Widened for the rounding of the centre, the radius and the object's own tests (relative
    // 1e-9 of the ball's scale: orders of magnitude beyond them).
    const double scale = max_component(abs(centre)) + radius;
    radius = radius * (1 + 1e-9) + 1e-9 * scale;
    if (!(scale + radius <= kShadowBallLimit)) within = false;
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
