#pragma once
// Triangle meshes: compact float storage, the per-mesh BVH, and the mesh as a shape of the
// scene (a light handle to the shared, immutable data).
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "accel/build_memory.h"
#include "geometry/shape.h"
#include "mesh/mesh_bvh.h"

namespace raycast {

/// A triangle mesh in object space. Positions are float, triangles are index triples; triangles
/// that are degenerate (zero area in float, or repeated indices) are dropped at construction and
/// counted. `source` maps each kept triangle to its index in the input (the `prim` users see).
/// Once built the mesh is immutable and may be queried from any number of threads.
struct Mesh {
  std::vector<Vec3f> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // kept triangles
  BuildVector<std::uint32_t> source;                    // kept triangle -> input triangle index
  std::vector<Vec3f> normals;  // unit vertex normals (smooth meshes), else empty
  std::size_t dropped = 0;     // degenerate input triangles dropped
  Aabb box;                    // bounds of the kept triangles (empty when none)
  MeshBvh bvh;
  double build_ms = 0;      // BVH build time
  double build_cpu_ms = 0;  // CPU time of the process (all threads) during the BVH build

  /// Whether every edge (by welded position) is shared by exactly two triangles. Found on first
  /// use (a sort of all edges, seconds for tens of millions of triangles), so that meshes never
  /// used as solids (CSG operands, span queries) never pay for it; thread-safe.
  bool closed() const;
  /// -1 for a closed mesh whose normals point inwards (negative volume), else 1; found with
  /// closed().
  double orientation() const;

  std::size_t triangle_count() const { return triangles.size(); }
  /// Bytes of the acceleration structure (nodes and precomputed leaf triangles).
  std::size_t bvh_bytes() const { return bvh.memory_bytes(); }
  /// Bytes of everything the mesh holds (storage and BVH).
  std::size_t memory_bytes() const;

 private:
  void find_closed() const;
  mutable std::once_flag closed_once_;
  mutable bool closed_ = false;
  mutable double orientation_ = 1;
};

/// Options of make_mesh.
struct MeshOptions {
  bool smooth = false;  // interpolate vertex normals: `normals` if given, else angle-weighted ones
  MeshBvhConfig bvh;
};

/// Builds a mesh from positions and triangles (input order kept for `prim`). Throws
/// std::invalid_argument when a position is not finite, an index is out of range, or `normals`
/// is non-empty and not one finite non-zero normal per position.
std::shared_ptr<const Mesh> make_mesh(std::vector<Vec3f> positions,
                                      std::vector<std::array<std::uint32_t, 3>> triangles,
                                      std::vector<Vec3f> normals = {},
                                      const MeshOptions& options = {});

/// Angle-weighted vertex normals (Thurmer and Wuthrich 1998), unit; a vertex of no triangle
/// gets (0, 0, 1).
std::vector<Vec3f> angle_weighted_normals(
    const std::vector<Vec3f>& positions,
    const std::vector<std::array<std::uint32_t, 3>>& triangles);

/// Whether every edge (by welded position) is shared by exactly two triangles.
bool is_closed_mesh(const std::vector<Vec3f>& positions,
                    const std::vector<std::array<std::uint32_t, 3>>& triangles);

/// The mesh as a shape: a handle to shared data. Rays arrive in double; the BVH and the
/// watertight triangle test run in float (the ray is converted once, its direction scaled by a
/// power of two); the nearest hit's t is then recomputed in double against the triangle's plane
/// and clamped to [tmin, tmax] (the float test decided the hit). LocalHit: t, prim = input
/// triangle index, part = kept triangle index, (a, b) = barycentrics (b1, b2).
/// Normals: geometric, unit, to the side from which the vertices run counter-clockwise.
/// Spans: a closed mesh gives solid intervals (entering where the normal faces the ray); an open
/// one gives each crossing as a zero-length span.
struct MeshShape {
  static constexpr const char* kName = "mesh";
  std::shared_ptr<const Mesh> mesh;
};

Aabb bounds(const MeshShape& s);
bool intersect(const MeshShape& s, const Ray& ray, LocalHit& hit);
bool occluded(const MeshShape& s, const Ray& ray);
/// The same two queries on the mesh itself (MeshShape's call these), for a caller that holds
/// the mesh: a scene of one untransformed mesh goes straight here (scene/scene.h).
bool intersect(const Mesh& m, const Ray& ray, LocalHit& hit);
bool occluded(const Mesh& m, const Ray& ray);
/// intersect() of up to eight rays (rays[l] for each bit l of mask; each is_valid) traced as one
/// packet: the same hits as one by one; returns the mask of the rays that hit.
int intersect8(const MeshShape& s, const Ray* rays, int mask, LocalHit* hits);
/// The packets' last step (intersect8, mesh_packet16.h's intersect16): for each lane l of
/// `found`, h[l]'s t refined in double as intersect() refines its one hit, and hits[l] written.
void write_packet_hits(const Mesh& m, const Ray* rays, int found, const MeshBvhHit* h,
                       const double* scale, LocalHit* hits);
void spans(const MeshShape& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const MeshShape& s, const Ray& ray, const LocalHit& hit);
bool contains(const MeshShape& s, const Vec3& p);
bool is_closed(const MeshShape& s);

/// The ray in the float form the mesh BVH takes, and the factor that turns its t back into units
/// of ray.d (t_ray = t_mesh * scale). [tmin, tmax] are rounded outwards.
MeshRay to_mesh_ray(const Ray& ray, double& scale);

/// The t of the line o + t d on the plane through v0, v1, v2, in double; t_float when the line
/// runs in the plane.
double refine_t(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& o, const Vec3& d,
                double t_float);

}  // namespace raycast
