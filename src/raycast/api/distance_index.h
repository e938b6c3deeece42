#pragma once
// What the point queries of raycast::api::Scene need per object (docs/library.md "Distances"):
// its world box, whether it is a closed solid, and how to find its nearest surface point.
#include <memory>
#include <string>
#include <vector>

#include "mesh/closest_point.h"
#include "scene/scene.h"

namespace raycast::api {

class DistanceIndex {
 public:
  explicit DistanceIndex(const raycast::Scene& scene);

  struct Nearest {
    raycast::Vec3 point;
    double distance2 = raycast::kInfinity;
    int object = -1;  // index into Scene::objects
    std::int32_t prim = -1;
  };
  /// The nearest surface point over every object; throws NotImplementedError naming the shape
  /// of the first object without a distance.
  Nearest nearest(const raycast::Vec3& p) const;
  /// Whether p is inside or on a closed solid (exact span parity, objects/object.h contains).
  /// `distance2`, when known, is p's squared distance to the nearest surface: points farther
  /// than rounding from every surface skip the on-surface test.
  bool inside(const raycast::Vec3& p, double distance2 = 0) const;
  /// The largest coordinate magnitude of the closed solids' boxes (inf when one is unbounded).
  double magnitude() const { return magnitude_; }
  /// Empty when every object has a distance, else the error message for the first one without.
  const std::string& unsupported() const { return unsupported_; }

 private:
  struct Entry {
    const raycast::Object* object;
    raycast::Aabb box;
    bool closed;
    std::unique_ptr<raycast::MeshDistance> mesh;  // meshes, placed in world space
  };
  bool on_surface(const Entry& e, const raycast::Vec3& p, double distance2) const;
  std::vector<Entry> entries_;
  std::string unsupported_;
  double magnitude_ = 0;
};

}  // namespace raycast::api
