#include "scene/object_set.h"

namespace raycast {

void ObjectSet::build(std::span<const Object> objects) {
  std::vector<Aabb> boxes;
  std::vector<Vec3> centres;
  bounded_.clear();
  unbounded_.clear();
  bounds_ = finite_bounds_ = Aabb{};
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Aabb b = raycast::bounds(objects[i]);
    bounds_.grow(b);
    if (b.is_empty()) continue;  // nothing to hit
    if (b.is_bounded()) {
      boxes.push_back(b);
      centres.push_back(b.centre());
      bounded_.push_back(static_cast<std::uint32_t>(i));
      finite_bounds_.grow(b);
    } else {
      unbounded_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  flat_ = bounded_.size() <= kFlatLimit;
  if (flat_) {
    boxes_ = std::move(boxes);
    bvh_ = Bvh{};
    return;
  }
  boxes_.clear();
  // One object per leaf: its own box is the last test before its shape's (a leaf of four tested
  // each object's shape on a hit of the leaf's box; docs/performance-render.md, round 5).
  BvhBuildConfig config;
  config.max_leaf_size = 1;
  bvh_ = build_bvh(boxes, centres, config);
}

bool ObjectSet::intersect(std::span<const Object> objects, const Ray& ray, LocalHit& hit,
                          std::int32_t& index) const {
  Ray r = ray;
  bool found = false;
  auto test = [&](std::uint32_t i, double& tmax) {
    r.tmax = tmax;
    LocalHit h;
    if (raycast::intersect(objects[i], r, h) && h.t <= tmax) {
      tmax = h.t;
      hit = h;
      index = static_cast<std::int32_t>(i);
      found = true;
    }
  };
  double tmax = ray.tmax;
  for (std::uint32_t i : unbounded_) test(i, tmax);
  if (flat_) {
    const Vec3 inv_d = reciprocal(ray.d);
    for (std::size_t k = 0; k < boxes_.size(); ++k) {
      double t_enter;
      if (intersect_slabs(boxes_[k], ray.o, inv_d, ray.tmin, tmax, t_enter))
        test(bounded_[k], tmax);
    }
    return found;
  }
  traverse_nearest(bvh_, ray.o, ray.d, ray.tmin, tmax,
                   [&](std::uint32_t prim, double& t) { test(bounded_[prim], t); });
  return found;
}

bool ObjectSet::occluded(std::span<const Object> objects, const Ray& ray) const {
  return any(ray, [&](std::uint32_t i) { return raycast::occluded(objects[i], ray); });
}

}  // namespace raycast
