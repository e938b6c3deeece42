#pragma once
// POV-Ray evaluates its checker at p + 0.001 (its small tolerance), so a floor through an integer
// coordinate (plane { y, 0 }) is one colour, not noise. raycast's checker has no offset: the
// shape's points are moved by kCheckerOffset * scale in object space and moved back by the
// transform, only where a flat face lies on the grid (the transform costs time on every ray).
#include <cmath>

#include "pov/pov_scene.h"

namespace raycast::pov {

inline constexpr double kCheckerOffset = 1e-3;

/// Whether a flat face of the shape lies in a plane x, y or z = k * scale (k whole).
inline bool on_checker_grid(const Node& n, double scale) {
  auto on = [&](double v) { return std::floor(v / scale) == v / scale; };
  auto axis_of = [](const Vec3& d) {  // the axis d is along, or -1
    if (d.y == 0 && d.z == 0) return 0;
    if (d.x == 0 && d.z == 0) return 1;
    if (d.x == 0 && d.y == 0) return 2;
    return -1;
  };
  auto at = [](const Vec3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
  switch (n.kind) {
    case Node::Plane: {
      const int a = axis_of(n.points[0]);
      return a >= 0 && on(n.values[0]);  // the plane is at +-distance on that axis
    }
    case Node::Box:
      for (const Vec3& c : n.points)
        if (on(c.x) || on(c.y) || on(c.z)) return true;
      return false;
    case Node::Disc: {
      const int a = axis_of(n.points[1]);
      return a >= 0 && on(at(n.points[0], a));
    }
    case Node::Cylinder:
    case Node::Cone: {
      const int a = axis_of(n.points[1] - n.points[0]);
      return a >= 0 && (on(at(n.points[0], a)) || on(at(n.points[1], a)));
    }
    case Node::Mesh:
      for (const auto& t : n.triangles)
        for (int a = 0; a < 3; ++a) {
          const double v = at(n.vertices[static_cast<std::size_t>(t[0])], a);
          if (on(v) && at(n.vertices[static_cast<std::size_t>(t[1])], a) == v &&
              at(n.vertices[static_cast<std::size_t>(t[2])], a) == v)
            return true;
        }
      return false;
    default:
      return false;  // curved surfaces meet the grid's planes along curves only
  }
}

}  // namespace raycast::pov
