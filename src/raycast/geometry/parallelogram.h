#pragma once
// Parallelograms (open surfaces): origin + a u + b v with a, b in [0, 1].
#include "geometry/shape.h"

namespace raycast {

/// The parallelogram with corners origin, origin + u, origin + u + v, origin + v (in that
/// counter-clockwise order seen from the normal's side). Normal: normalize(cross(u, v)).
/// (u, v) at a hit are its coefficients a, b along the edges, both in [0, 1].
struct Parallelogram {
  static constexpr const char* kName = "parallelogram";
  Vec3 origin;
  Vec3 u{1, 0, 0}, v{0, 1, 0};
  Vec3 n{0, 0, 1};  // unit normal, set by make_parallelogram
};

/// A validated parallelogram: finite origin and edges, edges not parallel (the sine of their
/// angle above kDegenerateSine of triangle.h). Throws std::invalid_argument otherwise.
Parallelogram make_parallelogram(const Vec3& origin, const Vec3& u, const Vec3& v);

Aabb bounds(const Parallelogram& q);
bool intersect(const Parallelogram& q, const Ray& ray, LocalHit& hit);
void spans(const Parallelogram& q, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Parallelogram& q, const Ray& ray, const LocalHit& hit);
inline bool contains(const Parallelogram&, const Vec3&) { return false; }
inline bool is_closed(const Parallelogram&) { return false; }

}  // namespace raycast
