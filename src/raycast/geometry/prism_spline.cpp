#include "geometry/prism_spline.h"

#include <stdexcept>
#include <string>

namespace raycast {

namespace {

using Point = std::array<double, 2>;

Point plus_diff(const Point& a, const Point& b, const Point& c, double w) {  // a + w (b - c)
  return {a[0] + w * (b[0] - c[0]), a[1] + w * (b[1] - c[1])};
}

ContourPiece line(const Point& a, const Point& b) {
  ContourPiece p;
  p.degree = 1;
  p.p[0] = a;
  p.p[1] = b;
  return p;
}

// Closes a contour left open by a straight piece back to its start.
void close(Contour& c) {
  if (c.empty()) return;
  const Point& end = c.back().p[static_cast<std::size_t>(c.back().degree)];
  if (end != c.front().p[0]) c.push_back(line(end, c.front().p[0]));
}

std::vector<Contour> linear_contours(const std::vector<Point>& pt) {
  std::vector<Contour> out;
  Contour c;
  std::size_t start = 0;
  for (std::size_t i = 1; i < pt.size(); ++i) {
    if (i == start) continue;
    if (pt[i] != pt[i - 1]) c.push_back(line(pt[i - 1], pt[i]));
    if (pt[i] == pt[start]) {
      if (!c.empty()) out.push_back(c);
      c.clear();
      start = i + 1;
    }
  }
  close(c);
  if (!c.empty()) out.push_back(c);
  return out;
}

// Quadratic (Lagrange through Pi-1, Pi, Pi+1) and cubic (Catmull-Rom) pieces share the layout:
// `lead` control points before the curve's first point, `trail` after its closing point.
std::vector<Contour> interpolating_contours(const std::vector<Point>& pt, bool cubic) {
  std::vector<Contour> out;
  const std::size_t lead = 1, trail = cubic ? 1 : 0;
  std::size_t first = 0;  // the sub-shape's first point (a control point)
  while (first + lead < pt.size()) {
    const std::size_t s = first + lead;  // the curve's start
    std::size_t end = s + 1;
    while (end < pt.size() && pt[end] != pt[s]) ++end;
    if (end >= pt.size()) end = pt.size() - 1 - trail;  // never closed: curve to the end
    if (end <= s || end + trail >= pt.size())
      throw std::invalid_argument("a sub-shape starting at point " + std::to_string(first) +
                                  " has too few points for a " + (cubic ? "cubic" : "quadratic") +
                                  " spline");
    Contour c;
    for (std::size_t i = s; i < end; ++i) {
      if (pt[i] == pt[i + 1]) continue;
      ContourPiece p;
      p.p[0] = pt[i];
      if (!cubic) {
        // q(s) = Pi + s (Pi+1 - Pi-1) / 2 + s^2 (...): the control point is Pi + q'(0) / 2.
        p.degree = 2;
        p.p[1] = plus_diff(pt[i], pt[i + 1], pt[i - 1], 0.25);
        p.p[2] = pt[i + 1];
      } else {
        p.degree = 3;
        p.p[1] = plus_diff(pt[i], pt[i + 1], pt[i - 1], 1.0 / 6);
        p.p[2] = plus_diff(pt[i + 1], pt[i], pt[i + 2], 1.0 / 6);
        p.p[3] = pt[i + 1];
      }
      c.push_back(p);
    }
    close(c);
    if (!c.empty()) out.push_back(c);
    first = end + 1 + trail;
  }
  return out;
}

std::vector<Contour> bezier_contours(const std::vector<Point>& pt) {
  if (pt.size() % 4 != 0)
    throw std::invalid_argument("a bezier spline needs 4 points per piece, got " +
                                std::to_string(pt.size()) + " points");
  std::vector<Contour> out;
  Contour c;
  for (std::size_t i = 0; i + 3 < pt.size(); i += 4) {
    if (!c.empty() && pt[i] != c.back().p[3]) {
      close(c);  // a piece that does not continue the last one starts a new sub-shape
      out.push_back(c);
      c.clear();
    }
    ContourPiece p;
    p.degree = 3;
    for (std::size_t k = 0; k < 4; ++k) p.p[k] = pt[i + k];
    if (p.p[0] != p.p[3] || p.p[1] != p.p[0] || p.p[2] != p.p[0]) c.push_back(p);
    if (!c.empty() && pt[i + 3] == c.front().p[0]) {
      out.push_back(c);
      c.clear();
    }
  }
  close(c);
  if (!c.empty()) out.push_back(c);
  return out;
}

}  // namespace

std::vector<Contour> spline_contours(const std::vector<std::array<double, 2>>& points,
                                     PrismSpline spline) {
  switch (spline) {
    case PrismSpline::kLinear:
      return linear_contours(points);
    case PrismSpline::kQuadratic:
      return interpolating_contours(points, false);
    case PrismSpline::kCubic:
      return interpolating_contours(points, true);
    case PrismSpline::kBezier:
      return bezier_contours(points);
  }
  return {};
}

}  // namespace raycast
