#pragma once
// The inside of raycast::api::Scene (include/raycast/api/scene.h): the engine's scene plus what
// building in code needs. Only the api/ sources include this; it is the one place where the
// public types and the engine's meet (docs/library.md "The API boundary").
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "objects/prototype.h"
#include "raycast/api/scene.h"
#include "scene/scene.h"

namespace raycast::api {

class DistanceIndex;  // api/distance_index.h

struct Scene::Impl {
  raycast::Scene scene;  // the engine's scene; final after commit
  bool committed = false;

  // Building in code: objects by id; `hidden` marks those that became parts of a CSG object or
  // a prototype.
  std::vector<raycast::Object> objects;
  std::vector<char> hidden;
  std::vector<std::shared_ptr<const raycast::Prototype>> prototypes;

  // Distance queries build their per-object structures on first use.
  mutable std::once_flag distance_once;
  mutable std::shared_ptr<const DistanceIndex> distance;

  Impl();
  ~Impl();
  const DistanceIndex& distance_index() const;
};

/// The engine's ray for a public one.
inline raycast::Ray to_engine(const Ray& r) {
  return {{r.origin[0], r.origin[1], r.origin[2]},
          {r.direction[0], r.direction[1], r.direction[2]},
          r.tmin,
          r.tmax};
}

inline Vec3d to_public(const raycast::Vec3& v) { return {v.x, v.y, v.z}; }
inline raycast::Vec3 to_engine(const Vec3d& v) { return {v[0], v[1], v[2]}; }

/// The engine's transform for a public one; throws SceneError (file = `call`) when it is
/// singular, not finite or projective.
raycast::Transform to_engine(const Transform& t, const std::string& call);

/// Rethrows the engine's SceneError as the public one.
[[noreturn]] void rethrow_scene_error(const raycast::SceneError& e);

}  // namespace raycast::api
