#pragma once
// Convex polyhedra as intersections of half-spaces (possibly unbounded).
#include <array>
#include <vector>

#include "geometry/shape.h"

namespace raycast {

/// The solid n_i . p + d_i <= 0 for every plane i, stored with unit n_i (the given rows scaled
/// by 1 / |n_i|, which keeps the solid). Part i of a hit is plane i; its outward normal is n_i.
/// (u, v) are 0. Unbounded polyhedra are allowed (bounds are then infinite where needed).
struct Polyhedron {
  static constexpr const char* kName = "polyhedron";
  std::vector<std::array<double, 4>> planes;  // (nx, ny, nz, d), |n| = 1
  Aabb hull = Aabb::everything();
};

/// The most planes a polyhedron may have: validation enumerates the vertices and the receding
/// edge directions, O(n^3) at load time (35 ms for 100 planes).
inline constexpr std::size_t kMaxPolyhedronPlanes = 100;
/// Relative tolerance (to the planes' largest |d|, at least 1) of feasibility tests at load time.
inline constexpr double kPolyhedronTolerance = 1e-9;

/// A validated polyhedron: 1 to kMaxPolyhedronPlanes finite planes with non-zero normals whose
/// solid has an interior. Throws std::invalid_argument ("planes[i] ..." for one bad plane; "is
/// empty" when no point is strictly inside).
Polyhedron make_polyhedron(const std::vector<std::array<double, 4>>& planes);

Aabb bounds(const Polyhedron& p);
bool intersect(const Polyhedron& p, const Ray& ray, LocalHit& hit);
bool occluded(const Polyhedron& p, const Ray& ray);
void spans(const Polyhedron& p, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Polyhedron& p, const Ray& ray, const LocalHit& hit);
bool contains(const Polyhedron& p, const Vec3& q);
inline bool is_closed(const Polyhedron&) { return true; }

}  // namespace raycast
