#pragma once
// Nearest hits of packets of up to sixteen rays (the renderer's camera rays), each lane's
// answer Scene::intersect's bit for bit, the scene's meshes traced by the packet kernels
// (mesh/packet_traverse.inl) and every other object lane by lane.
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace raycast {

class ScenePackets {
 public:
  /// The plan for `scene` (built; it must outlive the plan and not change). usable() only when
  /// the scene has a bounded mesh object and its nearest-hit walk is one the plan repeats step by
  /// step (ObjectSet::walks_double_boxes): the unbounded objects, then the bounded ones, each
  /// after its double box test, in the set's order, each tested with the ray's tmax lowered to the
  /// nearest hit so far.
  explicit ScenePackets(const Scene& scene);

  bool usable() const { return usable_; }
  /// The rays of one packet: 16 where the mesh kernels trace 16-ray packets (AVX-512), else 8.
  int width() const { return width_; }

  /// For each bit l of `mask` (l < width(); no other lane is read or written): whether
  /// `scene.intersect(rays[l], hit)` finds a hit (bit l of the mask returned), and that hit in
  /// hits[l] (left as it was for a lane that hits nothing). Only for a usable() plan.
  int intersect(const Ray* rays, int mask, SceneHit* hits) const;

 private:
  struct Step {
    std::uint32_t object = 0;         // index in scene.objects
    const MeshShape* mesh = nullptr;  // a bounded mesh: its lanes traced as one packet
    bool boxed = false;               // a bounded object: tested only where its box is met
    Aabb box;                         // bounds(object)
  };

  const Scene& scene_;
  std::vector<Step> steps_;  // in the order Scene::intersect tries the objects
  bool usable_ = false;
  int width_ = 8;
};

}  // namespace raycast
