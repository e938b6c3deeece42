#pragma once
// Single triangles (open surfaces) with optional per-vertex shading normals, in double.
// Meshes of many triangles are a separate, compact type (mesh/).
#include "geometry/shape.h"

namespace raycast {

/// The triangle p0 p1 p2. Its geometric normal is normalize(cross(p1 - p0, p2 - p0)): it points to
/// the side from which the vertices run counter-clockwise. (u, v) = (b1, b2), the barycentric
/// weights of p1 and p2 (p = b0 p0 + b1 p1 + b2 p2, b0 = 1 - b1 - b2). With `has_normals`, the
/// shading normal interpolates the unit vertex normals n0 n1 n2 and is turned to the geometric
/// normal's side.
struct Triangle {
  static constexpr const char* kName = "triangle";
  Vec3 p0, p1{1, 0, 0}, p2{0, 1, 0};
  Vec3 n{0, 0, 1};  // unit geometric normal, set by make_triangle
  bool has_normals = false;
  Vec3 n0, n1, n2;
};

/// Below this sine of the angle between the edges p1 - p0 and p2 - p0 the triangle counts as
/// degenerate: its normal would be rounding noise (collinear points give sines near 1e-16).
inline constexpr double kDegenerateSine = 1e-12;

/// A validated triangle: finite vertices that are not collinear (see kDegenerateSine). Throws
/// std::invalid_argument otherwise.
Triangle make_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2);
/// The same with shading normals (each finite and non-zero; normalised here).
Triangle make_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& n0,
                       const Vec3& n1, const Vec3& n2);

Aabb bounds(const Triangle& tri);
bool intersect(const Triangle& tri, const Ray& ray, LocalHit& hit);
void spans(const Triangle& tri, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Triangle& tri, const Ray& ray, const LocalHit& hit);
inline bool contains(const Triangle&, const Vec3&) { return false; }
inline bool is_closed(const Triangle&) { return false; }

}  // namespace raycast
