#include "geometry/algebraic.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <vector>

#include "geometry/clipped_solid.h"
#include "math/bernstein.h"
#include "math/float_error.h"
#include "math/interval.h"
#include "math/polynomial_solver.h"

namespace raycast {

namespace {

// The rounding of the substituted coefficients exceeds Horner's own error by a factor growing
// with the degree; this widens the root's error estimate accordingly (per degree).
constexpr double kCoefficientErrorFactor = 4;
// Extended-precision polish of a hit: bracket widenings (x4 each) and bisection steps (64 reach
// the last bit of an x87 long double from a bracket of the root's error estimate).
constexpr int kMaxBracketWidenings = 12;
constexpr int kExtendedBisections = 64;
// A root's error estimate is capped at this fraction of the chord's length.
constexpr double kMaxRootError = 1e-3;

// The line's polynomial about the chord's middle and its roots on the chord.
struct LineRoots {
  BoxChord chord;
  double mid = 0;
  Polynomial p;
  int n = 0;
  double t[kMaxPolynomialDegree];
  double err[kMaxPolynomialDegree];
};

// The chord and the line's polynomial about its middle (the roots not yet found).
bool line_polynomial(const Algebraic& s, const Ray& ray, LineRoots& r) {
  if (!box_chord(s.box, ray, r.chord)) return false;
  r.mid = 0.5 * (r.chord.t0 + r.chord.t1);
  r.p = restrict_to_line(s.f, ray.o + r.mid * ray.d, ray.d);
  return true;
}

// The roots on the chord, after line_polynomial.
void solve_line(LineRoots& r) {
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
    r.err[r.n] =
        dp != 0 ? std::min(scale * e / std::abs(dp), kMaxRootError * (r.chord.t1 - r.chord.t0)) : 0;
    ++r.n;
  }
}

bool line_roots(const Algebraic& s, const Ray& ray, LineRoots& r) {
  if (!line_polynomial(s, ray, r)) return false;
  solve_line(r);
  return true;
}

// Whether the line's polynomial certainly changes sign within [lo, hi] (ray parameters inside the
// chord): its signs, beyond their rounding bounds, at the ends and the middle. A sign change is a
// root there, a crossing of the surface that the full solve would report.
bool certain_sign_change(const LineRoots& r, double lo, double hi) {
  int seen = 0;  // bit 0: a certain positive value, bit 1: a certain negative one
  for (const double t : {lo, 0.5 * (lo + hi), hi}) {
    double e;
    const double v = evaluate(r.p, t - r.mid, e);
    if (std::abs(v) > e) seen |= v < 0 ? 2 : 1;
  }
  return seen == 3;
}

// What a sweep of an interval by Bernstein forms of the line's polynomial settled.
enum class Sweep {
  kCrossing,   // a piece whose ends have certain opposite signs: a root inside, a crossing
  kNegative,   // certainly no root, the polynomial negative throughout
  kPositive,   // certainly no root, positive throughout
  kUnsettled,  // neither within the halving caps
};

// The sweep's halving caps: depth of a piece, halvings in all.
constexpr int kSweepMaxDepth = 8;
constexpr int kSweepMaxSplits = 16;

// Sweeps [a, b] (ray parameters, a < b) depth first from the left: a piece whose Bernstein
// coefficients have no possible sign change has the one sign of all of them; the first piece with
// one possible change and ends of certain opposite signs holds a root and ends the sweep;
// anything else is halved, up to the caps.
Sweep bernstein_sweep(const LineRoots& r, double a, double b, int max_depth) {
  const int n = r.p.degree;
  struct Piece {
    int depth;
    BernsteinForm f;
  };
  Piece stack[kSweepMaxDepth + 2];
  int top = 0, splits = 0, sign = 0;
  stack[0].depth = 0;
  // Widened as the solver does: covers [a, b] despite the rounding of a - mid and b - a.
  const double u = a - r.mid,
               w = (b - a) * (1 + 4 * kMachineEpsilon) + 4 * kMachineEpsilon * std::abs(u);
  stack[0].f = bernstein_form(r.p, u - 2 * kMachineEpsilon * std::abs(u), w);
  while (top >= 0) {
    Piece& piece = stack[top];
    const BernsteinForm& f = piece.f;
    const int changes = max_sign_changes(f);
    const double f0 = f.b[0], fn = f.b[n];
    if (changes == 0 && std::abs(f0) > f.e[0]) {
      const int s = f0 < 0 ? -1 : 1;
      if (sign != 0 && s != sign) return Sweep::kUnsettled;  // not reached: pieces share ends
      sign = s;
      --top;
      continue;
    }
    if (changes == 1 && std::abs(f0) > f.e[0] && std::abs(fn) > f.e[n] && (f0 < 0) != (fn < 0))
      return Sweep::kCrossing;
    if (piece.depth >= max_depth || ++splits > kSweepMaxSplits) return Sweep::kUnsettled;
    // The right half replaces the piece, the left one goes on top of it.
    Piece& left = stack[top + 1];
    bernstein_halves(f, left.f, piece.f);
    left.depth = ++piece.depth;
    ++top;
  }
  return sign < 0 ? Sweep::kNegative : Sweep::kPositive;
}

// occluded's answer without isolating the roots, where the sweeps settle it: 1 or 0, -1 when
// only the full solve can tell. intersect skips a curved root within its error estimate (at most
// kMaxRootError of the chord) of tmin, so a root there cannot be judged without it: the part of
// [tmin, tmax] within that cap of tmin must be certainly root-free; a certain crossing past it is
// a hit; with no root at all the solid's sign over the whole range decides (a face at either end
// of the chord inside the range, or nothing).
int occluded_by_sweeps(const Algebraic& s, const Ray& ray, const LineRoots& r) {
  const double a = std::max(r.chord.t0, ray.tmin), b = std::min(r.chord.t1, ray.tmax);
  if (!(a < b) || r.p.degree == 0 || !std::isfinite(r.mid)) return -1;
  for (int i = 0; i <= r.p.degree; ++i)
    if (!std::isfinite(r.p.c[i])) return -1;
  const double split = ray.tmin + kMaxRootError * (r.chord.t1 - r.chord.t0);
  Sweep near = Sweep::kUnsettled;
  if (a < split) {
    near = bernstein_sweep(r, a, std::min(b, split), 2);
    if (near != Sweep::kNegative && near != Sweep::kPositive) return -1;
  }
  Sweep far = near;
  if (split < b) {
    far = bernstein_sweep(r, std::max(a, split), b, kSweepMaxDepth);
    if (far == Sweep::kCrossing) return 1;
    if (far == Sweep::kUnsettled || (a < split && far != near)) return -1;
  }
  if (s.open || far == Sweep::kPositive) return 0;
  return r.chord.t0 >= ray.tmin || r.chord.t1 <= ray.tmax ? 1 : 0;
}

// Polishes a root of f(o + t d) in extended precision and returns the point. Where f's gradient
// nearly vanishes on the surface (the heart's f behaves like a cube of the distance along its
// equator z = 0) a double root is only good to about cbrt(eps), and the gradient at such a point
// points the wrong way; extended precision shrinks that band a thousandfold.
Vec3 polished_point(const Algebraic& s, const Ray& ray, const LocalHit& hit, long double p[3]) {
  auto f = [&](long double t) {
    return evaluate_extended(s.f, ray.o.x + t * ray.d.x, ray.o.y + t * ray.d.y,
                             ray.o.z + t * ray.d.z);
  };
  const long double t0 = hit.t;
  long double delta = std::max<long double>(hit.a, 1e-12L * (std::abs(t0) + 1));
  long double lo = t0 - delta, hi = t0 + delta;
  long double flo = f(lo), fhi = f(hi);
  for (int k = 0; k < kMaxBracketWidenings && (flo < 0) == (fhi < 0); ++k) {
    delta *= 4;
    lo = t0 - delta;
    hi = t0 + delta;
    flo = f(lo);
    fhi = f(hi);
  }
  long double t = t0;
  if ((flo < 0) != (fhi < 0)) {
    // Regula falsi with the Illinois correction (the end kept twice in a row has its value
    // halved), and a bisection whenever two such steps in a row have not halved the bracket:
    // superlinear on a simple root, never slower than bisection by more than a factor 3.
    int kept = 0;  // +1: lo kept by the last step, -1: hi kept
    int since_halved = 0;
    long double width_before = hi - lo;
    for (int k = 0; k < 3 * kExtendedBisections; ++k) {
      const long double mid = 0.5L * (lo + hi);
      if (mid <= lo || mid >= hi) break;  // lo and hi are adjacent: no step can shrink the bracket
      long double m = lo - flo * (hi - lo) / (fhi - flo);
      if (since_halved >= 2 || std::isnan(m)) {
        m = mid;
      } else if (m <= lo || m >= hi) {
        // The step lands on an end: that end is within rounding of the root. Probe the next
        // number inward: a sign change there closes the bracket at once, where bisection would
        // take ~log2(width / ulp) steps.
        m = m <= lo ? std::nextafter(lo, hi) : std::nextafter(hi, lo);
        // Where long double is no wider than double in fact (valgrind's x87 emulation), the
        // probe may round back onto the end: bisect instead.
        if (!(m > lo && m < hi)) m = mid;
      }
      const long double fm = f(m);
      if (fm == 0) {
        lo = hi = m;
        break;
      }
      if ((fm < 0) == (flo < 0)) {
        lo = m;
        flo = fm;
        if (kept == -1) fhi *= 0.5L;
        kept = -1;
      } else {
        hi = m;
        fhi = fm;
        if (kept == 1) flo *= 0.5L;
        kept = 1;
      }
      if (hi - lo <= 0.5L * width_before) {
        width_before = hi - lo;
        since_halved = 0;
      } else {
        ++since_halved;
      }
    }
    t = 0.5L * (lo + hi);
  }
  for (int i = 0; i < 3; ++i) p[i] = ray.o[i] + t * ray.d[i];
  return {static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])};
}

