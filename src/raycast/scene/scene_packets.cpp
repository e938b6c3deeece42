#include "scene/scene_packets.h"

#include <algorithm>
#include <bit>
#include <variant>

#include "math/isa.h"
#include "mesh/mesh.h"
#include "mesh/mesh_packet16.h"
#include "scene/lane_array.h"

namespace raycast {

ScenePackets::ScenePackets(const Scene& scene) : scene_(scene), width_(packet_width(active_isa())) {
  // Nothing to gain without a mesh (the scan below computes every object's bounds).
  if (std::none_of(scene.objects.begin(), scene.objects.end(),
                   [](const Object& o) { return std::holds_alternative<MeshShape>(o.shape); }))
    return;
  // ObjectSet::build's split: empty boxes never hit, unbounded objects on every ray, the bounded
  // ones behind their boxes.
  std::vector<Step> unbounded, bounded;
  bool any_mesh = false;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    Step step;
    step.object = static_cast<std::uint32_t>(i);
    step.box = bounds(o);
    if (step.box.is_empty()) continue;
    step.boxed = step.box.is_bounded();
    step.mesh = step.boxed ? std::get_if<MeshShape>(&o.shape) : nullptr;
    any_mesh |= step.mesh != nullptr;
    (step.boxed ? bounded : unbounded).push_back(step);
  }
  // More bounded objects: ObjectSet orders them per ray (float boxes by entry, or its BVH).
  if (!any_mesh || bounded.size() >= ObjectSet::kFloatBoxesFrom) return;
  steps_ = std::move(unbounded);
  steps_.insert(steps_.end(), bounded.begin(), bounded.end());
  usable_ = true;
}

int ScenePackets::intersect(const Ray* rays, int mask, SceneHit* hits) const {
  mask &= (1 << width_) - 1;
  // Each lane's ray with its tmax lowered to its nearest hit so far (ObjectSet's NearestTest),
  // and 1 / d for the box tests (ObjectSet's inv_d).
  LaneArray<Ray, 16> r;
  LaneArray<Vec3, 16> inv_d;
  int live = 0;  // Scene::intersect answers nothing for a ray that is not is_valid
  for (int m = mask; m != 0; m &= m - 1) {
    const int l = std::countr_zero(static_cast<unsigned>(m));
    r[l] = rays[l];
    if (is_valid(r[l])) live |= 1 << l;
    inv_d[l] = reciprocal(r[l].d);
  }
  int found = 0;
  auto take = [&](int l, const LocalHit& h, std::uint32_t object) {
    if (!(h.t <= r[l].tmax)) return;
    r[l].tmax = h.t;
    hits[l] = SceneHit{h, static_cast<std::int32_t>(object)};
    found |= 1 << l;
  };
  for (const Step& step : steps_) {
    const Object& object = scene_.objects[step.object];
    if (!step.mesh) {
      for (int m = live; m != 0; m &= m - 1) {
        const int l = std::countr_zero(static_cast<unsigned>(m));
        double t_enter;
        if (step.boxed &&
            !intersect_slabs(step.box, r[l].o, inv_d[l], r[l].tmin, r[l].tmax, t_enter))
          continue;
        LocalHit h;
        if (raycast::intersect(object, r[l], h)) take(l, h, step.object);
      }
      continue;
    }
    // The mesh's lanes that meet its box, in its own space (to_object_space, as intersect(Object)
    // does); a lane whose object-space ray is not is_valid (the packet's precondition) goes
    // alone.
    LaneArray<Ray, 16> local;
    LaneArray<LocalHit, 16> h;
    int packet = 0;
    for (int m = live; m != 0; m &= m - 1) {
      const int l = std::countr_zero(static_cast<unsigned>(m));
      double t_enter;
      if (!intersect_slabs(step.box, r[l].o, inv_d[l], r[l].tmin, r[l].tmax, t_enter)) continue;
      local[l] = to_object_space(object, r[l]);
      if (is_valid(local[l])) {
        packet |= 1 << l;
      } else {
        LocalHit single;
        if (raycast::intersect(object, r[l], single)) take(l, single, step.object);
      }
    }
    if (!packet) continue;
    const int hit = width_ > 8 ? intersect16(*step.mesh, local.data(), packet, h.data())
                               : intersect8(*step.mesh, local.data(), packet, h.data());
    for (int m = hit; m != 0; m &= m - 1) {
      const int l = std::countr_zero(static_cast<unsigned>(m));
      take(l, h[l], step.object);
    }
  }
  return found;
}

}  // namespace raycast
