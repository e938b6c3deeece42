#pragma once
// POV-Ray's prism point lists: the four spline kinds, read into closed contours.
#include <array>
#include <vector>

#include "math/contour.h"

namespace raycast {

enum class PrismSpline { kLinear, kQuadratic, kCubic, kBezier };

/// The contours of a prism's point list, as POV-Ray reads it. Points run in sub-shapes; each
/// closes when a point repeats the sub-shape's first point on the curve, and the next point
/// starts the next sub-shape.
/// - linear: P0, P1, ..., Pn = P0: straight pieces.
/// - quadratic: P0 is a control point, P1 the start, Pn = P1 closes; the piece from Pi to Pi+1
///   is the parabola through Pi-1, Pi, Pi+1 at s = -1, 0, 1 continued to s = 1.
/// - cubic: P0 and the point after the closing Pn = P1 are control points; the piece from Pi to
///   Pi+1 is the Catmull-Rom curve with tangent (Pi+1 - Pi-1) / 2 at Pi.
/// - bezier: four points per piece; a piece ending at the sub-shape's first point closes it.
/// A last sub-shape left open is closed by a straight piece. Throws std::invalid_argument when
/// a sub-shape has too few points to make a piece.
std::vector<Contour> spline_contours(const std::vector<std::array<double, 2>>& points,
                                     PrismSpline spline);

}  // namespace raycast
