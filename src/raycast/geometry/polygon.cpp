#include "geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace raycast {

namespace {

// Orientation of c relative to the directed line a -> b in 2D: > 0 left, < 0 right, 0 on it.
double orient(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

bool on_segment(double ax, double ay, double bx, double by, double cx, double cy) {
  return std::min(ax, bx) <= cx && cx <= std::max(ax, bx) && std::min(ay, by) <= cy &&
         cy <= std::max(ay, by);
}

// Whether the closed 2D segments ab and cd share a point.
bool segments_touch(const double* a, const double* b, const double* c, const double* d) {
  const double o1 = orient(a[0], a[1], b[0], b[1], c[0], c[1]);
  const double o2 = orient(a[0], a[1], b[0], b[1], d[0], d[1]);
  const double o3 = orient(c[0], c[1], d[0], d[1], a[0], a[1]);
  const double o4 = orient(c[0], c[1], d[0], d[1], b[0], b[1]);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && on_segment(a[0], a[1], b[0], b[1], c[0], c[1])) ||
         (o2 == 0 && on_segment(a[0], a[1], b[0], b[1], d[0], d[1])) ||
         (o3 == 0 && on_segment(c[0], c[1], d[0], d[1], a[0], a[1])) ||
         (o4 == 0 && on_segment(c[0], c[1], d[0], d[1], b[0], b[1]));
}

}  // namespace

Polygon make_polygon(const std::vector<Vec3>& v) {
  const std::size_t n = v.size();
  if (n < 3) throw std::invalid_argument("needs at least 3 vertices, got " + std::to_string(n));
  Polygon p;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_finite(v[i]))
      throw std::invalid_argument("vertices[" + std::to_string(i) + "] must be finite");
    p.box.grow(v[i]);
  }
  const double size = max_component(p.box.extent());
  // Newell's area vector, relative to the first vertex for accuracy.
  Vec3 area;
  for (std::size_t i = 1; i + 1 < n; ++i) area += cross(v[i] - v[0], v[i + 1] - v[0]);
  const double len = length(area);
  if (!(0.5 * len > kPolygonMinArea * size * size) || !std::isfinite(len))
    throw std::invalid_argument("has zero area");
  p.n = area / len;
  Vec3 centroid;
  for (const Vec3& q : v) centroid += q;
  centroid /= static_cast<double>(n);
  p.offset = dot(p.n, centroid);
  std::size_t worst = 0;
  double worst_off = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double off = std::abs(dot(p.n, v[i] - centroid));
    if (off > worst_off) worst = i, worst_off = off;
  }
  if (worst_off > kPolygonPlanarity * size)
    throw std::invalid_argument("vertices[" + std::to_string(worst) +
                                "] is off the polygon's plane by " + std::to_string(worst_off) +
                                " (the polygon must be planar)");
  const int drop = max_dimension(abs(p.n));
  p.axis_u = (drop + 1) % 3;
  p.axis_v = (drop + 2) % 3;
  // Simple: no two non-adjacent edges share a point, and adjacent ones only their vertex.
  std::vector<double> xy(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    xy[2 * i] = v[i][p.axis_u];
    xy[2 * i + 1] = v[i][p.axis_v];
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t i1 = (i + 1) % n;
    if (xy[2 * i] == xy[2 * i1] && xy[2 * i + 1] == xy[2 * i1 + 1])
      throw std::invalid_argument("vertices[" + std::to_string(i1) +
                                  "] repeats the previous vertex");
    for (std::size_t j = i + 2; j < n; ++j) {
      const std::size_t j1 = (j + 1) % n;
      if (j1 == i) continue;  // adjacent through the closing edge
      if (segments_touch(&xy[2 * i], &xy[2 * i1], &xy[2 * j], &xy[2 * j1]))
        throw std::invalid_argument("has edges " + std::to_string(i) + " and " + std::to_string(j) +
                                    " cross: the polygon must be simple");
    }
  }
  p.vertices = v;
  p.eu = normalize(v[1] - v[0]);
  p.ev = cross(p.n, p.eu);
  return p;
}

bool polygon_contains_projected(const Polygon& p, const Vec3& q) {
  // Crossing number (Shimrat 1962; Franklin's PNPOLY): count edges crossed by the ray from q
  // along +u; an edge counts when its endpoints lie on opposite sides of v = q.v with the lower
  // end closed and the upper end open, so vertices on the ray are counted once.
  const double qu = q[p.axis_u], qv = q[p.axis_v];
  const std::size_t n = p.vertices.size();
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    double ua = p.vertices[i][p.axis_u], va = p.vertices[i][p.axis_v];
    double ub = p.vertices[j][p.axis_u], vb = p.vertices[j][p.axis_v];
    if ((va > qv) == (vb > qv)) continue;
    // The same edge in two polygons runs in opposite directions: order its ends (lower v first)
    // so both compute the same crossing bit for bit, and a point on it belongs to exactly one.
    if (va > vb) {
      std::swap(ua, ub);
      std::swap(va, vb);
    }
    const double u_cross = ua + (qv - va) * (ub - ua) / (vb - va);
    if (qu < u_cross) inside = !inside;
  }
  return inside;
}

Aabb bounds(const Polygon& p) { return p.box; }

namespace {
// The line's parameter at the plane; NaN or inf when parallel.
double plane_t(const Polygon& p, const Ray& ray) {
  return (p.offset - dot(p.n, ray.o)) / dot(p.n, ray.d);
}
}  // namespace

bool intersect(const Polygon& p, const Ray& ray, LocalHit& hit) {
  const double t = plane_t(p, ray);
  if (!(t >= ray.tmin && t <= ray.tmax) || !std::isfinite(t)) return false;
  if (!polygon_contains_projected(p, ray.at(t))) return false;
  hit = LocalHit{.t = t};
  return true;
}

void spans(const Polygon& p, const Ray& ray, SpanList& out) {
  const double t = plane_t(p, ray);
  if (!std::isfinite(t) || !polygon_contains_projected(p, ray.at(t))) return;
  const LocalHit h{t, -1, 0, 0, 0};
  out.add(h, h);
}

SurfaceInfo surface(const Polygon& p, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 q = ray.at(hit.t);
  q -= (dot(p.n, q) - p.offset) * p.n;
  si.p = q;
  si.p_error = gamma(6) * (abs(q) + abs(p.vertices[0]));
  si.n = p.n;
  si.shading_n = p.n;
  const Vec3 rel = q - p.vertices[0];
  si.u = dot(rel, p.eu);
  si.v = dot(rel, p.ev);
  return si;
}

}  // namespace raycast
