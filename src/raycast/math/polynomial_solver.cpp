#include "math/polynomial_solver.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "math/bernstein.h"
#include "math/float_error.h"

namespace raycast {

namespace {

// Bisection halves an interval of doubles at most ~2100 times before it stops shrinking; Newton
// takes over long before on any simple root, so this cap is only a guard against cycling.
constexpr int kMaxRefineSteps = 200;

bool same_sign(double a, double b) { return (a < 0) == (b < 0); }

// The root of p in [a, b], where p(a) = fa and p(b) = fb have opposite signs: starts at the
// regula falsi point, then Newton steps kept inside the bracket, bisection when a step leaves it
// or does not halve the bracket.
double refine_root(const Polynomial& p, double a, double b, double fa, double fb) {
  double x = a - fa * (b - a) / (fb - fa);
  if (!(x > a && x < b)) x = 0.5 * (a + b);
  double step_before = b - a;
  for (int i = 0; i < kMaxRefineSteps; ++i) {
    double df, err;
    const double f = evaluate(p, x, df, err);
    if (f == 0) return x;
    if (std::abs(f) <= err) {
      // Within the (pessimistic) error bound of p: one more Newton step usually lands on the
      // root to the last bits, as the actual rounding is far below the bound.
      const double last = x - f / df;
      return last >= a && last <= b ? last : x;
    }
    if (same_sign(f, fa)) {
      a = x;
      fa = f;
    } else {
      b = x;
    }
    const double mid = 0.5 * (a + b);
    if (!(mid > a && mid < b)) return std::abs(f) <= std::abs(evaluate(p, a)) ? x : a;
    double next = x - f / df;
    const double step = std::abs(next - x);
    if (!(next > a && next < b) || 2 * step > step_before) {
      next = mid;
      step_before = b - a;
    } else {
      step_before = step;
    }
    if (next == x) return x;
    x = next;
  }
  return x;
}

// Whether p certainly has no root in [lo, hi]: with the Taylor expansion p(c + u) = sum a_k u^k
// about the centre, |a_0| > sum_{k >= 1} |a_k| h^k (plus rounding) excludes every |u| <= h.
bool certainly_no_root(const Polynomial& p, double lo, double hi) {
  const double c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
  const Polynomial q = shifted(p, c);
  double sum = 0, hk = 1, mag = std::abs(q.c[0]);
  for (int k = 1; k <= q.degree; ++k) {
    hk *= h;
    sum += std::abs(q.c[k]) * hk;
  }
  // The shift's rounding: gamma(2n) relative to the coefficients' magnitudes about c.
  double scale = 0, ck = 1;
  for (int k = 0; k <= p.degree; ++k) {
    scale += std::abs(p.c[k]) * ck;
    ck *= std::abs(c) + h;
  }
  return mag > sum + gamma(4 * p.degree + 4) * scale;
}

// Roots of a quadratic in [lo, hi]: the vertex decides (a double root when p vanishes there to
// within rounding), then the cancellation-free pair q / a, c / q (Numerical Recipes 5.6),
// each polished by one Newton step.
int quadratic_roots(const Polynomial& p, double lo, double hi, double* out) {
  const double a = p.c[2], b = p.c[1], c = p.c[0];
  const double vertex = -b / (2 * a);
  double err;
  const double fv = evaluate(p, vertex, err);
  if (std::abs(fv) <= err) {
    if (!(vertex >= lo && vertex <= hi)) return 0;
    out[0] = vertex;
    return 1;
  }
  if (same_sign(fv, a)) return 0;
  const double four_ac = 4 * a * c;
  const double disc = std::max(std::fma(b, b, -four_ac) + std::fma(-4 * a, c, four_ac), 0.0);
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r[2] = {q / a, q != 0 ? c / q : vertex};
  if (r[0] > r[1]) std::swap(r[0], r[1]);
  int n = 0;
  for (double t : r) {
    double d, e;
    const double f = evaluate(p, t, d, e);
    if (std::abs(f) > e && d != 0) {
      const double polished = t - f / d;
      if (std::isfinite(polished)) t = polished;
    }
    if (t >= lo && t <= hi && (n == 0 || t > out[n - 1])) out[n++] = t;
  }
  return n;
}

// Roots of p in [lo, hi] (finite, lo <= hi), increasing; p is trimmed.
int roots_in(const Polynomial& p, double lo, double hi, double* out) {
  if (p.degree == 0) return 0;
  if (p.degree == 1) {
    const double t = -p.c[0] / p.c[1];
    if (!(t >= lo && t <= hi)) return 0;
    out[0] = t;
    return 1;
  }
  if (p.degree == 2) return quadratic_roots(p, lo, hi, out);
  // The critical points split [lo, hi] into monotone pieces.
  double points[kMaxPolynomialDegree + 1];
  const Polynomial dp = trimmed(derivative(p));
  int n_points = roots_in(dp, lo, hi, points);
  points[n_points++] = hi;

  int count = 0;
  double a = lo, ea;
  double fa = evaluate(p, a, ea);
  bool a_is_root = std::abs(fa) <= ea;
  if (a_is_root) out[count++] = a;
  for (int i = 0; i < n_points; ++i) {
    const double b = points[i];
    if (b <= a && i + 1 < n_points) continue;
    double eb;
    const double fb = evaluate(p, b, eb);
    const bool b_is_root = std::abs(fb) <= eb;
    if (!a_is_root && !b_is_root && !same_sign(fa, fb)) {
      const double t = refine_root(p, a, b, fa, fb);
      if (count == 0 || t > out[count - 1]) out[count++] = t;
    }
    if (b_is_root && (count == 0 || b > out[count - 1])) out[count++] = b;
    a = b;
    fa = fb;
    a_is_root = b_is_root;
  }
  return count;
}

// The Bernstein isolation gives up (and the derivative sequence decides) past this many halvings
// of the interval, or this many halvings in all per degree.
constexpr int kBernsteinMaxDepth = 12;
constexpr int kBernsteinSplitsPerDegree = 4;

// find_first_real_root's filter inside the isolation: roots there are in scaled units (t = u 2^e).
struct RootStop {
  const RootFilter* accept;
  int scale_exp = 0;
  bool stopped = false;
  bool takes(double u);
};

// The roots of p in [lo, hi] (lo < hi) when Descartes' rule of signs on the Bernstein form of
// halvings of [lo, hi] settles every piece: none in a piece whose coefficients allow no sign
// change; exactly one, simple, where they allow one and the piece's ends have certain opposite
// signs (refined as above). -1 when a piece stays unsettled within the caps (roots closer than
// the caps resolve, a multiple root, a root at an end or at a halving point): the caller then
// runs the derivative sequence on the whole interval, so those cases keep its behaviour.
// With a stop, each new root is offered to it (scaled back) as soon as it is refined, and the
// isolation ends at the first one it takes: every piece left of it is settled by then (depth
// first, left halves first), so it is the same root the full isolation reports there.
int bernstein_roots(const Polynomial& p, double lo, double hi, double* out, RootStop* stop) {
  const int n = p.degree;
  const double w = (hi - lo) * (1 + 4 * kMachineEpsilon);  // covers [lo, hi] despite rounding
  struct Piece {
    double a, b;
    int depth;
    BernsteinForm f;
  };
  Piece stack[kBernsteinMaxDepth + 2];  // depth first, left halves first: one right half per level
  int top = 0, count = 0, splits = 0;
  stack[0] = {lo, lo + w, 0, bernstein_form(p, lo, w)};
  while (top >= 0) {
    Piece& piece = stack[top];
    const BernsteinForm& f = piece.f;
    const int changes = max_sign_changes(f);
    if (changes == 0) {
      --top;
      continue;
    }
    const double f0 = f.b[0], fn = f.b[n];
    if (changes == 1 && std::abs(f0) > f.e[0] && std::abs(fn) > f.e[n]) {
      if (!same_sign(f0, fn)) {
        if (count == n) return -1;
        double t = refine_root(p, piece.a, piece.b, f0, fn);
        if (t > hi) {
          // The piece reaches past hi by the rounding of w: the root counts if p(hi) is within
          // its rounding of 0 or already has the far end's sign.
          double err;
          const double fh = evaluate(p, hi, err);
          if (std::abs(fh) > err && same_sign(fh, f0)) return count;
          t = hi;
        }
        if (count == 0 || t > out[count - 1]) {
          out[count++] = t;
          if (stop && stop->takes(t)) return count;
        }
      }
      --top;
      continue;
    }
    if (piece.depth >= kBernsteinMaxDepth || ++splits > kBernsteinSplitsPerDegree * n) return -1;
    // The right half replaces the piece, the left one goes on top of it.
    const double a = piece.a, m = 0.5 * (a + piece.b);
    const int depth = piece.depth + 1;
    Piece& left = stack[top + 1];
    bernstein_halves(f, left.f, piece.f);
    piece.a = m;
    piece.depth = depth;
    left.a = a;
    left.b = m;
    left.depth = depth;
    ++top;
  }
  return count;
}

// std::ilogb(x) without the libm call for normal x (the exponent field); others go to libm.
int exponent_of(double x) {
  const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
  if (biased == 0 || biased == 0x7ff) return std::ilogb(x);
  return biased - 1023;
}

// x 2^e, as std::ldexp(x, e) (one correctly rounded operation either way) without the libm call
// while 2^e is a normal double.
double scale2(double x, int e) {
  if (e < -1022 || e > 1023) return std::ldexp(x, e);
  return x * std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

// Fujiwara's bound on the magnitude of every complex root, 2 max |c_{n-i} / c_n|^(1/i) (the
// constant term's ratio halved), rounded up to powers of two so that no pow() is needed.
double root_bound(const Polynomial& p) {
  const int n = p.degree;
  int e = std::numeric_limits<int>::min();
  for (int i = 1; i <= n; ++i) {
    const double ratio = std::abs(p.c[n - i] / p.c[n]) * (i == n ? 0.5 : 1.0);
    if (ratio == 0) continue;
    if (!std::isfinite(ratio)) return kInfinity;
    // ratio < 2^(ilogb + 1), so ratio^(1/i) < 2^ceil((ilogb + 1) / i).
    const int k = exponent_of(ratio) + 1;
    const int root_exp = k >= 0 ? (k + i - 1) / i : -((-k) / i);
    e = std::max(e, root_exp);
  }
  if (e == std::numeric_limits<int>::min()) return 0;
  return scale2(2.0, e);
}

bool RootStop::takes(double u) {
  stopped = (*accept)(scale2(u, scale_exp));
  return stopped;
}

// find_real_roots, and find_first_real_root when stop is given (see bernstein_roots).
int solve(const Polynomial& p_in, double lo, double hi, double* roots, RootStop* stop) {
  if (std::isnan(lo) || std::isnan(hi) || lo > hi) return 0;
  for (int i = 0; i <= p_in.degree; ++i)
    if (!std::isfinite(p_in.c[i])) return 0;
  Polynomial p = trimmed(p_in);
  if (p.degree == 0) return 0;

  // Scale the coefficients so the largest is about 1 (exact: a power of two).
  double cmax = 0;
  for (int i = 0; i <= p.degree; ++i) cmax = std::max(cmax, std::abs(p.c[i]));
  const int ce = exponent_of(cmax);
  for (int i = 0; i <= p.degree; ++i) p.c[i] = scale2(p.c[i], -ce);

  // Clip the interval to the root bound, then scale the variable so the interval is about
  // [-1, 1]: t = s u with s a power of two, c_i -> c_i s^i.
  const double bound = root_bound(p);
  if (std::isfinite(bound)) {
    lo = std::max(lo, -bound * (1 + gamma(4)));
    hi = std::min(hi, bound * (1 + gamma(4)));
  }
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    lo = std::max(lo, -std::numeric_limits<double>::max());
    hi = std::min(hi, std::numeric_limits<double>::max());
  }
  if (lo > hi) return 0;
  const double extent = std::max(std::abs(lo), std::abs(hi));
  const int se = extent > 0 ? exponent_of(extent) : 0;
  if (se != 0) {
    for (int i = 1; i <= p.degree; ++i) p.c[i] = scale2(p.c[i], se * i);
    cmax = 0;
    for (int i = 0; i <= p.degree; ++i) cmax = std::max(cmax, std::abs(p.c[i]));
    if (!std::isfinite(cmax) || cmax == 0) return 0;
    const int ce2 = exponent_of(cmax);
    for (int i = 0; i <= p.degree; ++i) p.c[i] = scale2(p.c[i], -ce2);
    while (p.degree > 0 && p.c[p.degree] == 0) --p.degree;  // trimmed, in place
    if (p.degree == 0) return 0;
    lo = scale2(lo, -se);
    hi = scale2(hi, -se);
  }
  if (stop) stop->scale_exp = se;
  int n = p.degree >= 3 && lo < hi ? bernstein_roots(p, lo, hi, roots, stop) : -1;
  if (n < 0) n = certainly_no_root(p, lo, hi) ? 0 : roots_in(p, lo, hi, roots);
  for (int i = 0; i < n; ++i) roots[i] = scale2(roots[i], se);
  return n;
}

}  // namespace

int find_real_roots(const Polynomial& p, double lo, double hi, double* roots) {
  return solve(p, lo, hi, roots, nullptr);
}

bool find_first_real_root(const Polynomial& p, double lo, double hi, const RootFilter& accept,
                          double& root) {
  double roots[kMaxPolynomialDegree];
  RootStop stop{&accept};
  const int n = solve(p, lo, hi, roots, &stop);
  if (stop.stopped) {
    root = roots[n - 1];
    return true;
  }
  // The full isolation ran (or the derivative sequence): the roots in order.
  for (int i = 0; i < n; ++i)
    if (accept(roots[i])) {
      root = roots[i];
      return true;
    }
  return false;
}

int solve_cubic(double a, double b, double c, double d, double roots[3]) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d)) return 0;
  if (a == 0) {
    Polynomial q;
    q.degree = 2;
    q.c = {d, c, b};
    return find_real_roots(q, -kInfinity, kInfinity, roots);
  }
  // Depressed cubic x^3 + P x + Q with t = x - b / (3a).
  const double B = b / a, C = c / a, D = d / a;
  const double shift = B / 3;
  const double P = C - B * shift;
  const double Q = D - C * shift + 2 * shift * shift * shift;
  int n = 0;
  const double h = Q * Q / 4 + P * P * P / 27;
  if (P < 0 && h <= 0) {
    // Three real roots: x = 2 sqrt(-P/3) cos(theta/3 - 2 pi k / 3).
    const double m = 2 * std::sqrt(-P / 3);
    const double arg = std::clamp(3 * Q / (P * m), -1.0, 1.0);
    const double theta = std::acos(arg) / 3;
    for (int k = 0; k < 3; ++k)
      roots[n++] = m * std::cos(theta - 2 * std::numbers::pi * k / 3) - shift;
  } else {
    // One real root (Cardano), with the cube roots' signs chosen to avoid cancellation.
    const double s = std::sqrt(std::max(h, 0.0));
    const double u = std::cbrt(-Q / 2 + (Q < 0 ? s : -s));
    const double x = u == 0 ? 0 : u - P / (3 * u);
    roots[n++] = x - shift;
  }
  // Polish on the original cubic.
  Polynomial p;
  p.degree = 3;
  p.c = {d, c, b, a};
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 2; ++k) {
      double df, err;
      const double f = evaluate(p, roots[i], df, err);
      if (std::abs(f) <= err || df == 0) break;
      roots[i] -= f / df;
    }
  }
  std::sort(roots, roots + n);
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (m == 0 || roots[i] != roots[m - 1]) roots[m++] = roots[i];
  return m;
}

}  // namespace raycast
