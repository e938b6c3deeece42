#pragma once
// Closest points on a triangle mesh: a BVH over the triangles (accel/bvh.h) walked nearest box
// first, pruned by the distance to each box (docs/library.md "Distances").
#include <cstdint>
#include <optional>

#include "accel/bvh.h"
#include "math/transform.h"
#include "mesh/mesh.h"

namespace raycast {

/// A mesh's triangles placed in world space (in double, through `xf` when given) with a BVH for
/// closest-point queries. Immutable after construction; queries are thread-safe.
class MeshDistance {
 public:
  MeshDistance(const Mesh& mesh, const std::optional<Transform>& xf);

  struct Result {
    Vec3 point;                    // the nearest surface point
    double distance2 = kInfinity;  // its squared distance
    std::int32_t prim = -1;        // the input triangle index (Mesh::source)
  };
  /// The nearest point of the mesh to p within sqrt(best.distance2) (pass a default Result for
  /// no bound); `best` is improved in place and returned true when it was.
  bool closest(const Vec3& p, Result& best) const;
  const Aabb& box() const { return box_; }
  bool empty() const { return tris_.empty(); }

 private:
  struct Tri {
    Vec3 a, b, c;
    std::int32_t prim;
  };
  std::vector<Tri> tris_;  // in BVH leaf order
  Bvh bvh_;
  Aabb box_;
};

/// The squared distance from p to the box (0 inside).
double distance2(const Aabb& box, const Vec3& p);

}  // namespace raycast
