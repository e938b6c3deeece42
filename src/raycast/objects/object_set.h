#pragma once
// A set of objects with a BVH over the bounded ones (unbounded ones, planes and the like, are
// tried on every ray): the one implementation of the nearest / any / all walks over objects,
// used by the scene's top level and by instance prototypes. A set of few bounded objects is
// walked as a flat list of their boxes instead (faster on the scenes of
// bench/render_instructions.sh), without the tree's stack and node boxes: two double boxes per SIMD
// test (accel/box_pair.h, intersect_slabs's test), or for the larger flat sets four float boxes per
// test (accel/box4.h, conservative: the objects' own tests decide); a set of one bounded object
// tests its box alone. Shadow rays walk a flat set by a ball around each object instead
// (any_along).
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "accel/box4.h"
#include "accel/box_pair.h"
#include "accel/bvh.h"
#include "accel/bvh_traverse.h"
#include "objects/ball_list.h"
#include "objects/direction_lists.h"
#include "objects/object.h"

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

  /// any()'s walk for shadow rays (e: ray.d's unit direction; requires is_valid(ray)): the same
  /// objects in the same order, a flat set's bounded ones culled by their balls
  /// (objects/bounding_ball.h: often tighter than the boxes, and no per-ray set-up) instead of
  /// their boxes; for the one-mesh set the mesh first, then its box (shadow rays start on the mesh,
  /// inside its box: only the blocked ones pay the box).
  template <class F>
  bool any_along(const Ray& ray, const Vec3& e, F&& visit) const {
    if (sole_mesh_) return visit(bounded_[0]) && box_meets(0, ray, reciprocal(ray.d), ray.tmax);
    if (!balls_usable_ || !(length_squared(ray.o) <= kBallLimit * kBallLimit))
      return any(ray, visit);
    for (std::uint32_t index : unbounded_)
      if (visit(index)) return true;
    return each_ball_near(balls_.data(), balls_.data() + balls_.size(), ray.o, e, visit);
  }

  /// any_along for a segment that ends at `lists`' apex (ray.d = apex - ray.o exactly, as
  /// apex - o rounds; tmin 0, tmax 1; lists: one of light_lists()): the unbounded objects, then
  /// the entries of -d's cell (objects/direction_lists.h), in index order, those farther from the
  /// apex than |d| left out, each after any_along's ball test. Visits a subset of any_along's
  /// objects in its order, leaving out only objects the segment cannot cross; a segment longer
  /// than the lists' reach, or with |d|^2 outside may_meet's [1e-30, 1e30], takes any_along
  /// (with e = d / |d|, as the shadow rays' callers compute it).
  template <class F>
  bool any_along_to(const DirectionLists& lists, const Ray& ray, F&& visit) const {
    const double dd = length_squared(ray.d);
    if (!(dd <= lists.reach2() && dd >= 1e-30 && dd <= 1e30))
      return any_along(ray, ray.d * (1 / std::sqrt(dd)), visit);
    for (std::uint32_t index : unbounded_)
      if (visit(index)) return true;
    // The segment's points seen from the apex lie along -d (within the lists' margins). The
    // balls' test scaled by |d|^2 (as view_nearest's): no unit direction, whose square root and
    // division most segments, whose cells are empty or cut, would not use.
    for (const DirectionLists::Entry& entry : lists.cell(-ray.d))
      if (entry.near2 <= dd && entry.may_meet(ray.o, ray.d, dd) && visit(entry.index)) return true;
    return false;
  }

  /// Direction lists (objects/direction_lists.h) around `view` (the nearest-hit walk's, for rays
  /// that start there: a pinhole camera's position), for flat sets of at least kListsFrom
  /// bounded objects; none otherwise. Call after build.
  void set_view(std::span<const Object> objects, const Vec3& view);
  /// Direction lists in index order around each light position that `light_points` gives (the
  /// scene's point and spot lights; nullopt for lights whose shadow segments end nowhere, such
  /// as directional ones), for any_along_to's shadow segments that end there, under the same
  /// conditions as set_view. Call after build.
  void set_lights(std::span<const Object> objects,
                  std::span<const std::optional<Vec3>> light_points);

  /// Whether set_view built the lists.
  bool has_view_lists() const { return view_lists_.built(); }
  /// The lists around light_points[k] of set_lights, or nullptr when it has none.
  const DirectionLists* light_lists(std::size_t k) const {
    return k < light_lists_.size() && light_lists_[k].built() ? &light_lists_[k] : nullptr;
  }
  /// Whether set_lights built lists around any light.
  bool has_light_lists() const {
    for (const DirectionLists& lists : light_lists_)
      if (lists.built()) return true;
    return false;
  }
  /// Whether any_along culls by balls (a flat set, not the one-mesh set, coordinates in range).
  bool walks_balls() const { return balls_usable_; }
  /// Whether the nearest-hit walk tries the unbounded objects, then each bounded one after its
  /// box test, in index order (a flat set of fewer than kBoxPairsFrom bounded objects): the order
  /// camera-ray packets repeat (scene/scene_packets.h).
  bool walks_double_boxes() const { return flat_ && bounded_.size() < kBoxPairsFrom; }
  /// The objects tested on every ray, and the bounded ones with their boxes (box(k) is
  /// bounded()[k]'s; only where walks_double_boxes()).
  std::span<const std::uint32_t> unbounded() const { return unbounded_; }
  std::span<const std::uint32_t> bounded() const { return bounded_; }
  const Aabb& box(std::size_t k) const { return boxes_[k]; }
  /// The index of the set's one object when it is an untransformed mesh and every other object's
  /// box is empty (the queries' one-mesh path), else -1.
  std::int32_t sole_mesh() const {
    return sole_mesh_ ? static_cast<std::int32_t>(bounded_[0]) : -1;
  }
  /// Bounds of every object, and of the bounded ones only.
  const Aabb& bounds() const { return bounds_; }
  const Aabb& finite_bounds() const { return finite_bounds_; }
  std::size_t memory_bytes() const {
    return bvh_.memory_bytes() + pairs_.capacity() * sizeof(BoxPair) +
           groups_.capacity() * sizeof(Box4) + boxes_.capacity() * sizeof(Aabb) +
           balls_.capacity() * sizeof(BallPair) + view_lists_.memory_bytes() + light_lists_bytes() +
           (bounded_.capacity() + unbounded_.capacity()) * sizeof(std::uint32_t);
  }

  /// Sets of at most this many bounded objects are walked flat (no BVH); measured on the
  /// benchmark scenes (bench/render_instructions.sh).
  static constexpr std::size_t kFlatLimit = 16;
  /// Flat sets of at least this many bounded objects test their boxes two at a time
  /// (accel/box_pair.h) and visit the objects nearest entry first; fewer test each box in index
  /// order.
  static constexpr std::size_t kBoxPairsFrom = 4;
  /// Flat sets of at least this many test four float boxes at a time (accel/box4.h) instead: its
  /// per-ray set-up (rounding the ray and the slack, about 110 instructions more than the pairs')
  /// pays where it saves three pair tests or more (about 37 instructions each; on
  /// bench/render_instructions.sh's scenes the pairs save 2.5-2.8 % on textured (4) and glass (6),
  /// cost 0.7 % on csg (12)).
  static constexpr std::size_t kFloatBoxesFrom = 11;
  /// Flat sets of at least this many bounded objects get direction lists (set_view): on
  /// bench/render_instructions.sh's scenes the camera's save 6.7 % on csg (12 objects), 1.2 %
  /// on glass (6); with 4 (camera and light lists) textured -1.6 %, surfaces +2.9 % (its balls
  /// pass more camera rays than its boxes).
  static constexpr std::size_t kListsFrom = 5;
  /// Cells per cube-face side of the direction lists.
  static constexpr int kListSide = 64;

 private:
  std::size_t light_lists_bytes() const {
    std::size_t bytes = light_lists_.capacity() * sizeof(DirectionLists);
    for (const DirectionLists& lists : light_lists_) bytes += lists.memory_bytes();
    return bytes;
  }
  /// The balls set_view and set_lights build their lists of, and the reach of lists around
  /// `apex` (0 where no lists are made: not a flat set of kListsFrom objects or more, or out of
  /// range).
  std::vector<DirectionLists::Ball> list_balls(std::span<const Object> objects) const;
  double list_reach(const Vec3& apex) const;
  /// The nearest-hit walk of a ray from view_lists_'s apex: 1 hit, 0 none, -1 two bounded objects
  /// hit at the same t (the caller's walk decides: its order breaks the tie).
  int view_nearest(std::span<const Object> objects, const Ray& ray, LocalHit& hit,
                   std::int32_t& index) const;
  /// visit(index) for each bounded object whose box may meet the segment, in index order; stops
  /// when visit returns true (returned).
  template <class F>
  bool flat_any(const Ray& ray, F&& visit) const {
    if (bounded_.empty()) return false;
    const Vec3 inv_d = reciprocal(ray.d);
    if (bounded_.size() < kBoxPairsFrom) {
      for (std::size_t k = 0; k < boxes_.size(); ++k)
        if (box_meets(k, ray, inv_d, ray.tmax) && visit(bounded_[k])) return true;
      return false;
    }
    std::uint32_t candidates[kFlatLimit];
    const std::size_t n = bounded_.size() < kFloatBoxesFrom
                              ? paired_candidates(ray, inv_d, candidates)
                              : float_candidates(ray, inv_d, candidates);
    for (std::size_t j = 0; j < n; ++j)
      if (visit(candidates[j])) return true;
    return false;
  }
  /// The objects whose boxes meet the ray's segment, in index order (out of line: the callers'
  /// visitors inline the walk around it); returns their count.
  std::size_t paired_candidates(const Ray& ray, const Vec3& inv_d, std::uint32_t* out) const;
  /// The same from the float boxes (kFloatBoxesFrom objects or more): those that may meet it.
  std::size_t float_candidates(const Ray& ray, const Vec3& inv_d, std::uint32_t* out) const;
  /// build's float groups of `boxes` (groups_, last_lanes_, scale_).
  void build_float_groups(const std::vector<Aabb>& boxes);
  /// Whether boxes_[k] meets the ray's segment [tmin, tmax].
  bool box_meets(std::size_t k, const Ray& ray, const Vec3& inv_d, double tmax) const {
    double t_enter;
    return intersect_slabs(boxes_[k], ray.o, inv_d, ray.tmin, tmax, t_enter);
  }
  /// f(k, t_enter) for each k whose box meets the segment [tmin, tmax] of o + t d (inv_d =
  /// reciprocal(d)), in index order, t_enter its entry; stops when f returns true (returned).
  template <class F>
  bool each_paired_box(const Vec3& o, const Vec3& inv_d, double tmin, double tmax, F&& f) const {
    const BoxPair* pairs = pairs_.data() + ray_octant(inv_d) * pair_count_;
    for (std::size_t q = 0; q < pair_count_; ++q) {
      double t_enter[2];
      unsigned mask = box_pair_hits(pairs[q], o, inv_d, tmin, tmax, t_enter);
      for (; mask != 0; mask &= mask - 1) {
        const unsigned l = static_cast<unsigned>(std::countr_zero(mask));
        if (f(2 * q + l, t_enter[l])) return true;
      }
    }
    return false;
  }
  /// The float test's constants for the ray, its slab rows fixed to the octant copies' order
  /// (near planes in rows 0-2, far in 3-5): box4_hits then loads them at constant offsets, and
  /// the per-ray choice of rows by the signs of d is not made (the compiler drops it).
  Box4Ray float_ray(const Ray& ray, const Vec3& inv_d) const {
    Box4Ray r = make_box4_ray(ray, inv_d, scale_);
    for (std::uint32_t a = 0; a < 3; ++a) {
      r.near_row[a] = a;
      r.far_row[a] = 3 + a;
    }
    return r;
  }
  /// f(k, t_enter) for each k whose float box (groups_, the copies of inv_d's octant) may meet
  /// the segment [r.tmin, tmax_up], in index order, t_enter its entry; stops when f returns true
  /// (returned).
  template <class F>
  bool each_float_box(const Box4Ray& r, const Vec3& inv_d, float tmax_up, F&& f) const {
    const Box4* groups = groups_.data() + ray_octant(inv_d) * group_count_;
    for (std::size_t g = 0; g < group_count_; ++g) {
      alignas(16) float t_enter[4];
      unsigned mask = box4_hits(groups[g], r, tmax_up, t_enter);
      if (g + 1 == group_count_) mask &= last_lanes_;
      for (; mask != 0; mask &= mask - 1) {
        const int l = std::countr_zero(mask);
        if (f(4 * g + static_cast<std::size_t>(l), t_enter[l])) return true;
      }
    }
    return false;
  }

  bool flat_ = false;  // few bounded objects: boxes_ or groups_, no bvh_
  // The set is one untransformed mesh and nothing else (boxes_ holds its box): queries test the
  // box and go straight to the mesh, without the general walk's set-up.
  bool sole_mesh_ = false;
  // The set is one bounded object of any kind and nothing else (boxes_ holds its box): the same
  // short cut for both queries.
  bool sole_ = false;
  // sole_: whether its box is tested first; not for a CSG object whose leaves are all whole
  // spheres and boxes (their own intervals are as cheap as the box test).
  bool sole_box_ = true;
  // flat_, from kBoxPairsFrom: bounded_[2 q + l]'s box in lane l of pair q, stored once per ray
  // octant o (ray_octant) at pairs_[o * pair_count_ + q]; an odd count's last lane is empty.
  std::vector<BoxPair> pairs_;
  std::size_t pair_count_ = 0;
  // flat_, from kFloatBoxesFrom instead: bounded_[4 g + l]'s box in lane l of group g, stored
  // once per ray octant o at groups_[o * group_count_ + g], its rows the near planes then the far
  // ones for that octant (lo or hi by the sign).
  std::vector<Box4> groups_;
  std::size_t group_count_ = 0;
  unsigned last_lanes_ = 0;  // the lanes of the last group that hold a box
  Box4Scale scale_{};        // from a bound on |coordinate| over groups_' planes
  std::vector<Aabb> boxes_;  // flat_, fewer than kBoxPairsFrom: bounded_[k]'s box
  // flat_, not sole_mesh_: a ball around each bounded object with a non-empty one, in index order
  // (any_along), when every ball lies within kBallLimit (balls_usable_).
  std::vector<BallPair> balls_;
  bool balls_usable_ = false;
  // set_view's lists around the camera (nearest first), set_lights's around each light (index
  // order; not built for lights other than point and spot lights).
  DirectionLists view_lists_;
  std::vector<DirectionLists> light_lists_;
  Bvh bvh_;                               // over the bounded objects
  std::vector<std::uint32_t> bounded_;    // bvh prim -> object index
  std::vector<std::uint32_t> unbounded_;  // objects tested on every ray
  Aabb bounds_, finite_bounds_;
};

}  // namespace raycast
