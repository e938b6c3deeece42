#include "geometry/superellipsoid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/angles.h"
#include "geometry/crossing_list.h"
#include "geometry/shape_error.h"

namespace raycast {

namespace {

// The root isolation works on f(t) = gauge(o + t d) - 1. The gauge is increasing in |x|, |y|,
// |z|, and on a t-interval each |coordinate| lies between its values at the ends (0 if the
// coordinate changes sign there): the gauge at the smallest and at the largest corner bound f
// over the interval. Its derivative is bounded the same way, through the chain rule of the
// nested norms (partial derivatives (|x| / N)^(p - 1) of N = (|x|^p + |y|^p)^(1/p)). An
// interval whose value bounds exclude 0 holds no root; one whose derivative bounds exclude 0
// holds at most one, found by bracketing to double precision; others are halved.

constexpr double kSeEps = std::numeric_limits<double>::epsilon();
// At most this many crossings are kept per line (far more than the shape can have: at most two
// per octant where the solid is convex or its complement is, a few where they are mixed).
constexpr int kSeMaxCrossings = 32;
// Halvings of one interval: past this the interval is a few ulps wide for any t.
constexpr int kSeMaxDepth = 160;
// Bounds on the work for one line: past the budget only intervals whose ends differ in sign are
// followed (each still holds a crossing), by halving.
constexpr int kSeEvalBudget = 6000;

struct SeExponents {
  double p;  // 2 / e: the cross-section's norm
  double q;  // 2 / n: the profile's norm
};

SeExponents se_exponents(const Superellipsoid& s) { return {2 / s.e, 2 / s.n}; }

// (a^p + b^p)^(1/p) for a, b >= 0 as max * (1 + (min / max)^p)^(1/p): the se_ratio keeps every
// power in [0, 1] (it saturates to inf only where the true value exceeds any double).
template <class T>
T se_norm(T a, T b, T p) {
  const T hi = std::max(a, b), lo = std::min(a, b);
  if (!(lo > 0)) return hi;
  return hi * std::pow(1 + std::pow(lo / hi, p), 1 / p);
}

double se_gauge(const SeExponents& x, double ax, double ay, double az) {
  return se_norm(se_norm(ax, ay, x.p), az, x.q);
}

// (se_ratio)^(k) over se_ratio in [lo, hi] within [0, 1], for the partial derivatives.
struct SeRange {
  double lo, hi;
};
SeRange se_pow_range(double lo, double hi, double k) {
  const double a = std::pow(lo, k), b = std::pow(hi, k);
  return k >= 0 ? SeRange{a, b} : SeRange{b, a};
}

// w * d for w in [w.lo, w.hi] with w >= 0 (possibly +inf) and any d: 0 * inf counts as 0 (a
// derivative factor that is 0 at an end bounds the product by 0 there).
SeRange se_mul_nonneg(SeRange w, SeRange d) {
  auto m = [](double a, double b) {
    const double r = a * b;
    return r == r ? r : 0.0;
  };
  if (d.lo == 0 && d.hi == 0) return {0, 0};
  return {d.lo >= 0 ? m(w.lo, d.lo) : m(w.hi, d.lo), d.hi >= 0 ? m(w.hi, d.hi) : m(w.lo, d.hi)};
}

// The se_ratio v / total over v in [vlo, vhi] and total in [tlo, thi] (v <= total), within [0, 1].
SeRange se_ratio(double vlo, double vhi, double tlo, double thi) {
  return {thi > 0 ? std::min(1.0, vlo / thi) : 0, tlo > 0 ? std::min(1.0, vhi / tlo) : 1};
}

struct SeLine {
  Vec3 o, d;
  SeExponents x;
  double slack;  // rounding allowance of f, from the size of the coordinates

  double f(double t) const {
    const Vec3 p = o + t * d;
    return se_gauge(x, std::abs(p.x), std::abs(p.y), std::abs(p.z)) - 1;
  }
  long double f_ld(double t) const {
    using L = long double;
    const L ax = std::abs(o.x + L(t) * d.x), ay = std::abs(o.y + L(t) * d.y);
    const L az = std::abs(o.z + L(t) * d.z);
    return se_norm(se_norm(ax, ay, L(x.p)), az, L(x.q)) - 1;
  }

