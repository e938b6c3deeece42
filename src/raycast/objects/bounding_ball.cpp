#include "objects/bounding_ball.h"

#include <algorithm>
#include <cmath>

#include "objects/csg_tree.h"
#include "objects/prototype.h"

namespace raycast {

namespace {

Ball ball_around(const Aabb& b) {
  if (b.is_empty()) return {{}, -1};
  if (!b.is_bounded()) return {};
  return {b.centre(), 0.5 * length(b.extent())};
}

Ball smaller(const Ball& a, const Ball& b) { return b.radius < a.radius ? b : a; }

/// An upper bound on the operator norm of the transform's linear part A: the square root of
/// Gershgorin's bound on the largest eigenvalue of A^T A (1 for a rotation, up to rounding).
double norm_bound(const Transform& xf) {
  const auto& m = xf.matrix().m;
  double widest = 0;
  for (int i = 0; i < 3; ++i) {
    double row = 0;
    for (int j = 0; j < 3; ++j) {
      double g = 0;
      for (int k = 0; k < 3; ++k) g += m[k][i] * m[k][j];
      row += std::abs(g);
    }
    widest = std::max(widest, row);
  }
  return std::sqrt(widest) * (1 + 1e-12);
}

// A closed or open frustum (cylinder, cone): the solid is the hull of its two end discs, so the
// ball around both rims, centred on the axis where their distances agree (clamped to the axis
// segment), contains it.
Ball frustum_ball(const Frustum& f) {
  const double span = f.z1 - f.z0;
  double zc = (f.z1 * f.z1 - f.z0 * f.z0 + f.r1 * f.r1 - f.r0 * f.r0) / (2 * span);
  zc = std::clamp(std::isfinite(zc) ? zc : 0.5 * (f.z0 + f.z1), f.z0, f.z1);
  const double r = std::max(std::hypot(f.z0 - zc, f.r0), std::hypot(f.z1 - zc, f.r1));
  const Vec3 centre = f.has_frame ? f.origin + zc * f.ez : Vec3{0, 0, zc};
  return {centre, f.has_frame ? r * (1 + 1e-12) : r};  // the frame's rounding
}

Ball object_ball(const Object& o);

Ball csg_ball(const CsgTree& tree, std::int32_t code) {
  if (code < 0) {
    const auto leaf = static_cast<std::size_t>(-code - 1);
    if (leaf < tree.leaf_inverse.size() && tree.leaf_inverse[leaf]) return Ball{};  // unbounded
    return object_ball(tree.leaves[leaf]);
  }
  const CsgNode& node = tree.nodes[static_cast<std::size_t>(code)];
  Ball ball = csg_ball(tree, node.operands[0]);
  if (node.op != CsgOp::kDifference)
    for (std::size_t i = 1; i < node.operands.size(); ++i) {
      const Ball b = csg_ball(tree, node.operands[i]);
      ball = node.op == CsgOp::kUnion ? merge_balls(ball, b) : overlap_balls(ball, b);
    }
  return smaller(ball, ball_around(node.box));
}

// The shape's ball in its own space (not yet widened).
Ball shape_ball(const ShapeVariant& shape) {
  if (const auto* s = std::get_if<Sphere>(&shape)) return {s->center, s->radius};
  if (const auto* s = std::get_if<Box>(&shape)) return ball_around(Aabb{s->lo, s->hi});
  if (const auto* s = std::get_if<Cylinder>(&shape)) return frustum_ball(s->f);
  if (const auto* s = std::get_if<Cone>(&shape)) return frustum_ball(s->f);
  if (const auto* s = std::get_if<Torus>(&shape))
    return {{0, 0, 0}, s->major_radius + s->minor_radius};
  if (const auto* s = std::get_if<Ellipsoid>(&shape)) return {s->center, max_component(s->radii)};
  if (const auto* s = std::get_if<CsgShape>(&shape)) return csg_ball(*s->tree, 0);
  if (const auto* s = std::get_if<InstanceShape>(&shape)) {
    Ball ball{{}, -1};
    for (const Object& o : s->proto->objects) ball = merge_balls(ball, object_ball(o));
    return ball;
  }
  return std::visit([](const auto& s) { return ball_around(bounds(s)); }, shape);
}

// The object's ball in its parent's space (not yet widened): its shape's carried through its
// transform, or the ball around its box when smaller.
Ball object_ball(const Object& o) {
  const Aabb box = bounds(o);
  if (box.is_empty()) return {{}, -1};
  Ball ball = shape_ball(o.shape);
  if (ball.is_bounded() && !ball.is_empty() && o.xf)
    ball = {o.xf->point(ball.centre), ball.radius * norm_bound(*o.xf)};
  return smaller(ball, ball_around(box));
}

}  // namespace

Ball merge_balls(const Ball& a, const Ball& b) {
  if (a.is_empty()) return b;
  if (b.is_empty()) return a;
  if (!a.is_bounded() || !b.is_bounded()) return {};
  const Vec3 v = b.centre - a.centre;
  const double d = length(v);
  if (d + b.radius <= a.radius) return a;
  if (d + a.radius <= b.radius) return b;
  const double r = 0.5 * (d + a.radius + b.radius);
  return {a.centre + ((r - a.radius) / d) * v, r};
}

Ball overlap_balls(const Ball& a, const Ball& b) {
  if (a.is_empty() || b.is_empty()) return {{}, -1};
  if (!a.is_bounded()) return b;
  if (!b.is_bounded()) return a;
  const Vec3 v = b.centre - a.centre;
  const double d = length(v);
  // Apart by more than their radii (with a margin for the rounding of d): nothing in common.
  if (d > (a.radius + b.radius) * (1 + 1e-9)) return {{}, -1};
  Ball best = smaller(a, b);
  if (d + b.radius <= a.radius || d + a.radius <= b.radius) return best;
  // The balls' spheres meet in a circle at distance x from a's centre along v, of radius h; when
  // the circle's plane lies between the centres, each ball's cap beyond it is at most a
  // hemisphere, so the ball on that circle holds the lens. h^2 gets an absolute slack of 1e-9
  // a.radius^2: its cancellation near tangency cannot make it too small.
  const double x = (d * d + a.radius * a.radius - b.radius * b.radius) / (2 * d);
  if (x >= 0 && x <= d) {
    const double h =
        std::sqrt(std::max(0.0, a.radius * a.radius - x * x) + 1e-9 * a.radius * a.radius);
    if (h < best.radius) best = {a.centre + (x / d) * v, h};
  }
  return best;
}

Ball bounding_ball(const Object& o) {
  Ball ball = object_ball(o);
  if (ball.is_empty() || !ball.is_bounded()) return ball;
  const double scale = max_component(abs(ball.centre)) + ball.radius;
  ball.radius = ball.radius * (1 + 1e-9) + 1e-9 * scale;
  return ball;
}

}  // namespace raycast
