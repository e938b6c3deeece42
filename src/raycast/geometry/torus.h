#pragma once
// The torus about the z axis, intersected through its quartic with an isolating solver.
#include "geometry/shape.h"
#include "math/polynomial.h"

namespace raycast {

/// The solid (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) < 0: the tube of radius r around the
/// circle of radius R in the xy plane, centred at the origin. r > R (a spindle torus) is allowed:
/// the solid is then the "apple" without its inner "lemon". (u, v) = (phi, theta) / 2 pi with
/// phi = atan2(y, x) around z and theta = atan2(z, rho - R) around the tube, both in [0, 2 pi).
struct Torus {
  static constexpr const char* kName = "torus";
  double major_radius = 1;     // R
  double minor_radius = 0.25;  // r
};

/// A validated torus (both radii > 0 and finite); throws std::invalid_argument.
Torus make_torus(double major_radius, double minor_radius);

Aabb bounds(const Torus& s);
bool intersect(const Torus& s, const Ray& ray, LocalHit& hit);
void spans(const Torus& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Torus& s, const Ray& ray, const LocalHit& hit);
/// surface() without (u, v) (left 0): no atan2 (objects/object.h, SurfaceNeeds).
SurfaceInfo surface_geometry(const Torus& s, const Ray& ray, const LocalHit& hit);
bool contains(const Torus& s, const Vec3& p);
inline bool is_closed(const Torus&) { return true; }

/// The torus's implicit function at p (negative inside).
double torus_function(const Torus& s, const Vec3& p);

/// The quartic of the line in a well-conditioned frame: the line's point nearest the centre,
/// o + t_c d, becomes the origin and the variable u is arc length (t = t_c + u / |d|). Returns
/// false when the line misses the bounding sphere; else fills the quartic in u, t_c, 1 / |d| and
/// the half-length h of the chord through the bounding sphere (every root has |u| <= h).
struct TorusQuartic {
  Polynomial p;
  double t_c = 0;
  double inv_len = 0;
  double h = 0;
  Vec3 c, e;  // the line's point nearest the centre, its unit direction: the line is c + u e
};
bool torus_quartic(const Torus& s, const Ray& ray, TorusQuartic& q);

}  // namespace raycast