void line_spans(const Algebraic& s, const LineRoots& r, SpanList& out) {
  chord_spans(
      r.chord, r.t, r.err, r.n, !s.open, [&](double t) { return evaluate(r.p, t - r.mid) < 0; },
      out);
}

// The first span end in [tmin, tmax] (into *hit when given), skipping curved roots within their
// own error estimate of tmin: near singular points (the heart's equator, where f has a triple root)
// such a root cannot be told from the ray's origin lying on the surface, and a secondary ray would
// otherwise find its own surface again.
bool first_hit(const Algebraic& s, const Ray& ray, const LineRoots& r, LocalHit* hit) {
  SpanList l;
  line_spans(s, r, l);
  for (const Span& span : l)
    for (const LocalHit* h : {&span.in, &span.out}) {
      if (!(h->t >= ray.tmin && h->t <= ray.tmax)) continue;
      if (h->part < kFacePart && h->t - ray.tmin <= h->a) continue;
      if (hit) *hit = *h;
      return true;
    }
  return false;
}

// f over the box v[0] x v[1] x v[2] by interval arithmetic: the formula as written (line_code,
// whose sums and powers are not expanded, so far tighter) when kept, else the expanded terms.
Interval enclosure(const Trivariate& f, const Interval v[3]) {
  using Op = Trivariate::LineOp;
  if (f.line_code.empty()) {
    Interval sum(0.0);
    for (const Trivariate::Term& t : f.terms)
      sum = sum + Interval(t.c) * pow_int(v[0], t.i) * pow_int(v[1], t.j) * pow_int(v[2], t.k);
    return sum;
  }
  std::vector<Interval> stack, saved;
  for (const Op& in : f.line_code) {
    switch (in.kind) {
      case Op::kConst:
        stack.push_back(Interval(in.value));
        break;
      case Op::kVar:
        stack.push_back(v[in.n]);
        break;
      case Op::kAdd:
      case Op::kSub:
      case Op::kMul: {
        const Interval b = stack.back();
        stack.pop_back();
        Interval& a = stack.back();
        a = in.kind == Op::kAdd ? a + b : (in.kind == Op::kSub ? a - b : a * b);
        break;
      }
      case Op::kNeg:
        stack.back() = -stack.back();
        break;
      case Op::kDiv:
        stack.back() = stack.back() / Interval(in.value);
        break;
      case Op::kPow:
        stack.back() = in.n == 0 ? Interval(1.0) : pow_int(stack.back(), in.n);
        break;
      case Op::kStore:
        if (saved.size() <= static_cast<std::size_t>(in.n)) saved.resize(in.n + 1);
        saved[in.n] = stack.back();
        break;
      case Op::kLoad:
        stack.push_back(saved[in.n]);
        break;
    }
  }
  return stack.back();
}

