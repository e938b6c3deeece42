#pragma once
// Embree 3 as a peer for benchmarks and differential tests only; the engine never uses it.
// Everything here exists only when the build defines RAYCAST_HAVE_EMBREE.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "bench/bench.h"
#include "mesh/mesh.h"

namespace raycast {

/// One answer from the peer: t in units of the ray's d (as Embree saw it, in float), the geometry
/// (the index of the mesh in the list given to the peer) and the primitive (the mesh's input
/// triangle index), or geometry -1 on a miss.
struct PeerHit {
  double t = kInfinity;
  std::int32_t geometry = -1;
  std::int32_t prim = -1;
};

/// A mesh placed in the peer's scene (world-space positions, the mesh's kept triangles).
struct PeerMesh {
  std::shared_ptr<const Mesh> mesh;
  std::optional<Transform> xf;
};

class EmbreePeer {
 public:
  /// Builds an Embree scene (medium build quality, Embree's default) over the meshes, on `threads`
  /// threads (0: all). Throws std::runtime_error when Embree is missing or fails.
  EmbreePeer(const std::vector<PeerMesh>& meshes, int threads);
  ~EmbreePeer();
  EmbreePeer(const EmbreePeer&) = delete;
  EmbreePeer& operator=(const EmbreePeer&) = delete;

  double build_ms() const;
  double build_cpu_ms() const;  // CPU time of the process (all threads) during the build
  std::size_t bytes() const;    // memory Embree allocated for the scene (its BVH and triangle data)

  /// rtcIntersect1 / rtcOccluded1 over every ray, in parallel (tbb), writing one answer per ray.
  void intersect(std::span<const BenchRay> rays, std::span<PeerHit> out) const;
  void occluded(std::span<const BenchRay> rays, std::span<std::uint8_t> out) const;
  /// rtcIntersect8 over consecutive groups of eight rays (the last one masked), coherent flag set.
  void intersect8(std::span<const BenchRay> rays, std::span<PeerHit> out) const;
  /// The same with rtcIntersect16 over groups of sixteen.
  void intersect16(std::span<const BenchRay> rays, std::span<PeerHit> out) const;

  static bool available();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace raycast
