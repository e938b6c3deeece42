#include "objects/object_set.h"

#include <algorithm>

#include "objects/bounding_ball.h"
#include "objects/csg_tree.h"

namespace raycast {

void ObjectSet::build(std::span<const Object> objects) {
  std::vector<Aabb> boxes;
  bounded_.clear();
  unbounded_.clear();
  pairs_.clear();
  pair_count_ = 0;
  groups_.clear();
  group_count_ = 0;
  bounds_ = finite_bounds_ = Aabb{};
  view_lists_ = DirectionLists{};
  light_lists_.clear();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Aabb b = raycast::bounds(objects[i]);
    bounds_.grow(b);
    if (b.is_empty()) continue;  // nothing to hit
    if (b.is_bounded()) {
      boxes.push_back(b);
      bounded_.push_back(static_cast<std::uint32_t>(i));
      finite_bounds_.grow(b);
    } else {
      unbounded_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  flat_ = bounded_.size() <= kFlatLimit;
  sole_ = flat_ && bounded_.size() == 1 && unbounded_.empty();
  sole_mesh_ = sole_ && !objects[bounded_[0]].xf &&
               std::holds_alternative<MeshShape>(objects[bounded_[0]].shape);
  sole_box_ = true;
  if (const auto* csg = sole_ ? std::get_if<CsgShape>(&objects[bounded_[0]].shape) : nullptr) {
    // A CSG object of whole spheres and boxes only: each leaf's own interval costs about what
    // the box test does, and an instance's prototype box has just passed in the instance's box
    // (the csg scene of bench/render_instructions.sh).
    sole_box_ = false;
    for (const CsgTree::LeafKind kind : csg->tree->leaf_kind)
      if (kind != CsgTree::LeafKind::kSphere && kind != CsgTree::LeafKind::kBox) sole_box_ = true;
  }
  // The shadow walk's balls (any_along): from each object's shape, widened; an empty one (an
  // empty CSG intersection) has no crossing to find.
  balls_.clear();
  balls_usable_ = flat_ && !sole_mesh_;
  std::size_t ball_count = 0;
  for (std::size_t k = 0; balls_usable_ && k < bounded_.size(); ++k) {
    const Ball ball = bounding_ball(objects[bounded_[k]]);
    if (ball.is_empty()) continue;
    if (!(max_component(abs(ball.centre)) + ball.radius <= kBallLimit)) balls_usable_ = false;
    add_ball(balls_, ball_count, bounded_[k], ball.centre, ball.radius);
  }
  if (!balls_usable_) balls_.clear();
  if (flat_) {
    bvh_ = Bvh{};
    if (boxes.size() < kBoxPairsFrom) {
      boxes_ = std::move(boxes);
      return;
    }
    boxes_.clear();
    if (boxes.size() >= kFloatBoxesFrom) {
      build_float_groups(boxes);
      return;
    }
    pair_count_ = (boxes.size() + 1) / 2;
    pairs_.resize(8 * pair_count_);
    for (unsigned octant = 0; octant < 8; ++octant)
      for (std::size_t k = 0; k < 2 * pair_count_; ++k)
        set_box_pair_lane(pairs_[octant * pair_count_ + k / 2], static_cast<int>(k % 2),
                          k < boxes.size() ? boxes[k] : Aabb{}, octant);
    return;
  }
  // One object per leaf: its own box is the last test before its shape's (a leaf of four tests
  // each object's shape on a hit of the leaf's box, and is slower on the scenes of
  // bench/render_instructions.sh).
  BvhBuildConfig config;
  config.max_leaf_size = 1;
  bvh_ = build_bvh(boxes, config);
}

std::vector<DirectionLists::Ball> ObjectSet::list_balls(std::span<const Object> objects) const {
  std::vector<DirectionLists::Ball> balls;
  for (std::uint32_t index : bounded_) {
    const Ball ball = bounding_ball(objects[index]);
    if (!ball.is_empty()) balls.push_back({index, ball.centre, ball.radius});
  }
  return balls;
}

double ObjectSet::list_reach(const Vec3& apex) const {
  if (!flat_ || sole_ || !balls_usable_ || bounded_.size() < kListsFrom) return 0;
  // The reach (the lists' unit of margins; shadow segments up to DirectionLists::kSegmentReach
  // times it are served): twice the farthest corner of the bounded objects' box.
  double far2 = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{corner & 1 ? finite_bounds_.hi.x : finite_bounds_.lo.x,
                 corner & 2 ? finite_bounds_.hi.y : finite_bounds_.lo.y,
                 corner & 4 ? finite_bounds_.hi.z : finite_bounds_.lo.z};
    far2 = std::max(far2, length_squared(p - apex));
  }
  const double reach = 2 * std::sqrt(far2);
  return max_component(abs(apex)) <= kBallLimit && reach > 0 && reach <= kBallLimit ? reach : 0;
}

void ObjectSet::set_view(std::span<const Object> objects, const Vec3& view) {
  view_lists_ = DirectionLists{};
  const double reach = list_reach(view);
  if (reach > 0)
    view_lists_.build(view, list_balls(objects), reach, kListSide,
                      DirectionLists::Order::kNearestFirst);
}

void ObjectSet::set_lights(std::span<const Object> objects,
                           std::span<const std::optional<Vec3>> light_points) {
  light_lists_.assign(light_points.size(), DirectionLists{});
  std::vector<DirectionLists::Ball> balls;
  for (std::size_t k = 0; k < light_points.size(); ++k) {
    if (!light_points[k]) continue;
    const double reach = list_reach(*light_points[k]);
    if (!(reach > 0)) continue;
    if (balls.empty()) balls = list_balls(objects);
    light_lists_[k].build(*light_points[k], balls, reach, kListSide, DirectionLists::Order::kIndex);
  }
}

void ObjectSet::build_float_groups(const std::vector<Aabb>& boxes) {
  group_count_ = (boxes.size() + 3) / 4;
  std::vector<Box4> plain(group_count_);
  for (std::size_t k = 0; k < group_count_ * 4; ++k) {
    Box4& g = plain[k / 4];
    const int lane = static_cast<int>(k % 4);
    if (k < boxes.size())
      set_box4_lane(g, lane, boxes[k]);
    else
      clear_box4_lane(g, lane);
  }
  const std::size_t last = boxes.size() % 4;
  last_lanes_ = last == 0 ? 0xFu : (1u << last) - 1;
  double magnitude[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a)
    for (const Box4& g : plain)
      for (int row : {a, 3 + a})
        for (float p : g.plane[row])
          if (std::isfinite(p)) magnitude[a] = std::max(magnitude[a], double(std::abs(p)));
  scale_ = make_box4_scale(magnitude);
  // One copy per octant, rows ordered as make_box4_ray would pick them for its signs.
  groups_.resize(8 * group_count_);
  for (std::size_t octant = 0; octant < 8; ++octant)
    for (std::size_t g = 0; g < group_count_; ++g) {
      Box4& copy = groups_[octant * group_count_ + g];
      for (int a = 0; a < 3; ++a) {
        const bool negative = (octant >> a) & 1;
        for (int l = 0; l < 4; ++l) {
          copy.plane[a][l] = plain[g].plane[negative ? 3 + a : a][l];
          copy.plane[3 + a][l] = plain[g].plane[negative ? a : 3 + a][l];
        }
      }
    }
}

namespace {

// Tests object i on [tmin, r.tmax], lowering r.tmax to a hit; returns whether it found one.
struct NearestTest {
  std::span<const Object> objects;
  Ray& r;
  LocalHit& hit;
  std::int32_t& index;
  bool found = false;
  bool operator()(std::uint32_t i) {
    LocalHit h;
    if (raycast::intersect(objects[i], r, h) && h.t <= r.tmax) return take(i, h);
    return false;
  }
  // operator() for an unbounded object: an untransformed plane (the floor of most scenes, met
  // by most rays) calls its shape's test directly, the call intersect(Object) makes for it
  // after its dispatch.
  bool unbounded(std::uint32_t i) {
    const Object& o = objects[i];
    const Plane* plane = o.xf ? nullptr : std::get_if<Plane>(&o.shape);
    if (!plane) return (*this)(i);
    LocalHit h;
    if (raycast::intersect(*plane, r, h) && h.t <= r.tmax) return take(i, h);
    return false;
  }
  // Takes object i's hit h (t within [tmin, r.tmax]) as the nearest so far.
  bool take(std::uint32_t i, const LocalHit& h) {
    r.tmax = h.t;
    hit = h;
    index = static_cast<std::int32_t>(i);
    found = true;
    return true;
  }
};

}  // namespace

// The BVH walk on its own frame (its stack is 2 KB) so that the flat path does not carry it.
[[gnu::noinline]] static void bvh_nearest(const Bvh& bvh, std::span<const std::uint32_t> bounded,
                                          NearestTest& test) {
  double tmax = test.r.tmax;
  traverse_nearest(bvh, test.r.o, test.r.d, test.r.tmin, tmax, [&](std::uint32_t prim, double& t) {
    test.r.tmax = t;
    test(bounded[prim]);
    t = test.r.tmax;
  });
}

bool ObjectSet::intersect(std::span<const Object> objects, const Ray& ray, LocalHit& hit,
                          std::int32_t& index) const {
  if (sole_) {
    // The object's box first: rays that miss it cost less here than in the object (a mesh, or
    // an instance's prototype of one object), and the walk below is not set up (unless the box
    // test is skipped: sole_box_).
    const Object& object = objects[bounded_[0]];
    if (sole_box_ && !box_meets(0, ray, reciprocal(ray.d), ray.tmax)) return false;
    if (sole_mesh_) {
      if (!raycast::intersect(object, ray, hit)) return false;
    } else {  // the hit taken on the walk's terms (t not beyond tmax)
      LocalHit h;
      if (!raycast::intersect(object, ray, h) || !(h.t <= ray.tmax)) return false;
      hit = h;
    }
    index = static_cast<std::int32_t>(bounded_[0]);
    return true;
  }
  if (view_lists_.built() && ray.o == view_lists_.apex() && ray.tmin >= 0 &&
      length_squared(ray.d) >= 1e-30 && length_squared(ray.d) <= 1e30) {
    const int found = view_nearest(objects, ray, hit, index);
    if (found >= 0) return found != 0;
  }
  Ray r = ray;
  NearestTest test{objects, r, hit, index};
  for (std::uint32_t i : unbounded_) test.unbounded(i);
  if (!flat_) {
    bvh_nearest(bvh_, bounded_, test);
    return test.found;
  }
  if (bounded_.empty()) return test.found;
  const Vec3 inv_d = reciprocal(ray.d);
  if (bounded_.size() < kBoxPairsFrom) {
    for (std::size_t k = 0; k < boxes_.size(); ++k)
      if (box_meets(k, ray, inv_d, r.tmax)) test(bounded_[k]);
    return test.found;
  }
  // The boxes that meet [tmin, tmax], then their objects nearest entry first (ties in index
  // order), each while its entry is not beyond the tmax lowered by the hits found so far.
  if (bounded_.size() >= kFloatBoxesFrom) {  // the same in float (a few more boxes pass)
    const Box4Ray br = float_ray(ray, inv_d);
    float tmax_up = float_up(r.tmax);
    struct Candidate {
      float t;
      std::uint32_t k;
    };
    Candidate c[kFlatLimit];
    std::size_t n = 0;
    each_float_box(br, inv_d, tmax_up, [&](std::size_t k, float t_enter) {
      std::size_t at = n++;
      for (; at > 0 && c[at - 1].t > t_enter; --at) c[at] = c[at - 1];
      c[at] = {t_enter, static_cast<std::uint32_t>(k)};
      return false;
    });
    for (std::size_t j = 0; j < n; ++j) {
      if (!box4_enters_before(c[j].t, tmax_up)) break;
      if (test(bounded_[c[j].k])) tmax_up = float_up(r.tmax);
    }
    return test.found;
  }
  struct Candidate {
    double t;
    std::uint32_t k;
  };
  Candidate c[kFlatLimit];
  std::size_t n = 0;
  each_paired_box(ray.o, inv_d, ray.tmin, r.tmax, [&](std::size_t k, double t_enter) {
    // Insertion by entry, after equal entries: the order is a function of the ray.
    std::size_t at = n++;
    for (; at > 0 && c[at - 1].t > t_enter; --at) c[at] = c[at - 1];
    c[at] = {t_enter, static_cast<std::uint32_t>(k)};
    return false;
  });
  for (std::size_t j = 0; j < n && c[j].t <= r.tmax; ++j) test(bounded_[c[j].k]);
  return test.found;
}

int ObjectSet::view_nearest(std::span<const Object> objects, const Ray& ray, LocalHit& hit,
                            std::int32_t& index) const {
  Ray r = ray;
  NearestTest test{objects, r, hit, index};
  for (std::uint32_t i : unbounded_) test.unbounded(i);
  // Entries nearest first: once an entry's lower bound of the distance (near2, squared) exceeds
  // tmax |d| (the current hit's distance), no later entry can give a hit at t <= tmax.
  const double dd = length_squared(ray.d);
  double reach2 = r.tmax * r.tmax * dd;
  bool bounded_hit = false;
  for (const DirectionLists::Entry& entry : view_lists_.cell(ray.d)) {
    if (entry.near2 > reach2) break;
    if (!entry.may_meet(ray.o, ray.d, dd)) continue;
    LocalHit h;
    if (raycast::intersect(objects[entry.index], r, h) && h.t <= r.tmax) {
      // A tie between two bounded objects: the box walk's order picks the one it reports.
      if (bounded_hit && h.t == r.tmax) return -1;
      bounded_hit = true;
      r.tmax = h.t;
      hit = h;
      index = static_cast<std::int32_t>(entry.index);
      test.found = true;
      reach2 = r.tmax * r.tmax * dd;
    }
  }
  return test.found ? 1 : 0;
}

std::size_t ObjectSet::float_candidates(const Ray& ray, const Vec3& inv_d,
                                        std::uint32_t* out) const {
  std::size_t n = 0;
  each_float_box(float_ray(ray, inv_d), inv_d, float_up(ray.tmax), [&](std::size_t k, float) {
    out[n++] = bounded_[k];
    return false;
  });
  return n;
}

std::size_t ObjectSet::paired_candidates(const Ray& ray, const Vec3& inv_d,
                                         std::uint32_t* out) const {
  std::size_t n = 0;
  each_paired_box(ray.o, inv_d, ray.tmin, ray.tmax, [&](std::size_t k, double) {
    out[n++] = bounded_[k];
    return false;
  });
  return n;
}

bool ObjectSet::occluded(std::span<const Object> objects, const Ray& ray) const {
  if (sole_)  // flat_any's walk of one box, without the visitor
    return (!sole_box_ || box_meets(0, ray, reciprocal(ray.d), ray.tmax)) &&
           raycast::occluded(objects[bounded_[0]], ray);
  return any(ray, [&](std::uint32_t i) { return raycast::occluded(objects[i], ray); });
}

}  // namespace raycast
