#pragma once
// Surfaces of revolution: a profile curve in the (r, z) half-plane revolved about the z axis.
#include <array>
#include <vector>

#include "geometry/shape.h"
#include "math/polynomial.h"

namespace raycast {

enum class ProfileCurve { kLinear, kBSpline };

/// The profile [[r, z], ...] revolved about z, as line segments (linear) or a uniform cubic
/// B-spline (each 4 consecutive control points make one segment; the curve starts at
/// (P0 + 4 P1 + P2) / 6: repeat an end point three times to start exactly there). With `capped`,
/// disks close the ends that lie off the axis. Closed (a solid) when capped or when both ends lie
/// on the axis; else an open surface whose normals point as the closed solid's would.
/// Per segment the ray is reduced, as in the lecture seeds (Pelikan), to a r^2 + b z^2 + c z + d =
/// 0 with t eliminated, and the segment's r(s), z(s) substituted: a polynomial in s of twice the
/// curve's degree (2 or 6), solved on [0, 1] by find_real_roots, then t = (z(s) - z0) / z1 and a
/// Newton polish of (s, t). Near-horizontal rays (z1 ~ 0, where that form vanishes) solve z(s) = z0
/// and the ray's circle equation instead. (u, v) = (phi / 2 pi, (segment + s) / segments).
struct Revolution {
  static constexpr const char* kName = "revolution";
  struct Segment {
    Polynomial r, z;                      // in s over [0, 1]
    double z_lo = 0, z_hi = 0, r_hi = 0;  // bounds of the segment (from its control points)
  };
  struct Cap {
    double z = 0, radius = 0;
    double normal_z = 1;  // +1 or -1: out of the solid
    double v = 0;         // 0 at the profile's start, 1 at its end
  };
  std::vector<Segment> segments;
  std::vector<Cap> caps;
  bool closed = false;
  double orientation = 1;  // +1 when the closed profile loop runs counter-clockwise in (r, z)
  Aabb box;
};

/// Validates (finite points, r >= 0, at least 2 points for linear and 4 for bspline, not all on
/// one point) and builds the segments; throws std::invalid_argument.
Revolution make_revolution(const std::vector<std::array<double, 2>>& profile, ProfileCurve curve,
                           bool capped = true);

Aabb bounds(const Revolution& s);
bool intersect(const Revolution& s, const Ray& ray, LocalHit& hit);
void spans(const Revolution& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Revolution& s, const Ray& ray, const LocalHit& hit);
bool contains(const Revolution& s, const Vec3& p);
inline bool is_closed(const Revolution& s) { return s.closed; }

}  // namespace raycast
