#pragma once
// Candidate lists by direction around a fixed point, the apex (POV-Ray's vista and light
// buffers, made exact): the directions from the apex are cut into the cells of a cube map, and
// each cell keeps the objects whose bounding balls meet the cone of its directions. A ray that
// starts at the apex (a pinhole camera's), or a segment that ends at it (a point light's shadow
// ray), can only meet the objects of the cell its direction falls in. Each entry also keeps a
// lower bound of the distance from the apex to its object, for the nearest-hit walk's early stop
// and the shadow walk's cut at the segment's length. docs/rendering.md "Direction lists".
//
// Why no object is lost: cell_of's face is the exact major axis of d, and its cell coordinates
// err by less than 5e-16 in face units (a face spans [-1, 1]; three rounded operations, below);
// each cell is widened by kWidening (1e-9) in face coordinates before its cone is taken, and an
// object is dropped from a cell only when its ball lies more than kAngleMargin (1e-7 radians)
// outside the circular cone around the cell (see build). That margin also covers a shadow segment's
// end, from + (to - from) rounded, which misses the apex by a few ulps of |d|: for |d| <=
// kSegmentReach * reach() and balls further than kNearApex * reach() from the apex (nearer ones
// are in every cell), the segment's points in such a ball lie within 2e-8 radians of -d's
// direction. (With d = (to - from)(1 + delta) by component, |delta| <= 2^-53, a point
// p = from + t d, t in [0, 1], is apex + (t - 1)(to - from) + t (d - (to - from)): the first term
// lies along -d's exact direction, the second is at most 1.9e-16 |d| <= 1.9e-14 reach long,
// against |p - apex| >= 1e-6 reach; and -d's own direction errs by 2e-16.)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "objects/ball_list.h"

namespace raycast {

class DirectionLists {
 public:
  /// An object's ball, as the lists take it (index: the object's index in the scene).
  struct Ball {
    std::uint32_t index;
    Vec3 centre;
    double radius;
  };
  /// A cell's entry: the object's index, its ball (centre, radius squared widened as
  /// objects/ball_list.h's), and a value not above the square of its distance from the apex (0 when
  /// the apex is in or near its ball), for the walks' cuts.
  struct Entry {
    double near2;
    double x, y, z, radius2;
    std::uint32_t index;
    /// Whether the half-line from o along d (dd = |d|^2, within [1e-30, 1e30]; o within
    /// kBallLimit) may come within the ball: each_ball_near's test (objects/ball_list.h) with its
    /// terms scaled by dd, the same operations for a unit d and dd = 1.
    bool may_meet(const Vec3& o, const Vec3& d, double dd) const {
      const double vx = x - o.x, vy = y - o.y, vz = z - o.z;
      const double vv = (vx * vx + vy * vy + vz * vz) * dd * (1 - kBallSlack);
      const double k = vx * d.x + vy * d.y + vz * d.z;
      const double kk = k > 0 ? k * k : 0.0;
      return vv - kk <= radius2 * dd;
    }
  };
  enum class Order { kNearestFirst, kIndex };

  /// Lists for `apex` over `balls` (finite, radius >= 0), side x side cells per cube face,
  /// each cell's entries nearest first (ties in index order) or in index order. reach (> 0,
  /// finite): the scale of the scene seen from the apex (the longest shadow segment the lists
  /// serve, and the unit of the margins).
  void build(const Vec3& apex, std::span<const Ball> balls, double reach, int side, Order order);
  bool built() const { return !start_.empty(); }
  const Vec3& apex() const { return apex_; }
  /// The longest direction (|d|^2) the lists serve for segments that end at the apex.
  double reach2() const { return (kSegmentReach * reach_) * (kSegmentReach * reach_); }

  /// The cell of direction d (finite, not zero): the face of its major axis (ties: x before y
  /// before z), then the cell of its other two components divided by |major|.
  std::size_t cell_of(const Vec3& d) const {
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    double a, u, v;
    std::size_t face;
    if (ax >= ay && ax >= az) {
      a = d.x, u = d.y, v = d.z, face = 0;
    } else if (ay >= az) {
      a = d.y, u = d.z, v = d.x, face = 2;
    } else {
      a = d.z, u = d.x, v = d.y, face = 4;
    }
    face += a < 0;
    // With U = u / |a| in [-1, 1] exactly: fl(u * s) = U half (1 + t), |t| <= 2.3e-16, and the
    // sum adds a rounding of at most 2 half 2^-53; so the value errs from (U + 1) half by at most
    // 4.6e-16 half, U by 4.6e-16. Truncation sends (-1, 1) to 0; the top edge is clamped.
    const double s = half_ / std::abs(a);
    const int i = std::min(static_cast<int>(u * s + half_), last_);
    const int j = std::min(static_cast<int>(v * s + half_), last_);
    return (face * std::size_t(side_) + std::size_t(j)) * std::size_t(side_) + std::size_t(i);
  }
  /// The direction of face `face`'s point (u, v) in face coordinates (cell_of's inverse).
  static Vec3 face_direction(std::size_t face, double u, double v);
  /// The entries of direction d's cell.
  std::span<const Entry> cell(const Vec3& d) const {
    const std::size_t c = cell_of(d);
    return {entries_.data() + start_[c], entries_.data() + start_[c + 1]};
  }
  std::size_t memory_bytes() const {
    return start_.capacity() * sizeof(std::uint32_t) + entries_.capacity() * sizeof(Entry);
  }

  /// Each cell's widening in face coordinates (a face spans [-1, 1]).
  static constexpr double kWidening = 1e-9;
  /// The angle by which each cell's cone is widened.
  static constexpr double kAngleMargin = 1e-7;
  /// Segments that end at the apex are served up to this many times reach() long (the header's
  /// argument; shadow rays from a plane's far points are longer than reach: 1.2 % fewer
  /// instructions than at 1 on the csg scene of bench/render_instructions.sh).
  static constexpr double kSegmentReach = 100;
  /// Balls that come within this fraction of reach() of the apex are in every cell.
  static constexpr double kNearApex = 1e-6;

 private:
  Vec3 apex_;
  double reach_ = 0;
  int side_ = 0, last_ = 0;
  double half_ = 0;                   // side / 2
  std::vector<std::uint32_t> start_;  // cell c's entries: [start_[c], start_[c + 1])
  std::vector<Entry> entries_;
};

}  // namespace raycast
