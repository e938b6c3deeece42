#include "objects/direction_lists.h"

#include <algorithm>

namespace raycast {

Vec3 DirectionLists::face_direction(std::size_t face, double u, double v) {
  const double a = face % 2 == 0 ? 1.0 : -1.0;
  switch (face / 2) {
    case 0:
      return {a, u, v};
    case 1:
      return {v, a, u};
    default:
      return {u, v, a};
  }
}

void DirectionLists::build(const Vec3& apex, std::span<const Ball> balls, double reach, int side,
                           Order order) {
  apex_ = apex;
  reach_ = reach;
  side_ = side;
  last_ = side - 1;
  half_ = 0.5 * side;
  start_.assign(1, 0);
  entries_.clear();
  // Per ball: the unit direction of its centre, the cosine and sine of the angle its ball
  // subtends around it (asin(radius / distance)), and its entry; a ball that comes within
  // kNearApex * reach of the apex is in every cell.
  struct Seen {
    Vec3 unit;
    double cos_spread, sin_spread;
    bool everywhere;
    Entry entry;
  };
  std::vector<Seen> seen;
  const double near_apex = kNearApex * reach;
  for (const Ball& b : balls) {
    const Vec3 v = b.centre - apex;
    const double distance = length(v);
    const double gap = distance - b.radius;
    // 1e-6 below the exact bound: the cuts stay conservative for hits whose t errs far more
    // than a rounding (a tangent ray's double root).
    const double lower = gap * (1 - 1e-6) - near_apex;
    const Entry entry{lower > 0 ? lower * lower : 0.0, b.centre.x, b.centre.y, b.centre.z,
                      widened_radius2(b.radius),       b.index};
    const bool everywhere = gap <= near_apex;
    const double sin_spread = everywhere ? 1.0 : std::min(1.0, b.radius / distance);
    seen.push_back({everywhere ? Vec3{1, 0, 0} : v / distance,
                    std::sqrt(std::max(0.0, (1 - sin_spread) * (1 + sin_spread))), sin_spread,
                    everywhere, entry});
  }
  const double width = 2.0 / side;
  for (std::size_t face = 0; face < 6; ++face)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        // The cell's directions, widened, lie within `cone` of its centre's direction w: the
        // largest angle to the widened corners (the cell's cone is their conic hull, and the
        // directions within an angle below 90 degrees of w form a convex cone).
        const double u0 = -1 + width * i - kWidening, u1 = -1 + width * (i + 1) + kWidening;
        const double v0 = -1 + width * j - kWidening, v1 = -1 + width * (j + 1) + kWidening;
        const Vec3 w = normalize(face_direction(face, 0.5 * (u0 + u1), 0.5 * (v0 + v1)));
        double cos_cone = 1;
        for (double u : {u0, u1})
          for (double v : {v0, v1})
            cos_cone = std::min(cos_cone, dot(normalize(face_direction(face, u, v)), w));
        const double cone = std::acos(std::clamp(cos_cone, -1.0, 1.0)) + kAngleMargin;
        const double cos_c = std::cos(cone), sin_c = std::sin(cone);
        // A ball meets the cone only if the angle between its centre and w is at most the cone's
        // plus the ball's spread (the triangle inequality for angles), that is (for a sum below
        // pi) if the cosine of that angle is at least cos(cone + spread). The cosines err by a
        // few ulps; 1e-12 below covers that (kAngleMargin alone moves the bound by more than
        // 5e-15 at any angle).
        const std::size_t first = entries_.size();
        for (const Seen& s : seen) {
          const double bound = cos_c * s.cos_spread - sin_c * s.sin_spread - 1e-12;
          if (s.everywhere || dot(s.unit, w) >= bound) entries_.push_back(s.entry);
        }
        if (order == Order::kNearestFirst)
          std::stable_sort(entries_.begin() + std::ptrdiff_t(first), entries_.end(),
                           [](const Entry& a, const Entry& b) { return a.near2 < b.near2; });
        start_.push_back(static_cast<std::uint32_t>(entries_.size()));
      }
}

}  // namespace raycast
