#pragma once
// Axis-aligned ellipsoids, solved as the unit sphere in coordinates scaled by the radii.
#include "geometry/shape.h"

namespace raycast {

/// The solid ((x-cx)/a)^2 + ((y-cy)/b)^2 + ((z-cz)/c)^2 <= 1 with radii (a, b, c). (u, v) are the
/// sphere's on the unit sphere: u = phi / 2 pi with phi = atan2(y/b, x/a) in [0, 2 pi), v from 0 at
/// the south pole (z = -c) to 1 at the north pole.
struct Ellipsoid {
  static constexpr const char* kName = "ellipsoid";
  Vec3 center;
  Vec3 radii{1, 1, 1};
  Vec3 inv_radii{1, 1, 1};  // 1 / radii, so a ray reaches unit-sphere space by multiplies only
};

/// A validated ellipsoid (finite center; each radius > 0 and finite); throws std::invalid_argument.
Ellipsoid make_ellipsoid(const Vec3& center, const Vec3& radii);

Aabb bounds(const Ellipsoid& e);
bool intersect(const Ellipsoid& e, const Ray& ray, LocalHit& hit);
bool occluded(const Ellipsoid& e, const Ray& ray);
void spans(const Ellipsoid& e, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Ellipsoid& e, const Ray& ray, const LocalHit& hit);
/// surface() without (u, v) (left 0): no atan2 or acos (objects/object.h, SurfaceNeeds).
SurfaceInfo surface_geometry(const Ellipsoid& e, const Ray& ray, const LocalHit& hit);
bool contains(const Ellipsoid& e, const Vec3& p);
inline bool is_closed(const Ellipsoid&) { return true; }

}  // namespace raycast
