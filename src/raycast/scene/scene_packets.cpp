#include "scene/scene_packets.h"

#include <bit>
#include <variant>

#include "math/isa.h"
#include "math/lane_array.h"
#include "mesh/mesh.h"
#include "mesh/mesh_packet16.h"

namespace raycast {

ScenePackets::ScenePackets(const Scene& scene) : scene_(scene), width_(packet_width(active_isa())) {
  // The scene's own walk (more bounded objects: ObjectSet orders them per ray, by float boxes or
  // its BVH, which the plan does not repeat).
  const ObjectSet& set = scene.object_set();
  if (!set.walks_double_boxes()) return;
  for (const std::uint32_t index : set.unbounded())
    steps_.push_back(Step{index, nullptr, false, {}});
  bool any_mesh = false;
  for (std::size_t k = 0; k < set.bounded().size(); ++k) {
    const std::uint32_t index = set.bounded()[k];
    const MeshShape* mesh = std::get_if<MeshShape>(&scene.objects[index].shape);
    any_mesh |= mesh != nullptr;
    steps_.push_back(Step{index, mesh, true, set.box(k)});
  }
  usable_ = any_mesh;  // nothing to gain without a mesh
  if (!usable_) steps_.clear();
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
