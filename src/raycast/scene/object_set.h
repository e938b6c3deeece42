#pragma once
// A set of objects with a BVH over the bounded ones (unbounded ones, planes and the like, are
// tried on every ray): the one implementation of the nearest / any / all walks over objects,
// used by the scene's top level and by instance prototypes. A set of few bounded objects is
// walked as a flat list of their boxes instead (docs/performance-render.md, round 4): the same
// objects are tested, without the tree's stack and node boxes.
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
    for (std::uint32_t index : unbounded_)
      if (visit(index)) return true;
    if (flat_) return flat_any(ray, visit);
    return traverse_any(bvh_, ray.o, ray.d, ray.tmin, ray.tmax,
                        [&](std::uint32_t prim) { return visit(bounded_[prim]); });
  }
  /// visit(index) for every object the segment may cross (unbounded ones first).
  template <class F>
  void all(const Ray& ray, F&& visit) const {
    for (std::uint32_t index : unbounded_) visit(index);
    if (flat_) {
      flat_any(ray, [&](std::uint32_t index) {
        visit(index);
        return false;
      });
      return;
    }
    traverse_all(bvh_, ray.o, ray.d, ray.tmin, ray.tmax,
                 [&](std::uint32_t prim) { visit(bounded_[prim]); });
  }

  /// Bounds of every object, and of the bounded ones only.
  const Aabb& bounds() const { return bounds_; }
  const Aabb& finite_bounds() const { return finite_bounds_; }
  std::size_t memory_bytes() const {
    return bvh_.memory_bytes() + boxes_.capacity() * sizeof(Aabb) +
           (bounded_.capacity() + unbounded_.capacity()) * sizeof(std::uint32_t);
  }

  /// Sets of at most this many bounded objects are walked flat (no BVH); measured on the
  /// benchmark scenes (docs/performance-render.md, round 4).
  static constexpr std::size_t kFlatLimit = 8;

 private:
  /// visit(index) for each bounded object whose box meets the segment, in index order; stops
  /// when visit returns true (returned).
  template <class F>
  bool flat_any(const Ray& ray, F&& visit) const {
    const Vec3 inv_d = reciprocal(ray.d);
    for (std::size_t k = 0; k < boxes_.size(); ++k) {
      double t_enter;
      if (intersect_slabs(boxes_[k], ray.o, inv_d, ray.tmin, ray.tmax, t_enter) &&
          visit(bounded_[k]))
        return true;
    }
    return false;
  }

  bool flat_ = false;                     // few bounded objects: boxes_ instead of bvh_
  std::vector<Aabb> boxes_;               // flat_: the box of bounded_[k]
  Bvh bvh_;                               // over the bounded objects
  std::vector<std::uint32_t> bounded_;    // bvh prim -> object index
  std::vector<std::uint32_t> unbounded_;  // objects tested on every ray
  Aabb bounds_, finite_bounds_;
};

}  // namespace raycast