// Cells the reach search may bound per side before it settles for the best bound so far.
constexpr int kReachMaxCells = 4096;
// The search stops once the extreme cell is this fraction of the box's extent thin.
constexpr double kReachResolution = 1.0 / 256;

}  // namespace

Aabb reach_of_algebraic(const Algebraic& s) {
  const Aabb& box = s.box;
  const Vec3 extent = box.extent();
  // A bound on the magnitude of every term over the box: the scale of any evaluation's rounding.
  double magnitude = 0;
  for (const Trivariate::Term& t : s.f.terms) {
    double m = std::abs(t.c);
    const int power[3] = {t.i, t.j, t.k};
    for (int a = 0; a < 3; ++a)
      m *= std::pow(std::max(std::abs(box.lo[a]), std::abs(box.hi[a])), power[a]);
    magnitude += m;
  }
  const double delta = 1e-9 * magnitude;
  // A cell where f certainly stays beyond delta on the empty side holds neither solid nor surface.
  auto empty_cell = [&](const Aabb& c) {
    const Interval v[3] = {{c.lo.x, c.hi.x}, {c.lo.y, c.hi.y}, {c.lo.z, c.hi.z}};
    const Interval r = enclosure(s.f, v);
    return r.lo > delta || (s.open && r.hi < -delta);
  };
  Aabb reach;
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool upper : {false, true}) {
      // Best first: the cell reaching furthest out along the axis on this side. Every point not
      // proved empty lies in a queued cell or the one just taken, so that cell's far face bounds
      // them all, whenever the search stops.
      auto key = [&](const Aabb& c) { return upper ? c.hi[axis] : -c.lo[axis]; };
      auto nearer = [&](const Aabb& a, const Aabb& b) { return key(a) < key(b); };
      std::priority_queue<Aabb, std::vector<Aabb>, decltype(nearer)> cells(nearer);
      cells.push(box);
      bool found = false;
      double bound = 0;
      for (int taken = 0; !cells.empty(); ++taken) {
        const Aabb c = cells.top();
        cells.pop();
        if (taken < kReachMaxCells && empty_cell(c)) continue;
        if (taken >= kReachMaxCells || c.extent()[axis] <= kReachResolution * extent[axis]) {
          bound = key(c);
          found = true;
          break;
        }
        // Halved across the axis along which it is widest relative to the box.
        int split = axis;
        for (int a = 0; a < 3; ++a)
          if (c.extent()[a] * extent[split] > c.extent()[split] * extent[a]) split = a;
        const double mid = 0.5 * (c.lo[split] + c.hi[split]);
        Aabb low = c, high = c;
        low.hi[split] = mid;
        high.lo[split] = mid;
        cells.push(low);
        cells.push(high);
      }
      if (!found) return box;  // nothing anywhere: an empty solid
      if (upper) {
        reach.hi[axis] = bound;
      } else {
        reach.lo[axis] = -bound;
      }
    }
  }
  // A hair wider (the rounding of points computed from roots), within the box.
  for (int a = 0; a < 3; ++a) {
    reach.lo[a] = std::max(box.lo[a], reach.lo[a] - 1e-9 * extent[a]);
    reach.hi[a] = std::min(box.hi[a], reach.hi[a] + 1e-9 * extent[a]);
  }
  return reach;
}

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
  s.reach = reach_of_algebraic(s);
  return s;
}

