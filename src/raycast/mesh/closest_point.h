#pragma once
// Closest points on a triangle mesh: a 4-wide tree of oriented boxes over the triangles, walked
// nearest box first (best first) and pruned by the distance to each box (docs/library.md
// "Distances").
#include <cstdint>
#include <optional>
#include <vector>

#include "accel/bvh.h"
#include "math/transform.h"
#include "mesh/mesh.h"

namespace raycast {

/// A mesh's triangles placed in world space (in double, through `xf` when given) with a tree for
/// closest-point queries. Immutable after construction; queries are thread-safe.
///
/// Why oriented boxes: on a smooth surface the squared distance grows only quadratically away
/// from the nearest point, so every node whose bound falls short of the true distance by more
/// than that growth must be opened. An axis-aligned box of a tilted patch is as thick as it is
/// wide and falls short by about its size; a box aligned with the patch's mean normal is as thin
/// as the patch's curvature allows, which cuts the nodes opened per query by an order of
/// magnitude on curved meshes (python/bench_python.py).
class MeshDistance {
 public:
  MeshDistance(const Mesh& mesh, const std::optional<Transform>& xf);

  struct Result {
    Vec3 point;                    // the nearest surface point
    double distance2 = kInfinity;  // its squared distance
    std::int32_t prim = -1;        // the input triangle index (Mesh::source); least on ties
  };
  /// The nearest point of the mesh to p within sqrt(best.distance2) (pass a default Result for
  /// no bound); `best` is improved in place and returned true when it was.
  bool closest(const Vec3& p, Result& best) const;
  const Aabb& box() const { return box_; }
  bool empty() const { return tris_.empty(); }

  /// An oriented box per child: centre c, axes u, v (n x u rounded to float) and n, unit and
  /// orthogonal to float rounding, and half-extents h, such that every point of the child's
  /// triangles is c + s_u u + s_v v + s_n n with |s_k| <= h[k] for the exact reals stored (build
  /// slack covers the axes' rounding). 256 bytes, 64-aligned: four cache lines per node.
  struct alignas(64) Node {
    float c[3][4];
    float u[3][4], v[3][4], n[3][4];  // [component][lane]
    float h[3][4];                    // along u, v, n
    std::uint32_t ref[4];             // a node index, or the first triangle of a leaf
    std::uint32_t count[4];           // 0 for a node, the leaf's triangle count, kNone for no child
  };
  static constexpr std::uint32_t kNone = 0xffffffffu;

 private:
  // Which binary node's triangles a lane of a 4-wide node bounds.
  struct LaneSource {
    std::uint32_t node, lane, binary_node;
  };
  // Appends the 4-wide node made from binary node i and its subtree; returns its index.
  std::uint32_t collapse(const Bvh& bvh, std::uint32_t i, std::vector<LaneSource>& sources);
  // Each used lane's oriented box (in parallel), and a harmless box in the unused lanes.
  void fit_lane_boxes(const Bvh& bvh, const std::vector<LaneSource>& sources);

  struct Tri {
    Vec3 a, b, c;
    std::int32_t prim;
  };
  std::vector<Tri> tris_;  // in leaf order
  std::vector<Node> nodes_;
  std::uint32_t root_ref_ = 0, root_count_ = kNone;  // the root: nodes_[0], or a single leaf
  Aabb box_;
};

/// The squared distance from p to the box (0 inside).
double distance2(const Aabb& box, const Vec3& p);

}  // namespace raycast
