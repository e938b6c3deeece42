#include "geometry/prism.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/crossing_list.h"
#include "math/polynomial_solver.h"
#include "math/quadratic.h"

namespace raycast {

namespace {

// Crossings kept per ray (each piece gives at most 3, the caps 2); more are dropped.
constexpr int kMaxCrossings = 512;

// The power-basis polynomial of one coordinate of a Bezier piece.
Polynomial bezier_polynomial(const ContourPiece& c, int axis) {
  const auto q = [&](int i) {
    return c.p[static_cast<std::size_t>(i)][static_cast<std::size_t>(axis)];
  };
  Polynomial p;
  p.degree = c.degree;
  p.c[0] = q(0);
  if (c.degree == 1) {
    p.c[1] = q(1) - q(0);
  } else if (c.degree == 2) {
    p.c[1] = 2 * (q(1) - q(0));
    p.c[2] = q(0) - 2 * q(1) + q(2);
  } else {
    p.c[1] = 3 * (q(1) - q(0));
    p.c[2] = 3 * (q(0) - 2 * q(1) + q(2));
    p.c[3] = -q(0) + 3 * (q(1) - q(2)) + q(3);
  }
  return p;
}

// Whether x lies left of the crossing of a part of a piece, from (xa, ya) at sa to (xb, yb) at
// sb, with the horizontal line through y. The caller has checked that ya and yb lie on opposite
// sides of y. The part is monotone in x and in y, so the crossing's x lies between the x of the
// bracket's ends: bisect only while x lies inside that range (for most points, not at all).
bool left_of_crossing(const Prism::Piece& g, double sa, double xa, double ya, double sb, double xb,
                      double yb, double x, double y) {
  if (g.x.degree == 1) {
    // Order the ends so a piece shared by two solids gives the same bits both ways.
    if (ya > yb) std::swap(xa, xb), std::swap(ya, yb);
    return x < xa + (y - ya) * (xb - xa) / (yb - ya);
  }
  const bool rising = yb > ya;
  for (int k = 0; k < 60 && sb - sa > 1e-15; ++k) {
    if (x < std::min(xa, xb)) return true;
    if (x >= std::max(xa, xb)) return false;
    const double m = 0.5 * (sa + sb);
    const double xm = evaluate(g.x, m);
    if ((evaluate(g.y, m) > y) == rising)
      sb = m, xb = xm;
    else
      sa = m, xa = xm;
  }
  return x < evaluate(g.x, 0.5 * (sa + sb));
}

// Whether the horizontal ray from (x, y) towards +x crosses the piece an odd number of times.
// A part of the piece counts when its ends lie on opposite sides of y with "above" meaning > y,
// the rule of the crossing-number test, so a joint on the line counts once.
bool crosses_odd(const Prism::Piece& g, double x, double y) {
  // A piece wholly right of x (its control box is) is crossed once per change of side between
  // its monotone parts' ends; those changes telescope to its two ends.
  if (x < g.x_lo) return (g.start[1] > y) != (g.end[1] > y);
  double cut[6] = {0, 0, 0, 0, 0, 0};
  int n = 1;
  for (int k = 0; k < g.turn_count; ++k) cut[n++] = g.turns[static_cast<std::size_t>(k)];
  cut[n] = 1;
  bool odd = false;
  for (int i = 0; i < n; ++i) {
    const double sa = cut[i], sb = cut[i + 1];
    const double ya = i == 0 ? g.start[1] : evaluate(g.y, sa);
    const double yb = i + 1 == n ? g.end[1] : evaluate(g.y, sb);
    if ((ya > y) == (yb > y)) continue;
    const double xa = i == 0 ? g.start[0] : evaluate(g.x, sa);
    const double xb = i + 1 == n ? g.end[0] : evaluate(g.x, sb);
    if (left_of_crossing(g, sa, xa, ya, sb, xb, yb, x, y)) odd = !odd;
  }
  return odd;
}

// The roots of e on [0, 1]: closed forms below degree 3 (the common straight and quadratic
// pieces), the isolating solver for cubics. A tangent root counts twice, as a tangent crossing.
int piece_roots(const Polynomial& e, double* roots) {
  if (e.degree == 3 && e.c[3] != 0) return find_real_roots(e, 0, 1, roots);
  double r[2] = {0, 0};
  const int m = solve_quadratic(e.degree >= 2 ? e.c[2] : 0, e.c[1], e.c[0], r[0], r[1]);
  int n = 0;
  for (int k = 0; k < m; ++k)
    if (r[k] >= 0 && r[k] <= 1) roots[n++] = r[k];
  return n;
}

// The side crossings of one piece: the roots of a x(s) + b y(s) + c on [0, 1), where the plane
// a X + b Y + c W = 0 holds the ray and the rulings (W = 1: parallel to z; conic: W = Z scaled).
int piece_crossings(const Prism& sh, int index, const Ray& ray, double a, double b, double c,
                    CurveCrossing* out) {
  const Prism::Piece& g = sh.pieces[static_cast<std::size_t>(index)];
  // The plane misses the piece when the corners of its box all lie on one side.
  const double f[4] = {a * g.x_lo + b * g.y_lo + c, a * g.x_hi + b * g.y_lo + c,
                       a * g.x_lo + b * g.y_hi + c, a * g.x_hi + b * g.y_hi + c};
  if ((f[0] > 0 && f[1] > 0 && f[2] > 0 && f[3] > 0) ||
      (f[0] < 0 && f[1] < 0 && f[2] < 0 && f[3] < 0))
    return 0;
  Polynomial e;
  e.degree = std::max(g.x.degree, g.y.degree);
  for (int k = 0; k <= e.degree; ++k) e.c[k] = a * g.x.c[k] + b * g.y.c[k];
  e.c[0] += c;
  double roots[3];
  const int m = piece_roots(e, roots);
  int n = 0;
  const Vec3& o = ray.o;
  const Vec3& d = ray.d;
  for (int k = 0; k < m; ++k) {
    const double s = roots[k];
    if (s >= 1) continue;  // the joint belongs to the next piece
    const double px = evaluate(g.x, s), py = evaluate(g.y, s);
    double t;
    if (!sh.conic) {
      t = ((px - o.x) * d.x + (py - o.y) * d.y) / (d.x * d.x + d.y * d.y);
    } else {
      // o + t d = h (px, py, 1): least squares on (o x P) + t (d x P) = 0.
      const Vec3 P{px, py, 1};
      const Vec3 oP = cross(o, P), dP = cross(d, P);
      t = -dot(oP, dP) / dot(dP, dP);
    }
    const double z = o.z + t * d.z;
    if (!std::isfinite(t) || z < sh.z0 || z > sh.z1) continue;
    out[n++] = {t, index, s};
  }
  return n;
}

// Every crossing of the line with the sides and caps, unsorted.
int crossings(const Prism& sh, const Ray& ray, CurveCrossing* out) {
  int n = 0;
  const Vec3& o = ray.o;
  const Vec3& d = ray.d;
  double a, b, c;
  if (!sh.conic) {
    a = d.y, b = -d.x, c = d.x * o.y - d.y * o.x;
  } else {
    const Vec3 N = cross(o, d);
    a = N.x, b = N.y, c = N.z;
  }
  const int pieces = static_cast<int>(sh.pieces.size());
  if (a != 0 || b != 0) {
    for (int i = 0; i < pieces && n + 3 <= kMaxCrossings; ++i)
      n += piece_crossings(sh, i, ray, a, b, c, out + n);
  }
  if (!sh.open && d.z != 0) {
    for (int k = 0; k < 2; ++k) {
      const double z = k == 0 ? sh.z0 : sh.z1;
      if (sh.conic && z == 0) continue;  // the apex: no cap
      const double t = (z - o.z) / d.z;
      const double scale = sh.conic ? 1 / z : 1;
      if (inside_contours(sh, (o.x + t * d.x) * scale, (o.y + t * d.y) * scale))
        out[n++] = {t, pieces + k, 0};
    }
  }
  return n;
}

int sorted_crossings(const Prism& s, const Ray& ray, CurveCrossing* c) {
  double t0, t1;
  if (!slab_interval(s.box, ray.o, reciprocal(ray.d), t0, t1)) return 0;
  const int n = crossings(s, ray, c);
  std::sort(c, c + n, [](const CurveCrossing& a, const CurveCrossing& b) { return a.t < b.t; });
  return n;
}

// The signed area of a closed contour, 1/2 oint (x dy - y dx), exact for polynomial pieces.
double signed_area(const std::vector<Prism::Piece>& pieces, std::size_t from, std::size_t to) {
  double area = 0;
  for (std::size_t i = from; i < to; ++i) {
    const Polynomial a = multiply(pieces[i].x, derivative(pieces[i].y));
    const Polynomial b = multiply(pieces[i].y, derivative(pieces[i].x));
    for (int k = 0; k <= std::max(a.degree, b.degree); ++k)
      area += 0.5 * ((k <= a.degree ? a.c[k] : 0) - (k <= b.degree ? b.c[k] : 0)) / (k + 1);
  }
  return area;
}

Prism::Piece make_piece(const ContourPiece& c) {
  Prism::Piece g;
  g.x = bezier_polynomial(c, 0);
  g.y = bezier_polynomial(c, 1);
  g.start = c.p[0];
  g.end = c.p[static_cast<std::size_t>(c.degree)];
  g.x_lo = g.y_lo = kInfinity;
  g.x_hi = g.y_hi = -kInfinity;
  for (int k = 0; k <= c.degree; ++k) {
    const auto& q = c.p[static_cast<std::size_t>(k)];
    g.x_lo = std::min(g.x_lo, q[0]), g.x_hi = std::max(g.x_hi, q[0]);
    g.y_lo = std::min(g.y_lo, q[1]), g.y_hi = std::max(g.y_hi, q[1]);
  }
  // Split where x or y turns, so that each part is monotone in both: those turns in (0, 1),
  // ascending, each once (2 marks an unused entry).
  std::array<double, 4> turns{2, 2, 2, 2};
  std::size_t found = 0;
  for (const Polynomial* q : {&g.x, &g.y}) {
    if (q->degree < 2) continue;
    const Polynomial dq = derivative(*q);
    double r[2] = {0, 0};
    const int m = solve_quadratic(dq.degree >= 2 ? dq.c[2] : 0, dq.c[1], dq.c[0], r[0], r[1]);
    for (int k = 0; k < m; ++k)
      if (r[k] > 0 && r[k] < 1) turns[found++] = r[k];
  }
  std::sort(turns.begin(), turns.end());
  for (const double v : turns)
    if (v < 1 && (g.turn_count == 0 || v != g.turns[std::size_t(g.turn_count - 1)]))
      g.turns[std::size_t(g.turn_count++)] = v;
  return g;
}

void check_contour(const Contour& c, std::size_t index) {
  const std::string name = "contour " + std::to_string(index);
  if (c.empty()) throw std::invalid_argument(name + " is empty");
  for (std::size_t i = 0; i < c.size(); ++i) {
    const ContourPiece& p = c[i];
    if (p.degree < 1 || p.degree > 3)
      throw std::invalid_argument(name + ": pieces have degree 1 to 3");
    for (int k = 0; k <= p.degree; ++k)
      for (double v : p.p[static_cast<std::size_t>(k)])
        if (!std::isfinite(v)) throw std::invalid_argument(name + ": points must be finite");
    const ContourPiece& next = c[(i + 1) % c.size()];
    if (p.p[static_cast<std::size_t>(p.degree)] != next.p[0])
      throw std::invalid_argument(name + " is not closed: piece " + std::to_string(i) +
                                  " does not end where the next piece starts");
  }
}

}  // namespace

bool inside_contours(const Prism& s, double x, double y) {
  if (!(x >= s.x_lo && x <= s.x_hi && y >= s.y_lo && y <= s.y_hi)) return false;
  bool inside = false;
  for (const Prism::Piece& g : s.pieces) {
    if (y < g.y_lo || y > g.y_hi || x > g.x_hi) continue;
    if (crosses_odd(g, x, y)) inside = !inside;
  }
  return inside;
}

Prism make_prism(const std::vector<Contour>& contours, double z0, double z1, bool conic,
                 bool open) {
  if (contours.empty()) throw std::invalid_argument("needs at least one contour");
  if (!std::isfinite(z0) || !std::isfinite(z1) || z0 == z1)
    throw std::invalid_argument("the two heights must be finite and differ");
  if (z0 > z1) std::swap(z0, z1);
  if (conic && z0 < 0 && z1 > 0)
    throw std::invalid_argument("a conic sweep's heights must not lie on both sides of 0");
  Prism s;
  s.z0 = z0;
  s.z1 = z1;
  s.conic = conic;
  s.open = open;
  s.x_lo = s.y_lo = kInfinity;
  s.x_hi = s.y_hi = -kInfinity;
  // Each contour's pieces, those of contours without area left out (they bound nothing).
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  std::vector<double> areas;
  for (std::size_t ci = 0; ci < contours.size(); ++ci) {
    check_contour(contours[ci], ci);
    std::vector<Prism::Piece> pieces;
    for (const ContourPiece& c : contours[ci]) pieces.push_back(make_piece(c));
    const double area = signed_area(pieces, 0, pieces.size());
    if (area == 0) continue;
    ranges.emplace_back(s.pieces.size(), s.pieces.size() + pieces.size());
    areas.push_back(area);
    for (const Prism::Piece& g : pieces) {
      s.x_lo = std::min(s.x_lo, g.x_lo), s.x_hi = std::max(s.x_hi, g.x_hi);
      s.y_lo = std::min(s.y_lo, g.y_lo), s.y_hi = std::max(s.y_hi, g.y_hi);
      s.pieces.push_back(g);
    }
  }
  if (s.pieces.empty()) throw std::invalid_argument("the contours have no area");
  // Which side of each contour is the solid's: left of a counter-clockwise contour is its
  // inside, which is the solid's when an even number of the other contours enclose it.
  for (std::size_t ci = 0; ci < ranges.size(); ++ci) {
    const auto [from, to] = ranges[ci];
    // A point of the contour: the middle of its first piece (a start may be a shared corner).
    const double mx = evaluate(s.pieces[from].x, 0.5), my = evaluate(s.pieces[from].y, 0.5);
    bool enclosed = false;
    for (std::size_t i = 0; i < s.pieces.size(); ++i)
      if ((i < from || i >= to) && crosses_odd(s.pieces[i], mx, my)) enclosed = !enclosed;
    const double outward = (areas[ci] > 0 ? 1 : -1) * (enclosed ? -1 : 1);
    for (std::size_t i = from; i < to; ++i) s.pieces[i].outward = outward;
  }
  if (!conic) {
    s.box = {{s.x_lo, s.y_lo, z0}, {s.x_hi, s.y_hi, z1}};
  } else {
    for (double z : {z0, z1})
      for (double x : {s.x_lo, s.x_hi})
        for (double y : {s.y_lo, s.y_hi}) s.box.grow(Vec3{x * z, y * z, z});
  }
  return s;
}

Aabb bounds(const Prism& s) { return s.box; }

bool intersect(const Prism& s, const Ray& ray, LocalHit& hit) {
  CurveCrossing c[kMaxCrossings];
  return first_crossing_in_range(c, sorted_crossings(s, ray, c), ray, hit);
}

void spans(const Prism& s, const Ray& ray, SpanList& out) {
  CurveCrossing c[kMaxCrossings];
  const int n = sorted_crossings(s, ray, c);
  spans_from_crossings(
      c, n, ray, !s.open, [&](const Vec3& p) { return contains(s, p); }, out);
}

SurfaceInfo surface(const Prism& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  const int pieces = static_cast<int>(s.pieces.size());
  const double size = max_component(max(abs(s.box.lo), abs(s.box.hi)));
  si.p_error = gamma(16) * (abs(p) + Vec3{size, size, size});
  if (hit.part >= pieces) {
    const bool top = hit.part > pieces;
    p.z = top ? s.z1 : s.z0;
    si.n = {0, 0, top ? 1.0 : -1.0};
    si.u = p.x;
    si.v = p.y;
  } else {
    const Prism::Piece& g = s.pieces[static_cast<std::size_t>(hit.part)];
    const double sp = hit.a;
    const double x = evaluate(g.x, sp), y = evaluate(g.y, sp);
    const double dx = evaluate(derivative(g.x), sp), dy = evaluate(derivative(g.y), sp);
    Vec3 n{dy, -dx, 0};
    double h = 1;
    if (s.conic) {
      // S(h, s) = h (x, y, 1): the normal (x', y', 0) x (x, y, 1), times h's sign.
      h = p.z;
      n.z = dx * y - dy * x;
      if (h < 0) n = -n;
    }
    n *= g.outward;
    si.n = length(n) > 0 ? normalize(n) : -normalize(ray.d);
    si.u = (hit.part + sp) / pieces;
    si.v = (p.z - s.z0) / (s.z1 - s.z0);
    // The root's own error moves o + t d off the side; add twice the distance to the curve
    // point at the hit's height.
    const double dist = std::hypot(p.x - h * x, p.y - h * y);
    si.p_error += 2 * dist * abs(si.n);
  }
  si.shading_n = si.n;
  si.p = p;
  return si;
}

bool contains(const Prism& s, const Vec3& p) {
  if (s.open || !(p.z >= s.z0 && p.z <= s.z1)) return false;
  if (!s.conic) return inside_contours(s, p.x, p.y);
  if (p.z == 0) return false;
  return inside_contours(s, p.x / p.z, p.y / p.z);
}

}  // namespace raycast
