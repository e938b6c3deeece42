#pragma once
// A set of objects with a BVH over the bounded ones (unbounded ones, planes and the like, are
// tried on every ray): the one implementation of the nearest / any / all walks over objects,
// used by the scene's top level and by instance prototypes.
#include <cstdint>
#include <span>
#include <vector>

#include "accel/bvh.h"
#include "accel/bvh_traverse.h"
#include "scene/object.h"

namespace raycast {

class ObjectSet {
 public:
  /// Indexes `objects` (kept by the caller: every query takes the same span again).
  void build(std::span<const Object> objects);

  /// The nearest hit with tmin <= t <= tmax: its record and the index of its object.
  bool intersect(std::span<const Object> objects, const Ray& ray, LocalHit& hit,
                 std::int32_t& index) const;
  /// Whether any object crosses the ray within [tmin, tmax].
  bool occluded(std::span<const Object> objects, const Ray& ray) const;
  /// visit(index) for every unbounded object, then for those whose boxes the BVH finds on the
  /// segment, in a fixed order for a given ray; stops when visit returns true (returned).
  template <class F>
  bool any(const Ray& ray, F&& visit) const {
    if (only_ >= 0) return may_hit_only(ray) && visit(static_cast<std::uint32_t>(only_));
    for (std::uint32_t index : unbounded_)
      if (visit(index)) return true;
    return traverse_any(bvh_, ray.o, ray.d, ray.tmin, ray.tmax,
                        [&](std::uint32_t prim) { return visit(bounded_[prim]); });
  }
  /// visit(index) for every object the segment may cross (unbounded ones first).
  template <class F>
  void all(const Ray& ray, F&& visit) const {
    if (only_ >= 0) {
      if (may_hit_only(ray)) visit(static_cast<std::uint32_t>(only_));
      return;
    }
    for (std::uint32_t index : unbounded_) visit(index);
    traverse_all(bvh_, ray.o, ray.d, ray.tmin, ray.tmax,
                 [&](std::uint32_t prim) { visit(bounded_[prim]); });
  }

  /// Bounds of every object, and of the bounded ones only.
  const Aabb& bounds() const { return bounds_; }
  const Aabb& finite_bounds() const { return finite_bounds_; }
  std::size_t memory_bytes() const {
    return bvh_.memory_bytes() +
           (bounded_.capacity() + unbounded_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  // The slab test of the only object's box (what the top-level BVH would do, without the walk):
  // rays that miss it skip the object's own ray set-up.
  bool may_hit_only(const Ray& ray) const {
    double t;
    return unbounded_.size() == 1 ||
           intersect_slabs(finite_bounds_, ray.o, reciprocal(ray.d), ray.tmin, ray.tmax, t);
  }

  Bvh bvh_;                               // over the bounded objects
  std::vector<std::uint32_t> bounded_;    // bvh prim -> object index
  std::vector<std::uint32_t> unbounded_;  // objects tested on every ray
  // The one object of a set of one (a scene of one mesh): queried directly, without the top-level
  // BVH, whose box test the object's own structure repeats anyway. -1 otherwise.
  std::int32_t only_ = -1;
  Aabb bounds_, finite_bounds_;
};

}  // namespace raycast
