#pragma once
// Disks and annuli, whole or partial (pbrt-style), in object space.
#include "geometry/shape.h"

namespace raycast {

/// The flat annulus inner_radius <= r <= radius around `center` in the plane through it with
/// unit normal n, keeping 0 <= phi <= phi_max, where phi is the angle from the in-plane axis s
/// towards t (s, t, n right-handed). The canonical disk (make_disk) has center (0, 0, height),
/// n = +z, s = +x, t = +y, so phi = atan2(y, x) in [0, 2 pi) as for the sphere. An open surface
/// whose normal is n. (u, v) = (phi / phi_max, (radius - r) / (radius - inner_radius)).
struct Disk {
  static constexpr const char* kName = "disk";
  Vec3 center;
  Vec3 n{0, 0, 1}, s{1, 0, 0}, t{0, 1, 0};
  double radius = 1;
  double inner_radius = 0;
  double phi_max = 0;     // radians in (0, 2 pi]; set by make_disk
  bool canonical = true;  // n, s, t are the coordinate axes (exact arithmetic on z)
};

/// pbrt's disk: z = height, radius > 0, 0 <= inner_radius < radius, 0 < phi_max_degrees <= 360,
/// all finite. Throws std::invalid_argument naming the bad parameter otherwise.
Disk make_disk(double radius, double inner_radius = 0, double height = 0,
               double phi_max_degrees = 360);
/// The whole disk or annulus around `center` facing `normal` (finite, non-zero; normalised here).
/// phi is measured from the axis s of make_frame(normal) (vec3.h).
Disk make_disk(const Vec3& center, const Vec3& normal, double radius, double inner_radius = 0);

Aabb bounds(const Disk& d);
bool intersect(const Disk& d, const Ray& ray, LocalHit& hit);
void spans(const Disk& d, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Disk& d, const Ray& ray, const LocalHit& hit);
inline bool contains(const Disk&, const Vec3&) { return false; }
inline bool is_closed(const Disk&) { return false; }

}  // namespace raycast
