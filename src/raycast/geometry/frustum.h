#pragma once
// The core shared by the partial cylinder and cone (pbrt-style): a surface of revolution about z
// whose radius varies linearly, r(z) = r0 + k (z - z0) for z0 <= z <= z1, cut to
// 0 <= phi <= phi_max, with optional disks (caps) at z0 and z1. An optional orthonormal frame
// places it (the from/to forms). Cylinder and Cone (cylinder.h, cone.h) wrap it.
#include "geometry/quadric_line.h"
#include "geometry/shape.h"

namespace raycast {

struct Frustum {
  double z0 = 0, z1 = 1;                    // z range, z0 < z1
  double r0 = 1, r1 = 1;                    // radii at z0 and z1 (>= 0, not both 0)
  double k = 0;                             // (r1 - r0) / (z1 - z0)
  double phi_max = 0;                       // radians in (0, 2 pi]
  double cos_phi_max = 1, sin_phi_max = 0;  // for the angle test without atan2
  bool capped = true;
  // Local frame: p_local = (ex . (p - origin), ey . (p - origin), ez . (p - origin)).
  bool has_frame = false;
  Vec3 origin;
  Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};

  /// A closed solid when full around the axis and capped; otherwise an open surface.
  bool is_closed() const;
};

/// Hit parts of a frustum: the side, the cap at z0, the cap at z1.
inline constexpr int kFrustumSide = 0, kFrustumCap0 = 1, kFrustumCap1 = 2;

/// A validated frustum in canonical position (angles in degrees); throws std::invalid_argument.
Frustum make_frustum(double z0, double z1, double r0, double r1, double phi_max_degrees,
                     bool capped);
/// A validated frustum from `from` (radius r0) to `to` (radius r1), full around its axis.
Frustum make_frustum(const Vec3& from, const Vec3& to, double r0, double r1, bool capped);

Aabb frustum_bounds(const Frustum& f);
bool frustum_intersect(const Frustum& f, const Ray& ray, LocalHit& hit);
void frustum_spans(const Frustum& f, const Ray& ray, SpanList& out);
/// A closed frustum's intervals of the whole line (at most 2, sorted; the ends' parts as in
/// frustum_spans, which makes its spans from these), without a span list: for CSG's walk.
int frustum_solid_intervals(const Frustum& f, const Ray& ray, LineInterval out[2]);
/// u = phi / phi_max (phi from ex, counter-clockwise about ez), v = (z - z0) / (z1 - z0).
/// Side normals point away from the axis (as the closed solid's would), caps along -+ez.
SurfaceInfo frustum_surface(const Frustum& f, const Ray& ray, const LocalHit& hit);
/// frustum_surface without (u, v) (left 0): no atan2, for hits that need no parameters.
SurfaceInfo frustum_surface_geometry(const Frustum& f, const Ray& ray, const LocalHit& hit);
bool frustum_contains(const Frustum& f, const Vec3& p);

}  // namespace raycast
