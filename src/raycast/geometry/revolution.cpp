#include "geometry/revolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/angles.h"
#include "geometry/crossing_list.h"
#include "math/polynomial_solver.h"

namespace raycast {

namespace {

// Below this |z1| / |d| the ray counts as horizontal: the eliminated form's roots in s come in
// pairs closer than its rounding can separate (their separation scales with z1).
constexpr double kHorizontal = 1e-5;
constexpr int kPolishSteps = 4;
// A polished s may leave [0, 1] by rounding; beyond this it belongs to the neighbour segment.
constexpr double kSegmentSlack = 1e-9;
// Crossings per ray: segments * 2 * 3 (bspline) + caps; more are dropped.
constexpr int kMaxCrossings = 256;

Polynomial linear_poly(double a, double b) {  // a + b s
  Polynomial p;
  p.degree = 1;
  p.c[0] = a;
  p.c[1] = b;
  return p;
}

// Newton on (s, t) for z(s) = z0 + z1 t and r(s)^2 = B t^2 + 2 E t + F.
void polish(const Revolution::Segment& g, double z0, double z1, double B, double E, double F,
            double& s, double& t) {
  const Polynomial dr = derivative(g.r), dz = derivative(g.z);
  for (int k = 0; k < kPolishSteps; ++k) {
    const double r = evaluate(g.r, s), z = evaluate(g.z, s);
    const double g1 = z - z0 - z1 * t;
    const double g2 = r * r - (B * t * t + 2 * E * t + F);
    const double a11 = evaluate(dz, s), a12 = -z1;
    const double a21 = 2 * r * evaluate(dr, s), a22 = -(2 * B * t + 2 * E);
    const double det = a11 * a22 - a12 * a21;
    if (!(std::abs(det) > 0) || !std::isfinite(det)) return;
    const double ds = (g1 * a22 - a12 * g2) / det, dt = (a11 * g2 - a21 * g1) / det;
    if (!std::isfinite(ds) || !std::isfinite(dt) || std::abs(ds) > 0.1) return;
    s -= ds;
    t -= dt;
    if (std::abs(ds) <= 1e-16 && std::abs(dt) <= 1e-16 * (1 + std::abs(t))) return;
  }
}

// Whether the line z = z0 + z1 t, r^2 = B t^2 + 2 E t + F stays out of the segment's bounding
// ring (z_lo <= z <= z_hi, r <= r_hi: the control points' hull holds the curve), so that it
// cannot cross the segment. Widened by a relative margin far above the polished roots' rounding;
// for a horizontal line the test is the one the horizontal branch below makes, at height z0.
bool misses_segment(const Revolution::Segment& g, double z0, double z1, bool horizontal, double B,
                    double E, double F) {
  const double margin = 1e-9 * (1 + std::max(std::abs(g.z_lo), std::abs(g.z_hi)) + g.r_hi);
  const double lo = g.z_lo - margin, hi = g.z_hi + margin;
  const double r2 = (g.r_hi + margin) * (g.r_hi + margin);
  if (horizontal) return z0 < lo || z0 > hi || (B > 0 && F - E * (E / B) > r2);
  double ta = (lo - z0) / z1, tb = (hi - z0) / z1;
  if (ta > tb) std::swap(ta, tb);
  // The least r^2 over the slab's stretch of the line: at the vertex, or the nearer end.
  const double t = B > 0 ? std::clamp(-E / B, ta, tb) : ta;
  return B * t * t + 2 * E * t + F > r2;
}

// Every crossing of the line with the revolved segments and caps, unsorted.
int crossings(const Revolution& sh, const Ray& ray, CurveCrossing* out) {
  int n = 0;
  const Vec3& o = ray.o;
  const Vec3& d = ray.d;
  const double B = d.x * d.x + d.y * d.y, E = o.x * d.x + o.y * d.y, F = o.x * o.x + o.y * o.y;
  const double z0 = o.z, z1 = d.z;
  const bool horizontal = std::abs(z1) <= kHorizontal * length(d);
  for (std::size_t i = 0; i < sh.segments.size(); ++i) {
    const Revolution::Segment& g = sh.segments[i];
    if (misses_segment(g, z0, z1, horizontal, B, E, F)) continue;
    Polynomial w = g.z;
    w.c[0] -= z0;  // w(s) = z(s) - z0
    double roots[2 * 3];
    if (!horizontal) {
      // E(s) = B w^2 + 2 E z1 w + z1^2 (F - r^2): the seed's a r^2 + b z^2 + c z + d with the
      // curve substituted, written about z0 so its coefficients stay small.
      Polynomial e = multiply(w, w);
      for (int k = 0; k <= e.degree; ++k) e.c[k] *= B;
      for (int k = 0; k <= w.degree; ++k) e.c[k] += 2 * E * z1 * w.c[k];
      const Polynomial r2 = multiply(g.r, g.r);
      if (r2.degree > e.degree) e.degree = r2.degree;
      for (int k = 0; k <= r2.degree; ++k) e.c[k] -= z1 * z1 * r2.c[k];
      e.c[0] += z1 * z1 * F;
      const int m = find_real_roots(e, 0, 1, roots);
      for (int k = 0; k < m && n < kMaxCrossings; ++k) {
        double s = roots[k], t = evaluate(w, s) / z1;
        polish(g, z0, z1, B, E, F, s, t);
        if (s < -kSegmentSlack || s > 1 + kSegmentSlack) continue;
        out[n++] = {t, static_cast<int>(i), std::clamp(s, 0.0, 1.0)};
      }
    } else {
      if (B == 0) continue;
      const int m = find_real_roots(w, 0, 1, roots);
      for (int k = 0; k < m; ++k) {
        const double r = evaluate(g.r, roots[k]);
        // B t^2 + 2 E t + F - r^2 = 0, cancellation-free.
        const double disc = E * E - B * (F - r * r);
        if (disc < 0) continue;
        const double q = -(E + std::copysign(std::sqrt(disc), E));
        const double ts[2] = {q / B, q != 0 ? (F - r * r) / q : 0.0};
        for (double t : ts) {
          double s = roots[k];
          polish(g, z0, z1, B, E, F, s, t);
          if (s < -kSegmentSlack || s > 1 + kSegmentSlack || n >= kMaxCrossings) continue;
          out[n++] = {t, static_cast<int>(i), std::clamp(s, 0.0, 1.0)};
        }
      }
    }
  }
  for (std::size_t c = 0; c < sh.caps.size() && n < kMaxCrossings; ++c) {
    if (z1 == 0) continue;
    const double t = (sh.caps[c].z - z0) / z1;
    const double x = o.x + t * d.x, y = o.y + t * d.y;
    if (x * x + y * y <= sh.caps[c].radius * sh.caps[c].radius)
      out[n++] = {t, static_cast<int>(sh.segments.size() + c), 0};
  }
  return n;
}

int sorted_crossings(const Revolution& s, const Ray& ray, CurveCrossing* c) {
  double t0, t1;
  if (!slab_interval(s.box, ray.o, reciprocal(ray.d), t0, t1)) return 0;
  const int n = crossings(s, ray, c);
  std::sort(c, c + n, [](const CurveCrossing& a, const CurveCrossing& b) { return a.t < b.t; });
  return n;
}

// CurveCrossing number of the profile loop (profile + caps + axis) by a ray from (rho, z) towards
// +r.
bool inside_profile(const Revolution& s, double rho, double z) {
  int count = 0;
  for (const Revolution::Segment& g : s.segments) {
    if (z < g.z_lo || z > g.z_hi || rho > g.r_hi) continue;
    Polynomial w = g.z;
    w.c[0] -= z;
    double roots[3];
    const int m = find_real_roots(w, 0, 1, roots);
    for (int k = 0; k < m; ++k) {
      // Half-open at the segment's end so a joint counts once.
      if (roots[k] >= 1) continue;
      if (evaluate(g.r, roots[k]) > rho) ++count;
    }
  }
  return count % 2 == 1;
}

}  // namespace

Revolution make_revolution(const std::vector<std::array<double, 2>>& profile, ProfileCurve curve,
                           bool capped) {
  const std::size_t need = curve == ProfileCurve::kLinear ? 2 : 4;
  if (profile.size() < need)
    throw std::invalid_argument(std::string("profile needs at least ") + std::to_string(need) +
                                " points");
  for (const auto& p : profile) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
      throw std::invalid_argument("profile points must be finite");
    if (p[0] < 0) throw std::invalid_argument("profile radii must be >= 0");
  }
  Revolution s;
  if (curve == ProfileCurve::kLinear) {
    for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
      const auto& a = profile[i];
      const auto& b = profile[i + 1];
      if (a == b) continue;
      Revolution::Segment g;
      g.r = linear_poly(a[0], b[0] - a[0]);
      g.z = linear_poly(a[1], b[1] - a[1]);
      s.segments.push_back(g);
    }
  } else {
    for (std::size_t i = 0; i + 3 < profile.size(); ++i) {
      Revolution::Segment g;
      for (int axis = 0; axis < 2; ++axis) {
        const double p0 = profile[i][axis], p1 = profile[i + 1][axis], p2 = profile[i + 2][axis],
                     p3 = profile[i + 3][axis];
        Polynomial& q = axis == 0 ? g.r : g.z;
        q.degree = 3;
        q.c = {};
        q.c[0] = (p0 + 4 * p1 + p2) / 6;
        q.c[1] = (-3 * p0 + 3 * p2) / 6;
        q.c[2] = (3 * p0 - 6 * p1 + 3 * p2) / 6;
        q.c[3] = (-p0 + 3 * p1 - 3 * p2 + p3) / 6;
      }
      s.segments.push_back(g);
    }
  }
  if (s.segments.empty()) throw std::invalid_argument("profile has no extent");
  // Segment bounds from the control points (convex hull), and the shape's box.
  const std::size_t per = curve == ProfileCurve::kLinear ? 2 : 4;
  double r_max = 0, z_lo = kInfinity, z_hi = -kInfinity;
  for (std::size_t i = 0, k = 0; k < s.segments.size(); ++i) {
    if (curve == ProfileCurve::kLinear && profile[i] == profile[i + 1]) continue;
    Revolution::Segment& g = s.segments[k++];
    g.z_lo = kInfinity;
    g.z_hi = -kInfinity;
    for (std::size_t j = i; j < i + per; ++j) {
      g.z_lo = std::min(g.z_lo, profile[j][1]);
      g.z_hi = std::max(g.z_hi, profile[j][1]);
      g.r_hi = std::max(g.r_hi, profile[j][0]);
    }
    r_max = std::max(r_max, g.r_hi);
    z_lo = std::min(z_lo, g.z_lo);
    z_hi = std::max(z_hi, g.z_hi);
  }
  if (!(r_max > 0)) throw std::invalid_argument("profile lies on the axis");
  s.box = {{-r_max, -r_max, z_lo}, {r_max, r_max, z_hi}};

  // Ends, caps and closedness.
  const Revolution::Segment& first = s.segments.front();
  const Revolution::Segment& last = s.segments.back();
  const double r_start = evaluate(first.r, 0.0), z_start = evaluate(first.z, 0.0);
  const double r_end = evaluate(last.r, 1.0), z_end = evaluate(last.z, 1.0);
  s.closed = capped || (r_start == 0 && r_end == 0);
  // Orientation of the loop: the signed area, oint r dz (the caps and the axis add nothing).
  double area = 0;
  for (const Revolution::Segment& g : s.segments) {
    const Polynomial integrand = multiply(g.r, derivative(g.z));
    for (int k = 0; k <= integrand.degree; ++k) area += integrand.c[k] / (k + 1);
  }
  s.orientation = area >= 0 ? 1 : -1;
  if (capped) {
    // The loop runs start -> end -> (0, z_end) -> (0, z_start) -> start.
    // Leaving the end towards the axis (dr < 0) the outward side is orientation * (0, -dr).
    if (r_end > 0) s.caps.push_back({z_end, r_end, s.orientation, 1});
    if (r_start > 0) s.caps.push_back({z_start, r_start, -s.orientation, 0});
  }
  return s;
}

