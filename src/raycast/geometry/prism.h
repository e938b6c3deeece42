#pragma once
// Prisms: a set of closed 2-D contours in the x-y plane swept along z, straight (a linear sweep)
// or towards the origin (a conic sweep).
#include <array>
#include <vector>

#include "geometry/shape.h"
#include "math/contour.h"
#include "math/polynomial.h"

namespace raycast {

/// The solid whose cross-section at height z in [z0, z1] is the region inside an odd number of the
/// contours (the even-odd rule, so contours inside contours make holes). A linear sweep keeps the
/// cross-section as it is; a conic sweep scales it by z, so its sides are ruled surfaces through
/// the origin (cross-section z = 1 is the contours as given). `open` drops the two caps: the sides
/// alone, an open surface.
/// Sides: per piece, the plane that holds the ray and the sweep's ruling (parallel to z, or through
/// the origin) meets the contour where a x(s) + b y(s) + c = 0, a polynomial of the piece's degree
/// in its parameter s, solved on [0, 1] by find_real_roots; t follows from the ruling. Caps: the
/// crossing-number test of the 2-D point against every piece, split where y(s) turns so each part
/// crosses a horizontal line at most once. (u, v): on the sides ((piece + s) / pieces, height
/// fraction), on the caps the contour coordinates (x, y) of the hit.
struct Prism {
  static constexpr const char* kName = "prism";
  struct Piece {
    Polynomial x, y;                                // in s over [0, 1]
    std::array<double, 2> start{}, end{};           // exact end points (shared with the neighbours)
    double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;  // the control points' box
    double outward = 1;  // +1: (y', -x') points out of the solid, else -1
    // Where x(s) or y(s) turns inside (0, 1), ascending: the piece is monotone in x and in y
    // between them.
    std::array<double, 4> turns{};
    int turn_count = 0;
  };
  std::vector<Piece> pieces;
  double z0 = 0, z1 = 1;  // the sweep's heights, z0 < z1
  bool conic = false;
  bool open = false;
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;  // the contours' box
  Aabb box;
};

/// A validated prism: at least one contour, finite points, pieces of degree 1 to 3 joined end to
/// end and closed, z0 != z1 (swapped when given in decreasing order), and for a conic sweep
/// heights of one sign. Contours without area are left out (they bound nothing); none with area
/// left is an error. Throws std::invalid_argument naming the cause.
Prism make_prism(const std::vector<Contour>& contours, double z0, double z1, bool conic = false,
                 bool open = false);

Aabb bounds(const Prism& s);
bool intersect(const Prism& s, const Ray& ray, LocalHit& hit);
void spans(const Prism& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Prism& s, const Ray& ray, const LocalHit& hit);
bool contains(const Prism& s, const Vec3& p);
inline bool is_closed(const Prism& s) { return !s.open; }

/// The even-odd test of the 2-D point (x, y) against the prism's contours (its cross-section at
/// z = 1).
bool inside_contours(const Prism& s, double x, double y);

}  // namespace raycast
