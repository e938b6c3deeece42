#include "geometry/implicit.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "geometry/algebraic.h"
#include "geometry/clipped_solid.h"
#include "math/formula_lanes.h"

namespace raycast {

namespace {

using DualT = Dual<double, 1>;  // value and derivative along the ray
using Dual3 = Dual<double, 3>;  // value and gradient

// Newton with bisection gives up cycling after this many steps (bisection alone needs ~64).
constexpr int kMaxRefineSteps = 100;

double f_at(const Implicit& s, const Ray& ray, double t) {
  const Vec3 p = ray.at(t);
  return run<double>(s.f, p.x, p.y, p.z);
}

DualT f_along(const Implicit& s, const Ray& ray, double t) {
  const Vec3 p = ray.at(t);
  DualT x(p.x), y(p.y), z(p.z);
  x.d[0] = ray.d.x;
  y.d[0] = ray.d.y;
  z.d[0] = ray.d.z;
  return run<DualT>(s.f, x, y, z);
}

bool negative(double v) { return v < 0; }

// The root in [a, b] where f changes sign (fa = f(a), fb = f(b)): Newton's method kept inside
// the bracket, starting at the secant point, bisection when a step leaves the bracket. Stops when
// a Newton step is within 4 ulps of t (checked before the bracket test: once f is down to its
// rounding noise, the step from the bracket's end would otherwise leave it and bisect on).
double refine(const Implicit& s, const Ray& ray, double a, double b, double fa, double fb) {
  double x = a - fa * (b - a) / (fb - fa);
  if (!(x > a && x < b)) x = 0.5 * (a + b);
  for (int i = 0; i < kMaxRefineSteps; ++i) {
    const DualT f = f_along(s, ray, x);
    if (f.v == 0) return x;
    if (negative(f.v) == negative(fa)) {
      a = x;
      fa = f.v;
    } else {
      b = x;
    }
    const double mid = 0.5 * (a + b);
    if (!(mid > a && mid < b)) return x;
    double next = x - f.v / f.d[0];
    if (std::abs(next - x) <= 4 * kMachineEpsilon * std::abs(x)) return std::clamp(next, a, b);
    if (!(next > a && next < b)) next = mid;
    x = next;
  }
  return x;
}

// What find_roots looks for: every root, the first one, or whether there is any (the search
// stops at the first sign change without refining it: roots[0] is then only within its piece).
enum class Want { kAll, kFirst, kAny };

// The roots of f along the ray in [lo, hi], in increasing order, into roots (at most max_roots);
// see Want. Returns the count. known_f is f at known_t, if the caller has it (NaN: nothing). A
// piece is split in kFormulaLanes parts evaluated in one pass (run_lanes); parts whose inclusion
// excludes 0 are dropped, the others kept in order on a stack, each settled by its ends' signs once
// f is monotone on it (or it is too small to split) and split again otherwise.
int find_roots(const Implicit& s, const Ray& ray, double lo, double hi, Want want, double* roots,
               int max_roots, double known_t = std::numeric_limits<double>::quiet_NaN(),
               double known_f = 0) {
  const bool first_only = want != Want::kAll;
  constexpr int W = kFormulaLanes;
  struct Piece {
    double a, b;
    int depth;  // halvings from the chord: a split into W parts adds log2(W)
    bool monotone;
    // f's sign at a and at b where a neighbouring part's inclusion proved it (+1 or -1), else 0.
    signed char sign_a, sign_b;
    double sin_a[3], cos_a[3], sin_b[3], cos_b[3];  // of the variables at a and b (trig_vars)
  };
  constexpr int kDepthStep = std::bit_width(static_cast<unsigned>(W)) - 1;
  Piece stack[W * (kImplicitMaxDepth / kDepthStep + 2)];
  int top = -1, count = 0, steps = 0;
  // Bit 0: a part where f is certainly positive, bit 1: certainly negative. For Want::kAny on a
  // continuous f, both prove a root between them (inside [lo, hi]): the search stops there.
  unsigned signs_seen = 0;
  const bool any_by_signs = want == Want::kAny && s.f.continuous;
  const double o[3] = {ray.o.x, ray.o.y, ray.o.z}, d[3] = {ray.d.x, ray.d.y, ray.d.z};
  // Splits [a, b] into W parts and pushes those that may hold a root, last first. False when
  // the parts' ends would not increase strictly (the piece is a few ulps wide).
  const bool trig = s.f.trig_vars != 0;
  auto split = [&](double a, double b, int depth, const Piece* known) {
    double t[W + 1];
    t[0] = a;
    t[W] = b;
    for (int step = W / 2; step >= 1; step /= 2)
      for (int k = step; k < W; k += 2 * step) t[k] = 0.5 * (t[k - step] + t[k + step]);
    for (int k = 0; k < W; ++k)
      if (!(t[k] < t[k + 1])) return false;
    FormulaLanes f;
    LaneTrig lt;
    if (trig && known) {
      lt.ends_known = true;
      for (int v = 0; v < 3; ++v) {
        lt.s[v][0] = known->sin_a[v];
        lt.c[v][0] = known->cos_a[v];
        lt.s[v][W] = known->sin_b[v];
        lt.c[v][W] = known->cos_b[v];
      }
    }
    run_lanes(s.f, o, d, t, f, &lt);
    steps += W;
    // Each part's certain sign (0: none): the inclusion holds f's value at the part's ends as
    // f_at computes it (the same roundings, each inside the widened bounds), so a part's sign is
    // that value's sign at both ends.
    signed char sign[W + 2];
    sign[0] = known ? known->sign_a : 0;
    sign[W + 1] = known ? known->sign_b : 0;
    for (int k = 0; k < W; ++k)
      sign[k + 1] = f.lo[k] > 0 ? 1 : (f.hi[k] < 0 ? -1 : 0);  // (NaN and empty: 0)
    for (int k = W - 1; k >= 0; --k) {
      if (!(f.lo[k] <= 0 && 0 <= f.hi[k])) {  // excludes 0, or empty (undefined)
        if (f.lo[k] <= f.hi[k]) signs_seen |= f.hi[k] < 0 ? 2 : 1;
        continue;
      }
      const bool monotone = f.dlo[k] <= f.dhi[k] && (f.dlo[k] > 0 || f.dhi[k] < 0);
      Piece& p = stack[++top];
      p.a = t[k];
      p.b = t[k + 1];
      p.depth = depth + kDepthStep;
      p.monotone = monotone;
      p.sign_a = sign[k];
      p.sign_b = sign[k + 2];
      if (trig) {
        for (int v = 0; v < 3; ++v) {
          p.sin_a[v] = lt.s[v][k];
          p.cos_a[v] = lt.c[v][k];
          p.sin_b[v] = lt.s[v][k + 1];
          p.cos_b[v] = lt.c[v][k + 1];
        }
      }
    }
    return true;
  };
  // The root of a piece on which f is monotone (or which cannot be split): a sign change of its
  // ends. Returns whether the search is over.
  // f at known_t (a value the caller has, or the last end's: depth first from the left, a settled
  // piece's right end is often the next one's left end, the same point, so the same value).
  // For Want::kAny only signs matter: an end whose sign a neighbour proved stands in as +-1
  // (the same sign as f_at's value, and not 0), without evaluating f there.
  auto value_at = [&](double t, int sign) {
    return want == Want::kAny && sign != 0 ? double(sign) : f_at(s, ray, t);
  };
  auto settle = [&](double a, double b, int sign_a, int sign_b) {
    const double fa = a == known_t ? known_f : value_at(a, sign_a), fb = value_at(b, sign_b);
    known_t = b;
    known_f = fb;
    double t;
    if (fa == 0) {
      t = a;
    } else if (fb == 0 && b == hi) {
      t = b;  // a root at an inner piece's end is its neighbour's start
    } else if (std::isnan(fa) || std::isnan(fb) || negative(fa) == negative(fb)) {
      return false;
    } else {
      t = want == Want::kAny ? a : refine(s, ray, a, b, fa, fb);
    }
    if (count == 0 || t > roots[count - 1]) roots[count++] = t;
    return first_only;
  };
  auto proved_by_signs = [&] {
    if (!any_by_signs || signs_seen != 3) return false;
    roots[0] = lo;  // a root lies between two parts, somewhere in [lo, hi]
    count = 1;
    return true;
  };
  if (!split(lo, hi, 0, nullptr) && settle(lo, hi, 0, 0)) return count;
  if (proved_by_signs()) return count;
  while (top >= 0 && count < max_roots && steps <= kImplicitMaxSteps) {
    if (proved_by_signs()) break;
    const Piece p = stack[top--];
    if (p.monotone || p.depth >= kImplicitMaxDepth || !split(p.a, p.b, p.depth, &p)) {
      if (settle(p.a, p.b, p.sign_a, p.sign_b)) break;
    }
  }
  return count;
}

// Room for the crossings of one ray; a formula with more within the box loses the later ones.
constexpr int kMaxImplicitRoots = 64;

}  // namespace

Implicit make_implicit(std::string_view function, const Aabb& box, bool open) {
  check_bounds_box(box);
  Implicit s;
  s.f = compile_formula(function);
  s.box = box;
  s.open = open;
  return s;
}

double evaluate(const Implicit& s, const Vec3& p) { return run<double>(s.f, p.x, p.y, p.z); }

Aabb bounds(const Implicit& s) { return s.box; }

namespace {

// intersect, and occluded when hit is null (the same answer: the same pieces searched in the same
// order, only the root's refinement skipped).
bool first_hit(const Implicit& s, const Ray& ray, LocalHit* hit) {
  BoxChord c;
  if (!box_chord(s.box, ray, c)) return false;
  const double lo = std::max(c.t0, ray.tmin), hi = std::min(c.t1, ray.tmax);
  if (!(lo <= hi)) return false;
  const bool closed = !s.open;
  double known_t = std::numeric_limits<double>::quiet_NaN(), known_f = 0;
  if (closed && lo == c.t0) {
    known_t = c.t0;
    known_f = f_at(s, ray, c.t0);
    if (negative(known_f)) {
      if (hit) *hit = LocalHit{c.t0, -1, kFacePart + c.face0, 0, 0};
      return true;
    }
  }
  double t;
  if (find_roots(s, ray, lo, hi, hit ? Want::kFirst : Want::kAny, &t, 1, known_t, known_f) == 1) {
    if (hit) *hit = LocalHit{t, -1, kCurvedPart, 0, 0};
    return true;
  }
  if (closed && hi == c.t1 && negative(f_at(s, ray, c.t1))) {
    if (hit) *hit = LocalHit{c.t1, -1, kFacePart + c.face1, 0, 0};
    return true;
  }
  return false;
}

}  // namespace

bool intersect(const Implicit& s, const Ray& ray, LocalHit& hit) { return first_hit(s, ray, &hit); }

bool occluded(const Implicit& s, const Ray& ray) { return first_hit(s, ray, nullptr); }

void spans(const Implicit& s, const Ray& ray, SpanList& out) {
  BoxChord c;
  if (!box_chord(s.box, ray, c)) return;
  double roots[kMaxImplicitRoots], errors[kMaxImplicitRoots] = {};
  const int n = find_roots(s, ray, c.t0, c.t1, Want::kAll, roots, kMaxImplicitRoots);
  chord_spans(
      c, roots, errors, n, !s.open, [&](double t) { return negative(f_at(s, ray, t)); }, out);
}

SurfaceInfo surface(const Implicit& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  if (hit.part >= kFacePart) {
    const int face = hit.part - kFacePart;
    p[face / 2] = face % 2 ? s.box.hi[face / 2] : s.box.lo[face / 2];
    si.n = box_face_normal(face);
    si.p_error = gamma(4) * abs(p);
  } else {
    Dual3 c[3];
    for (int i = 0; i < 3; ++i) {
      c[i] = Dual3(p[i]);
      c[i].d[i] = 1;
    }
    const Dual3 f = run<Dual3>(s.f, c[0], c[1], c[2]);
    const Vec3 g{f.d[0], f.d[1], f.d[2]};
    const double gl = length(g);
    si.n = gl > 0 && std::isfinite(gl) ? g / gl : -normalize(ray.d);
    // The root is refined to a few ulps of t; the point's error follows.
    si.p_error = gamma(16) * (abs(p) + abs(hit.t * ray.d));
  }
  si.shading_n = si.n;
  si.p = p;
  return si;
}

bool contains(const Implicit& s, const Vec3& p) {
  return !s.open && s.box.contains(p) && negative(evaluate(s, p));
}

}  // namespace raycast
