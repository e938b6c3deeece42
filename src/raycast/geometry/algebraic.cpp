#include "geometry/algebraic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/clipped_solid.h"
#include "math/polynomial_solver.h"

namespace raycast {

namespace {

// The rounding of the substituted coefficients exceeds Horner's own error by a factor growing
// with the degree; this widens the root's error estimate accordingly (per degree).
constexpr double kCoefficientErrorFactor = 4;

// The line's polynomial about the chord's middle and its roots on the chord.
struct LineRoots {
  BoxChord chord;
  double mid = 0;
  Polynomial p;
  int n = 0;
  double t[kMaxPolynomialDegree];
  double err[kMaxPolynomialDegree];
};

bool line_roots(const Algebraic& s, const Ray& ray, LineRoots& r) {
  if (!box_chord(s.box, ray, r.chord)) return false;
  r.mid = 0.5 * (r.chord.t0 + r.chord.t1);
  r.p = restrict_to_line(s.f, ray.o + r.mid * ray.d, ray.d);
  double u[kMaxPolynomialDegree];
  const int n = find_real_roots(r.p, r.chord.t0 - r.mid, r.chord.t1 - r.mid, u);
  r.n = 0;
  for (int i = 0; i < n; ++i) {
    const double t = r.mid + u[i];
    if (r.n > 0 && t <= r.t[r.n - 1]) continue;
    double dp, e;
    evaluate(r.p, u[i], dp, e);
    r.t[r.n] = std::clamp(t, r.chord.t0, r.chord.t1);
    const double scale = kCoefficientErrorFactor * (r.p.degree + 1);
    r.err[r.n] = dp != 0 ? std::min(scale * e / std::abs(dp), 1e-3 * (r.chord.t1 - r.chord.t0)) : 0;
    ++r.n;
  }
  return true;
}

void line_spans(const Algebraic& s, const LineRoots& r, SpanList& out) {
  chord_spans(
      r.chord, r.t, r.err, r.n, !s.open, [&](double t) { return evaluate(r.p, t - r.mid) < 0; },
      out);
}

}  // namespace

void check_bounds_box(const Aabb& box) {
  if (!is_finite(box.lo) || !is_finite(box.hi))
    throw std::invalid_argument("bounds must be finite");
  if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
    throw std::invalid_argument("bounds.min must be < bounds.max on every axis");
}

Algebraic make_algebraic(std::string_view equation, const Aabb& box, bool open) {
  check_bounds_box(box);
  Algebraic s;
  s.f = expand_polynomial(equation);
  if (s.f.degree == 0) throw ExpressionError(0, "the equation is a constant: it has no surface");
  s.box = box;
  s.open = open;
  return s;
}

Aabb bounds(const Algebraic& s) { return s.box; }

bool intersect(const Algebraic& s, const Ray& ray, LocalHit& hit) {
  LineRoots r;
  if (!line_roots(s, ray, r)) return false;
  if (r.chord.t1 < ray.tmin || r.chord.t0 > ray.tmax) return false;
  SpanList l;
  line_spans(s, r, l);
  return first_crossing(l, ray, hit);
}

bool occluded(const Algebraic& s, const Ray& ray) {
  LocalHit h;
  return intersect(s, ray, h);
}

void spans(const Algebraic& s, const Ray& ray, SpanList& out) {
  LineRoots r;
  if (!line_roots(s, ray, r)) return;
  line_spans(s, r, out);
}

SurfaceInfo surface(const Algebraic& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  if (hit.part >= kFacePart) {
    const int face = hit.part - kFacePart;
    p[face / 2] = face % 2 ? s.box.hi[face / 2] : s.box.lo[face / 2];
    si.n = box_face_normal(face);
    si.p_error = gamma(4) * abs(p);
  } else {
    const Vec3 g = gradient(s.f, p);
    const double gl = length(g);
    // A singular point of the surface (zero gradient) has no normal: face the ray.
    si.n = gl > 0 && std::isfinite(gl) ? g / gl : -normalize(ray.d);
    si.p_error = gamma(16) * abs(p) + hit.a * abs(ray.d);
  }
  si.shading_n = si.n;
  si.p = p;
  return si;
}

bool contains(const Algebraic& s, const Vec3& p) {
  return !s.open && s.box.contains(p) && evaluate(s.f, p) < 0;
}

}  // namespace raycast
