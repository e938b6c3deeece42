#pragma once
// POV-Ray's superellipsoid: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in [-1, 1]^3, its
// crossings isolated by interval bounds and refined to double precision.
#include "geometry/shape.h"

namespace raycast {

/// The solid (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1: e shapes the cross-sections
/// across z, n the profile along z. e = n = 1 is the unit sphere, e = n = 2 the octahedron
/// |x| + |y| + |z| <= 1, small e and n tend to the cube [-1, 1]^3; above 2 the solid is
/// star-shaped with concave parts. (u, v) = (atan2(y, x) / 2 pi in [0, 1), the polar angle from
/// -z over pi).
struct Superellipsoid {
  static constexpr const char* kName = "superellipsoid";
  double e = 1;  // the exponent across z (POV-Ray's first, "east-west")
  double n = 1;  // the exponent along z (POV-Ray's second, "north-south")
};

/// A validated superellipsoid: e and n finite and in [kSuperellipsoidMinExponent,
/// kSuperellipsoidMaxExponent]; throws ShapeParameterError.
inline constexpr double kSuperellipsoidMinExponent = 1e-6;
inline constexpr double kSuperellipsoidMaxExponent = 1e3;
Superellipsoid make_superellipsoid(double e, double n);

Aabb bounds(const Superellipsoid& s);
bool intersect(const Superellipsoid& s, const Ray& ray, LocalHit& hit);
void spans(const Superellipsoid& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Superellipsoid& s, const Ray& ray, const LocalHit& hit);
bool contains(const Superellipsoid& s, const Vec3& p);
inline bool is_closed(const Superellipsoid&) { return true; }

/// The gauge of the solid at p: the s with p / s on the surface (homogeneous of degree 1, <= 1
/// inside), computed from ratios so that no exponent over- or underflows for finite p.
double superellipsoid_gauge(const Superellipsoid& s, const Vec3& p);

}  // namespace raycast