Aabb bounds(const Revolution& s) { return s.box; }

bool intersect(const Revolution& s, const Ray& ray, LocalHit& hit) {
  CurveCrossing c[kMaxCrossings];
  return first_crossing_in_range(c, sorted_crossings(s, ray, c), ray, hit);
}

void spans(const Revolution& s, const Ray& ray, SpanList& out) {
  CurveCrossing c[kMaxCrossings];
  const int n = sorted_crossings(s, ray, c);
  spans_from_crossings(
      c, n, ray, s.closed, [&](const Vec3& p) { return contains(s, p); }, out);
}

SurfaceInfo surface(const Revolution& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  const double phi_raw = std::atan2(p.y, p.x);
  const double phi = phi_raw < 0 ? phi_raw + kTwoPi : phi_raw;
  si.u = phi / kTwoPi;
  const int n_segments = static_cast<int>(s.segments.size());
  if (hit.part >= n_segments) {
    const Revolution::Cap& cap = s.caps[hit.part - n_segments];
    p.z = cap.z;
    si.n = {0, 0, cap.normal_z};
    si.v = cap.v;
  } else {
    const Revolution::Segment& g = s.segments[hit.part];
    const double sp = hit.a;
    const double dr = evaluate(derivative(g.r), sp), dz = evaluate(derivative(g.z), sp);
    // The loop's outward normal in (r, z): (dz, -dr) when counter-clockwise.
    double nr = s.orientation * dz, nz = -s.orientation * dr;
    const double len = std::hypot(nr, nz);
    const Vec3 radial{std::cos(phi), std::sin(phi), 0};
    si.n = len > 0 ? Vec3{nr / len * radial.x, nr / len * radial.y, nz / len} : -normalize(ray.d);
    si.v = (hit.part + sp) / static_cast<double>(s.segments.size());
  }
  si.shading_n = si.n;
  si.p = p;
  const double size = std::max({std::abs(s.box.lo.z), std::abs(s.box.hi.z), s.box.hi.x});
  si.p_error = gamma(16) * (abs(p) + Vec3{size, size, size});
  if (hit.part < n_segments) {
    // The polished (s, t) leave o + t d off the surface by the root's own error, which grows at
    // grazing angles: add twice the distance from p to the profile point in the (r, z) plane.
    const Revolution::Segment& g = s.segments[hit.part];
    const double dist =
        std::hypot(std::hypot(p.x, p.y) - evaluate(g.r, hit.a), p.z - evaluate(g.z, hit.a));
    si.p_error += 2 * dist * abs(si.n);
  }
  return si;
}

bool contains(const Revolution& s, const Vec3& p) {
  if (!s.closed || !s.box.contains(p)) return false;
  return inside_profile(s, std::sqrt(p.x * p.x + p.y * p.y), p.z);
}

}  // namespace raycast
