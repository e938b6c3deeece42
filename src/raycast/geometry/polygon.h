#pragma once
// Planar simple polygons (concave allowed), an open surface.
#include <vector>

#include "geometry/shape.h"

namespace raycast {

/// The polygon with the given vertices in order. Its normal points to the side from which the
/// vertices run counter-clockwise (Newell's area vector). Hits are found on the plane, then
/// kept by the crossing-number test in the 2D projection that drops the normal's dominant axis,
/// with half-open edges so that a point on a shared edge belongs to exactly one of two polygons
/// that share it. (u, v) are plane coordinates in scene units: from the first vertex, u along
/// the first edge, v along n x u.
struct Polygon {
  static constexpr const char* kName = "polygon";
  std::vector<Vec3> vertices;
  Vec3 n;                      // unit normal
  double offset = 0;           // n . p on the plane
  int axis_u = 0, axis_v = 1;  // the two coordinates kept by the 2D projection
  Vec3 eu, ev;                 // (u, v) axes
  Aabb box;
};

/// How far a vertex may lie off the polygon's best plane, relative to the polygon's size (the
/// largest extent of its box): a few digits less than double precision, for hand-typed input.
inline constexpr double kPolygonPlanarity = 1e-7;
/// The smallest area, relative to size^2, that a polygon may have.
inline constexpr double kPolygonMinArea = 1e-12;

/// A validated polygon: at least 3 finite vertices, non-zero area, planar to kPolygonPlanarity,
/// no two non-adjacent edges touching (simple). Throws std::invalid_argument naming the cause
/// (messages start with "vertices[i]" when one vertex is at fault).
Polygon make_polygon(const std::vector<Vec3>& vertices);

Aabb bounds(const Polygon& p);
bool intersect(const Polygon& p, const Ray& ray, LocalHit& hit);
void spans(const Polygon& p, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Polygon& p, const Ray& ray, const LocalHit& hit);
inline bool contains(const Polygon&, const Vec3&) { return false; }
inline bool is_closed(const Polygon&) { return false; }

/// The crossing-number test in the polygon's 2D projection, for a point on its plane.
bool polygon_contains_projected(const Polygon& p, const Vec3& q);

}  // namespace raycast