  // |c(t)| over [a, b] for the coordinate c = o_i + t d_i, and the range of its derivative.
  static void coord(double o, double d, double a, double b, SeRange& v, SeRange& dv) {
    const double ca = o + a * d, cb = o + b * d;
    if (ca >= 0 && cb >= 0) {
      v = {std::min(ca, cb), std::max(ca, cb)};
      dv = {d, d};
    } else if (ca <= 0 && cb <= 0) {
      v = {std::min(-ca, -cb), std::max(-ca, -cb)};
      dv = {-d, -d};
    } else {
      v = {0, std::max(std::abs(ca), std::abs(cb))};
      dv = {-std::abs(d), std::abs(d)};
    }
  }

  // Bounds of f and of f' over [a, b].
  void bound(double a, double b, SeRange& fv, SeRange& df) const {
    SeRange X, Y, Z, dX, dY, dZ;
    coord(o.x, d.x, a, b, X, dX);
    coord(o.y, d.y, a, b, Y, dY);
    coord(o.z, d.z, a, b, Z, dZ);
    const SeRange N{se_norm(X.lo, Y.lo, x.p), se_norm(X.hi, Y.hi, x.p)};
    const SeRange R{se_norm(N.lo, Z.lo, x.q), se_norm(N.hi, Z.hi, x.q)};
    fv = {R.lo - 1 - slack, R.hi - 1 + slack};
    const SeRange rx = se_ratio(X.lo, X.hi, N.lo, N.hi), ry = se_ratio(Y.lo, Y.hi, N.lo, N.hi);
    const SeRange tx = se_mul_nonneg(se_pow_range(rx.lo, rx.hi, x.p - 1), dX);
    const SeRange ty = se_mul_nonneg(se_pow_range(ry.lo, ry.hi, x.p - 1), dY);
    const SeRange dN{tx.lo + ty.lo, tx.hi + ty.hi};
    const SeRange rn = se_ratio(N.lo, N.hi, R.lo, R.hi), rz = se_ratio(Z.lo, Z.hi, R.lo, R.hi);
    const SeRange un = se_mul_nonneg(se_pow_range(rn.lo, rn.hi, x.q - 1), dN);
    const SeRange uz = se_mul_nonneg(se_pow_range(rz.lo, rz.hi, x.q - 1), dZ);
    df = {un.lo + uz.lo, un.hi + uz.hi};
  }
};

// The crossing in [a, b], where f is monotone and fa, fb differ in sign (or one is 0): the
// Illinois variant of regula falsi, with a halving whenever it stalls, to adjacent doubles.
template <class T, class F>
double se_bracket(const F& f, double a, double b, T fa, T fb) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  int side = 0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (a + b);
    if (!(mid > a && mid < b)) break;
    double m = mid;
    if (i % 4 != 3 && std::isfinite(fa) && std::isfinite(fb)) {
      const double s = static_cast<double>(a - fa * (b - a) / (fb - fa));
      if (s > a && s < b) m = s;
    }
    const T fm = f(m);
    if (fm == 0) return m;
    if ((fm < 0) == (fa < 0)) {
      a = m, fa = fm;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = m, fb = fm;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return std::abs(fa) <= std::abs(fb) ? a : b;
}

// The gauge's gradient at p through the nested norms: d gauge / d|x| = (N / R)^(q - 1)
// (|x| / N)^(p - 1); a component is NaN where its coordinate is 0 under a negative power.
Vec3 se_gradient(const SeExponents& x, const Vec3& p) {
  const Vec3 a = abs(p);
  const double N = se_norm(a.x, a.y, x.p), R = se_norm(N, a.z, x.q);
  const double vn = N > 0 ? std::pow(N / R, x.q - 1) : 0;
  Vec3 g{N > 0 ? vn * std::pow(a.x / N, x.p - 1) : 0, N > 0 ? vn * std::pow(a.y / N, x.p - 1) : 0,
         R > 0 ? std::pow(a.z / R, x.q - 1) : 0};
  for (std::size_t i = 0; i < 3; ++i) g[i] = p[i] == 0 ? 0 * g[i] : std::copysign(g[i], p[i]);
  return g;
}

// The crossing in [a, b], where fa and fb differ in sign. Near a crossing f loses its leading
// digits to the subtraction of 1: the root is uncertain by f's rounding (a few eps) over its
// slope, more than an ulp of t where the line grazes the surface. Where the slope at the root
// cannot promise an ulp, the double root is narrowed again on f in long double (three more
// digits; libm's powl is slow, so only there).
double se_refine(const SeLine& l, double a, double b, double fa, double fb) {
  const double t = se_bracket([&l](double u) { return l.f(u); }, a, b, fa, fb);
  const double ulp = std::nextafter(std::abs(t), kInfinity) - std::abs(t);
  const double df = std::abs(dot(se_gradient(l.x, l.o + t * l.d), l.d));
  const double slope = std::isnan(df) ? 0 : df;
  if (slope * ulp > kSeEps) return t;  // f rounds by a few eps: t by a few ulps
  const double reach = slope > 0 ? 16 * kSeEps / slope : kInfinity;
  const double lo = std::max(a, t - reach), hi = std::min(b, t + reach);
  const auto f_ld = [&l](double u) { return l.f_ld(u); };
  const long double la = f_ld(lo), lb = f_ld(hi);
  if ((la <= 0) != (lb <= 0) || la == 0 || lb == 0) return se_bracket(f_ld, lo, hi, la, lb);
  return t;
}

struct SeCrossings {
  double t[kSeMaxCrossings];
  int n = 0;
  void add(double v) {
    if (n > 0 && t[n - 1] == v) return;  // a crossing at a shared end, found from both sides
    if (n < kSeMaxCrossings) t[n++] = v;
  }
};

// Appends the crossings in [a, b] in increasing order; stops after the first when `first`.
void se_isolate(const SeLine& l, double a, double b, bool first, SeCrossings& out, int& budget) {
  struct Item {
    double a, b, fa, fb;
    int depth;
  };
  Item stack[kSeMaxDepth + 2];
  int top = 0;
  stack[top++] = {a, b, l.f(a), l.f(b), 0};
  while (top > 0) {
    const Item it = stack[--top];
    const bool change = (it.fa <= 0) != (it.fb <= 0) || it.fa == 0 || it.fb == 0;
    if (--budget < 0 && !change) continue;
    SeRange fv{0, 0}, df{0, 0};
    if (budget >= 0) {
      l.bound(it.a, it.b, fv, df);
      if (!change && (fv.lo > 0 || fv.hi < 0)) continue;
    }
    const double mid = 0.5 * (it.a + it.b);
    const bool monotone = budget >= 0 && (df.lo > 0 || df.hi < 0);
    if (monotone || !(mid > it.a && mid < it.b) || it.depth >= kSeMaxDepth) {
      if (change) {
        out.add(se_refine(l, it.a, it.b, it.fa, it.fb));
        if (first) return;
      }
      continue;
    }
    const double fm = l.f(mid);
    // Right half first onto the stack, so that the left half is taken next.
    stack[top++] = {mid, it.b, fm, it.fb, it.depth + 1};
    stack[top++] = {it.a, mid, it.fa, fm, it.depth + 1};
  }
}

// The line's t-range inside the box [-1, 1]^3, widened by a hair (the solid touches the box).
bool se_clip_to_box(const Ray& ray, double& t0, double& t1) {
  constexpr double kHalf = 1 + 1e-12;
  t0 = -kInfinity, t1 = kInfinity;
  for (std::size_t i = 0; i < 3; ++i) {
    const double o = ray.o[i], d = ray.d[i];
    if (d == 0) {
      if (std::abs(o) > kHalf) return false;
      continue;
    }
    double a = (-kHalf - o) / d, b = (kHalf - o) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

// The crossings within [lo, hi] (clipped to the box), in increasing t. The range is cut where
// the line crosses the coordinate planes, so that f is evaluated exactly there (a tangent touch
// on an axis) and the pieces' |coordinates| are linear.
void se_crossings(const Superellipsoid& s, const Ray& ray, double lo, double hi, bool first,
                  SeCrossings& out) {
  double t0, t1;
  if (!se_clip_to_box(ray, t0, t1)) return;
  lo = std::max(lo, t0);
  hi = std::min(hi, t1);
  if (!(lo <= hi)) return;
  double cuts[5];
  int nc = 0;
  cuts[nc++] = lo;
  for (std::size_t i = 0; i < 3; ++i)
    if (ray.d[i] != 0) {
      const double t = -ray.o[i] / ray.d[i];
      if (t > lo && t < hi) cuts[nc++] = t;
    }
  for (int i = 2; i < nc; ++i)  // at most three cuts: insertion sort
    for (int j = i; j > 1 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
  cuts[nc++] = hi;
  SeLine l{ray.o, ray.d, se_exponents(s), 0};
  const double reach = std::max(std::abs(lo), std::abs(hi));
  l.slack = 8 * kSeEps * (1 + max_component(abs(ray.o)) + reach * max_component(abs(ray.d)));
  int budget = kSeEvalBudget;
  if (lo == hi) {
    if (l.f(lo) == 0) out.add(lo);
    return;
  }
  for (int i = 0; i + 1 < nc; ++i) {
    if (!(cuts[i] < cuts[i + 1])) continue;
    se_isolate(l, cuts[i], cuts[i + 1], first, out, budget);
    if (first && out.n > 0) return;
  }
}

}  // namespace

Superellipsoid make_superellipsoid(double e, double n) {
  auto check = [](const char* name, double v) {
    if (!(v >= kSuperellipsoidMinExponent && v <= kSuperellipsoidMaxExponent))
      throw ShapeParameterError(
          name, "must be in [" + format_parameter(kSuperellipsoidMinExponent) + ", " +
                    format_parameter(kSuperellipsoidMaxExponent) + "], got " + format_parameter(v));
  };
  check("e", e);
  check("n", n);
  return Superellipsoid{e, n};
}

Aabb bounds(const Superellipsoid&) { return {{-1, -1, -1}, {1, 1, 1}}; }

double superellipsoid_gauge(const Superellipsoid& s, const Vec3& p) {
  return se_gauge(se_exponents(s), std::abs(p.x), std::abs(p.y), std::abs(p.z));
}

bool intersect(const Superellipsoid& s, const Ray& ray, LocalHit& hit) {
  SeCrossings c;
  se_crossings(s, ray, ray.tmin, ray.tmax, true, c);
  if (c.n == 0) return false;
  hit = LocalHit{.t = c.t[0]};
  return true;
}

void spans(const Superellipsoid& s, const Ray& ray, SpanList& out) {
  SeCrossings c;
  se_crossings(s, ray, -kInfinity, kInfinity, false, c);
  CurveCrossing cc[kSeMaxCrossings];
  for (int i = 0; i < c.n; ++i) cc[i] = {c.t[i], 0, 0};
  spans_from_crossings(
      cc, c.n, ray, true, [&](const Vec3& p) { return contains(s, p); }, out);
}

SurfaceInfo surface(const Superellipsoid& s, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  // The gauge is homogeneous of degree 1: p / gauge(p) lies on the surface, along the ray from
  // the centre (a move of the order of the root's rounding).
  const double g = superellipsoid_gauge(s, p);
  if (g > 0 && std::isfinite(g)) p = p / g;
  // A zero coordinate with a negative power (the tip of a cusp where e or n exceeds 2) makes
  // the gradient infinite: the surface has no normal there, and the radial direction (out of
  // the star-shaped solid) stands in for it.
  const Vec3 grad = se_gradient(se_exponents(s), p);
  const double gl = length(grad);
  si.n = gl > 0 && std::isfinite(gl) ? grad / gl : normalize(p);
  si.shading_n = si.n;
  si.p = p;
  si.u = phi_of(p.x, p.y) / kTwoPi;
  const double r = length(p);
  si.v = r > 0 ? std::acos(std::clamp(-p.z / r, -1.0, 1.0)) / std::numbers::pi : 0;
  si.p_error = gamma(32) * (abs(p) + Vec3{1, 1, 1});
  return si;
}

bool contains(const Superellipsoid& s, const Vec3& p) { return superellipsoid_gauge(s, p) <= 1; }

}  // namespace raycast
