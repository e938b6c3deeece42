#pragma once
// Closest points on the surfaces of the analytic shapes that have a closed form (or a robust
// iteration): the distance queries of the public API (docs/library.md "Distances"). Everything
// is in the shape's own space; points must be finite.
#include "geometry/box.h"
#include "geometry/cone.h"
#include "geometry/cylinder.h"
#include "geometry/ellipsoid.h"
#include "geometry/plane.h"
#include "geometry/sphere.h"
#include "geometry/torus.h"
#include "geometry/triangle.h"

namespace raycast {

/// The point of the plane nearest p (its orthogonal projection).
Vec3 closest_point(const Plane& s, const Vec3& p);
/// The point of the sphere's surface nearest p; false for a partial sphere (z or phi cut). At the
/// centre every surface point is nearest: the one on +x is returned.
bool closest_point(const Sphere& s, const Vec3& p, Vec3& q);
/// The point of the box's surface nearest p, from inside as from outside.
Vec3 closest_point(const Box& s, const Vec3& p);
/// The point of the ellipsoid's surface nearest p, by Eberly's robust bisection on the root of
/// the Lagrange condition (D. Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a
/// Hyperellipsoid", 2013), exact to the last bits of the bisection's bracket.
Vec3 closest_point(const Ellipsoid& s, const Vec3& p);
/// Cylinders and cones full around their axis (capped or not): the nearest point of the profile
/// (side segment and cap segments) in the half-plane through p and the axis. False for a
/// partial (phi-cut) one.
bool closest_point(const Cylinder& s, const Vec3& p, Vec3& q);
bool closest_point(const Cone& s, const Vec3& p, Vec3& q);
/// The nearest point of the torus: on the profile circle in the half-plane through p and the z
/// axis (for a spindle torus, on the outer arc only).
Vec3 closest_point(const Torus& s, const Vec3& p);
/// The point of the triangle (a, b, c) nearest p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace raycast
