#pragma once
// General quadrics f(p) = Ax^2 + By^2 + Cz^2 + Dxy + Exz + Fyz + Gx + Hy + Iz + J, the solid
// f < 0, optionally clipped to a box whose faces close it (POV-Ray's contained_by).
#include <array>
#include <optional>

#include "geometry/shape.h"
#include "math/transform.h"

namespace raycast {

/// The ten coefficients A..J of f, in that order.
using QuadricCoefficients = std::array<double, 10>;

/// The canonical quadrics of docs/scene-format.md's table (parameters a, b, c > 0).
enum class QuadricKind { kEllipsoid, kParaboloid, kHyperboloid1, kHyperboloid2, kCone, kCylinder };

/// The solid f(p) < 0 (inside), within `box` when one is given; with `open` only the curved
/// surface (inside the box, if any) remains, an open surface. The normal of the curved surface
/// is grad f normalised (out of the solid); where grad f vanishes (a cone's apex) the normal is
/// -d / |d|, facing the ray. Box faces have their axis normals. (u, v) are 0.
struct Quadric {
  static constexpr const char* kName = "quadric";
  QuadricCoefficients c{};
  std::optional<Aabb> box;  // the clipping box; absent means unbounded
  bool open = false;
  Aabb hull = Aabb::everything();  // the box, tightened to the ellipsoid when f is one
};

/// A validated quadric: finite coefficients, not all of A..I zero; a box with finite min < max
/// on every axis; f not positive definite with an empty inside. Throws std::invalid_argument.
Quadric make_quadric(const QuadricCoefficients& c, const std::optional<Aabb>& box = std::nullopt,
                     bool open = false);

/// The coefficients of x^T Q x for the homogeneous point x = (x, y, z, 1) and a symmetric Q
/// (A = Q00, D = 2 Q01, ..., J = Q33). Throws std::invalid_argument when Q is not symmetric to
/// kQuadricSymmetryTolerance relative to its largest entry.
QuadricCoefficients quadric_from_matrix(const Mat4& q);
/// Relative tolerance on |Q_ij - Q_ji| for a matrix to count as symmetric (user-typed decimals).
inline constexpr double kQuadricSymmetryTolerance = 1e-9;

/// The coefficients of a canonical kind (docs/shapes-quadrics.md); a, b, c must be > 0 and finite.
QuadricCoefficients quadric_of_kind(QuadricKind kind, double a, double b, double c);

/// f(p) and its gradient.
double quadric_value(const QuadricCoefficients& c, const Vec3& p);
Vec3 quadric_gradient(const QuadricCoefficients& c, const Vec3& p);

Aabb bounds(const Quadric& q);
bool intersect(const Quadric& q, const Ray& ray, LocalHit& hit);
void spans(const Quadric& q, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Quadric& q, const Ray& ray, const LocalHit& hit);
bool contains(const Quadric& q, const Vec3& p);
inline bool is_closed(const Quadric& q) { return !q.open; }

}  // namespace raycast