Aabb bounds(const Algebraic& s) { return s.reach.is_empty() ? s.box : s.reach; }

bool intersect(const Algebraic& s, const Ray& ray, LocalHit& hit) {
  LineRoots r;
  if (!line_roots(s, ray, r)) return false;
  if (r.chord.t1 < ray.tmin || r.chord.t0 > ray.tmax) return false;
  return first_hit(s, ray, r, &hit);
}

bool occluded(const Algebraic& s, const Ray& ray) {
  // The shadow walk tests a ball around bounds(): a segment that misses the reach box crosses
  // nothing (the reach holds every crossing with a margin far above this test's rounding; where it
  // is the box, the test is line_polynomial's own).
  if (BoxChord reach; !s.reach.is_empty() && (!box_chord(s.reach, ray, reach) ||
                                              reach.t1 < ray.tmin || reach.t0 > ray.tmax))
    return false;
  LineRoots r;
  if (!line_polynomial(s, ray, r)) return false;
  if (r.chord.t1 < ray.tmin || r.chord.t0 > ray.tmax) return false;
  // Shadow rays mostly cross the surface: a certain sign change of f between points past tmin by
  // more than any root's error estimate (so not the ray's own surface, which intersect skips) and
  // before tmax proves a hit without isolating the roots.
  const double lo = std::max(r.chord.t0, ray.tmin + kMaxRootError * (r.chord.t1 - r.chord.t0));
  const double hi = std::min(r.chord.t1, ray.tmax);
  if (lo < hi && certain_sign_change(r, lo, hi)) return true;
  if (const int known = occluded_by_sweeps(s, ray, r); known >= 0) return known == 1;
  solve_line(r);
  return first_hit(s, ray, r, nullptr);
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
    long double pe[3], ge[3];
    p = polished_point(s, ray, hit, pe);
    gradient_extended(s.f, pe[0], pe[1], pe[2], ge);
    const long double gmax = std::max({std::abs(ge[0]), std::abs(ge[1]), std::abs(ge[2])});
    const Vec3 g = gmax > 0
                       ? Vec3{static_cast<double>(ge[0] / gmax), static_cast<double>(ge[1] / gmax),
                              static_cast<double>(ge[2] / gmax)}
                       : Vec3{};
    const double gl = length(g);
    // A singular point of the surface (zero gradient) has no normal: face the ray.
    si.n = gl > 0 && std::isfinite(gl) ? g / gl : -normalize(ray.d);
    si.p_error = gamma(16) * abs(p) + hit.a * abs(ray.d);
    // The root's own error leaves p off the surface, most at grazing angles and where the
    // gradient is small: add twice the first-order distance |f(p)| / |grad f(p)|.
    const double dist = 2 * std::abs(evaluate(s.f, p)) / length(gradient(s.f, p));
    if (std::isfinite(dist)) si.p_error += dist * abs(si.n);
  }
  si.shading_n = si.n;
  si.p = p;
  return si;
}

bool contains(const Algebraic& s, const Vec3& p) {
  return !s.open && s.box.contains(p) && evaluate(s.f, p) < 0;
}

}  // namespace raycast
