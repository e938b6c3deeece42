#pragma once
// The loaded scene: objects, materials, lights, camera and settings, plus the top-level BVH.
// Build once, then query from any number of threads.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "objects/object.h"
#include "objects/object_set.h"
#include "scene/light.h"
#include "scene/material.h"
#include "scene/render_settings.h"
#include "scene/source_marks.h"

namespace raycast {

/// A hit on the scene: the object's index in Scene::objects and its local record.
struct SceneHit {
  LocalHit local;
  std::int32_t object = -1;
  bool valid() const { return object >= 0; }
};

/// One surface crossing along a ray, for `intersect_all`.
struct Crossing {
  double t;
  std::int32_t object;
  LocalHit local;
};

struct Scene {
  std::vector<Object> objects;
  std::vector<Material> materials;  // materials[0] is the default material
  std::vector<Light> lights;
  std::optional<CameraDesc> camera;  // absent: make_default_camera
  ImageSettings image;
  RenderSettings render;
  std::string source;  // file the scene came from ("<demo>" for the built-in one)
  int entries = 0;     // number of top-level `objects` entries
  SourceMarks marks;   // where the camera, lights and entries were written (loaded scenes)

  /// Builds the top-level BVH; call after the objects are final and before querying.
  /// direction_lists: also the lists around the camera and the point and spot lights
  /// (ObjectSet::set_view, set_lights; false only to compare against the walks without them).
  void build(bool direction_lists = true);
  double build_ms() const { return build_ms_; }
  std::size_t accel_bytes() const { return set_.memory_bytes(); }
  const Aabb& bounds() const { return set_.bounds(); }
  /// The bounds of the bounded objects only (used to frame a default camera).
  const Aabb& finite_bounds() const { return set_.finite_bounds(); }

  // The queries answer "nothing" (no hit, not occluded, no crossings) for a ray that is not
  // is_valid (geometry/ray.h): |o| or |d| out of range, NaN or empty [tmin, tmax].
  /// Nearest hit with ray.tmin <= t <= ray.tmax.
  bool intersect(const Ray& ray, SceneHit& hit) const;
  /// Whether any surface crosses the ray within [tmin, tmax].
  bool occluded(const Ray& ray) const;
  /// Every crossing of a final solid's (or open surface's) boundary within [tmin, tmax], sorted.
  void intersect_all(const Ray& ray, std::vector<Crossing>& out) const;
  /// Calls visit(index) (index into objects) for every object the ray's [tmin, tmax] segment may
  /// cross: every unbounded object, then those whose bounds the BVH finds on the segment, in a
  /// fixed order for a given ray. Stops as soon as visit returns true, and returns whether it did.
  /// Nothing is visited for a ray that is not is_valid.
  template <class F>
  bool any_object(const Ray& ray, F&& visit) const {
    return is_valid(ray) && set_.any(ray, visit);
  }
  /// any_object's walk for shadow rays, culled by a ball around each object when the scene is
  /// walked flat (ObjectSet::any_along; e: ray.d's unit direction). Requires is_valid(ray).
  template <class F>
  bool any_object_along(const Ray& ray, const Vec3& e, F&& visit) const {
    return set_.any_along(ray, e, visit);
  }
  /// The index of the scene's one untransformed mesh when every other object's box is empty
  /// (ObjectSet::sole_mesh), else -1.
  std::int32_t sole_mesh() const { return set_.sole_mesh(); }
  /// The walk over the objects (its order, for camera-ray packets: scene/scene_packets.h).
  const ObjectSet& object_set() const { return set_; }
  /// The full surface record of a hit found with this ray.
  SurfaceInfo surface(const Ray& ray, const SceneHit& hit,
                      SurfaceNeeds needs = SurfaceNeeds::kAll) const;
  const Material& material_of(const SceneHit& hit) const;

 private:
  ObjectSet set_;  // the objects' BVH and the walks over it
  double build_ms_ = 0;
  // The scene is one untransformed mesh and nothing else that can be hit: intersect and
  // occluded test its box and call the mesh directly, without the walk over objects. The same
  // answers as the general path (test).
  const Mesh* mesh_ = nullptr;  // owned by objects[mesh_object_]
  // occluded's kernel (MeshKernels::occluded_if_valid of the kernels in use), looked up at
  // build: the shadow ray's whole query, validity check included, in one call.
  bool (*mesh_occluded_)(const MeshBvh& bvh, const Ray& ray) = nullptr;
  std::int32_t mesh_object_ = -1;
  Aabb mesh_box_;
};

/// The camera to use: the scene's, or one with fov 40 looking along -z at the centre of the
/// scene's bounds from where its bounding sphere just fits (docs/rendering.md "Camera").
CameraDesc camera_or_default(const Scene& scene);

}  // namespace raycast
