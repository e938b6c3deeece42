// The lane kernel of math/formula_lanes.cpp, written once over W lanes: each including file
// (one per instruction set, docs/architecture.md "ISA dispatch") defines W and includes this
// inside its own namespace, after every header (so that no header code is compiled for a wider
// instruction set than the CPU's). Needs <algorithm>, <cmath>, <cstring>, <limits>, <numbers> and
// math/formula.h.

using DualI = Dual<Interval, 1>;
namespace {

// GCC's vector extension: W doubles, one SIMD register or a few (as wide as the target allows),
// and the lane masks comparisons give.
using V = double __attribute__((vector_size(8 * W)));
using M = long long __attribute__((vector_size(8 * W)));

// One stack slot: an inclusion of a value and of its t-derivative per lane.
struct Slot {
  V lo, hi, dlo, dhi;
};

DualI lane(const Slot& a, int k) {
  DualI r;
  r.v = {a.lo[k], a.hi[k]};
  r.d[0] = {a.dlo[k], a.dhi[k]};
  return r;
}
void set_lane(Slot& a, int k, const DualI& r) {
  a.lo[k] = r.v.lo;
  a.hi[k] = r.v.hi;
  a.dlo[k] = r.d[0].lo;
  a.dhi[k] = r.d[0].hi;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

V splat(double v) {
  V r;
  for (int k = 0; k < W; ++k) r[k] = v;
  return r;
}
V vabs(V x) { return x < 0 ? -x : x; }

// Whether every lane of m is set: one mask extraction where the including file says the target
// has AVX (RAYCAST_LANES_AVX), else lane by lane.
inline bool all_lanes(M m) {
#if defined(RAYCAST_LANES_AVX)
  return __builtin_ia32_movmskpd256(reinterpret_cast<V>(m)) == (1 << W) - 1;
#else
  for (int k = 0; k < W; ++k)
    if (!m[k]) return false;
  return true;
#endif
}

// [lo, hi] widened as interval_detail::widen(lo, hi): the branch-free form on every lane, then the
// rare lanes whose ends are infinite or NaN redone by the exact path; lanes where `empty` is set
// become empty.
inline void widen(V lo, V hi, M empty, V& rlo, V& rhi) {
  const V rel = splat(0x1p-52), tiny = splat(0x1p-1074), inf = splat(kInf);
  V l = lo - (vabs(lo) * rel + tiny), h = hi + (vabs(hi) * rel + tiny);
  const M ok = (l <= h) & (h - l < inf);
  if (!all_lanes(ok)) {
    for (int k = 0; k < W; ++k) {
      if (ok[k]) continue;
      const Interval r = interval_detail::widen(lo[k], hi[k], 1);
      l[k] = r.lo;
      h[k] = r.hi;
    }
  }
  rlo = empty ? inf : l;
  rhi = empty ? -inf : h;
}

inline M empty_of(V lo, V hi) { return ~(lo <= hi); }

// r = a + b (sub: a - b, i.e. a + (-b) with the same roundings), as Interval's operators.
inline void add(V alo, V ahi, V blo, V bhi, bool sub, V& rlo, V& rhi) {
  const M empty = empty_of(alo, ahi) | empty_of(blo, bhi);
  if (sub) {
    widen(alo + -bhi, ahi + -blo, empty, rlo, rhi);
  } else {
    widen(alo + blo, ahi + bhi, empty, rlo, rhi);
  }
}

inline V mul0(V a, V b) {
  const V zero = splat(0);
  return ((a == zero) | (b == zero)) ? zero : a * b;
}

// r = a * b, as Interval's operator* lane by lane (std::min_element / max_element order: the
// first of equal values wins).
// (Always inlined: as a call it passes its vectors through memory, ~15 % of the kernel's time.)
[[gnu::always_inline]] inline void mul(V alo, V ahi, V blo, V bhi, V& rlo, V& rhi) {
  const V p0 = mul0(alo, blo), p1 = mul0(alo, bhi), p2 = mul0(ahi, blo), p3 = mul0(ahi, bhi);
  V mn = p0, mx = p0;
  mn = p1 < mn ? p1 : mn;
  mx = mx < p1 ? p1 : mx;
  mn = p2 < mn ? p2 : mn;
  mx = mx < p2 ? p2 : mx;
  mn = p3 < mn ? p3 : mn;
  mx = mx < p3 ? p3 : mx;
  widen(mn, mx, empty_of(alo, ahi) | empty_of(blo, bhi), rlo, rhi);
}

// a^n for a whole n >= 1, as pow_int(Interval): for even n the range of |a| (from 0 when a holds
// it), the ends' powers by repeated multiplication (n - 1 roundings of half an ulp each), widened
// by 2 (n + kLibmUlps) steps of |x| 2^-52 + 2^-1074 (each at least an ulp; twice as many as ulps
// cover the larger ulps past a power of two), so at least the scalar's n + kLibmUlps ulps. Lanes
// whose powers are not finite take the scalar path.
inline void pow_lanes(V lo, V hi, int n, V& rlo, V& rhi) {
  const M empty = empty_of(lo, hi);
  const V zero = splat(0);
  if (n % 2 == 0) {
    const V alo = vabs(lo), ahi = vabs(hi);
    const V m = alo < ahi ? ahi : alo, l = alo < ahi ? alo : ahi;
    lo = ((lo <= zero) & (zero <= hi)) ? zero : l;
    hi = m;
  }
  V pl = lo, ph = hi;
  for (int k = 1; k < n; ++k) {
    pl = pl * lo;
    ph = ph * hi;
  }
  const V steps = splat(2.0 * (n + kLibmUlps));
  const V rel = splat(0x1p-52), tiny = splat(0x1p-1074), inf = splat(kInf);
  V l = pl - steps * (vabs(pl) * rel + tiny), h = ph + steps * (vabs(ph) * rel + tiny);
  if (n % 2 == 0) l = l < zero ? zero : l;
  const M ok = (l <= h) & (h - l < inf) & (vabs(pl) < inf) & (vabs(ph) < inf);
  if (!all_lanes(ok | empty)) {
    for (int k = 0; k < W; ++k) {
      if (ok[k] || empty[k]) continue;
      const Interval r = pow_int(Interval{lo[k], hi[k]}, n);
      l[k] = r.lo;
      h[k] = r.hi;
    }
  }
  rlo = empty ? inf : l;
  rhi = empty ? -inf : h;
}

// Dual power: v = a.v^n, d = (n a.v^(n-1)) a.d, as pow_int(Dual) does.
inline void dual_pow(Slot& a, int n) {
  V pl, ph, ql, qh, sl, sh, dl, dh;
  pow_lanes(a.lo, a.hi, n, pl, ph);
  pow_lanes(a.lo, a.hi, n - 1, ql, qh);
  mul(splat(n), splat(n), ql, qh, sl, sh);
  mul(sl, sh, a.dlo, a.dhi, dl, dh);
  a = {pl, ph, dl, dh};
}

// Dual product: v = a.v b.v, d = a.d b.v + a.v b.d.
inline void dual_mul(const Slot& a, const Slot& b, Slot& r) {
  V l1, h1, l2, h2, vl, vh;
  mul(a.dlo, a.dhi, b.lo, b.hi, l1, h1);
  mul(a.lo, a.hi, b.dlo, b.dhi, l2, h2);
  mul(a.lo, a.hi, b.lo, b.hi, vl, vh);
  add(l1, h1, l2, h2, false, r.dlo, r.dhi);
  r.lo = vl;
  r.hi = vh;
}

inline void dual_add(const Slot& a, const Slot& b, bool sub, Slot& r) {
  V l, h, dl, dh;
  add(a.lo, a.hi, b.lo, b.hi, sub, l, h);
  add(a.dlo, a.dhi, b.dlo, b.dhi, sub, dl, dh);
  r = {l, h, dl, dh};
}

// [lo, hi] widened by at least kLibmUlps + 1 ulps each side (libm's error and the rounding of
// the e terms below) without stepping bit patterns: as in interval_detail::widen, |x| 2^-52 +
// 2^-1074 is at least one ulp of x, and twice as many such steps as ulps are needed cover the
// larger ulps past a power of two. Values here are finite and within [-2, 2].
// Then clamped to [-1, 1] (std::max(lo, -1), std::min(hi, 1)): on every lane.
inline void widen_ulps_clamped(V lo, V hi, V& rlo, V& rhi) {
  const V steps = splat(2 * (kLibmUlps + 1)), ulp = splat(0x1p-52), tiny = splat(0x1p-1074);
  const V one = splat(1), minus_one = splat(-1);
  lo = lo - steps * (vabs(lo) * ulp + tiny);
  hi = hi + steps * (vabs(hi) * ulp + tiny);
  rlo = lo < minus_one ? minus_one : lo;
  rhi = one < hi ? one : hi;
}

// sin and cos of W points at once, each within kLaneSinCosError of the exact values (the bound
// is derived in formula_lanes.h). Reduction by the nearest multiple n of pi/2 in three exact
// steps (Cody and Waite: the first two parts of pi/2 have 33 bits each, so n * part is exact for
// |n| < 2^20, and the first difference is exact by Sterbenz's lemma; the third part is the rest
// to full precision), then Taylor polynomials on |r| <= 0.786
// (sin to r^15, cos to r^16), then the quadrant. Lanes with |x| > 2^19 (or not finite) take
// libm's sincos (within kLibmUlps ulps). Elementwise IEEE operations without contraction: the
// same bits for every width.
[[gnu::always_inline]] inline void sincos_points(V x, V& s, V& c) {
  constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double kPio2_1 = 0x1.921fb544p+0;  // 33 bits of pi/2, then the next 33, and so on
  constexpr double kPio2_2 = 0x1.0b4611a6p-34;
  constexpr double kPio2_3 = 0x1.3198a2e037073p-69;
  constexpr double kRound = 0x1.8p52;  // adding it rounds |q| < 2^51 to a whole number
  const V q = x * splat(kTwoOverPi) + splat(kRound);
  const V n = q - splat(kRound);
  const M quadrant = (M)q & 3;
  const V r = ((x - n * splat(kPio2_1)) - n * splat(kPio2_2)) - n * splat(kPio2_3);
  const V z = r * r;
  // sin r = r + r z P(z), cos r = 1 - z / 2 + z^2 Q(z), Horner in z.
  V p = splat(-1.0 / 1307674368000.0);
  p = p * z + splat(1.0 / 6227020800.0);
  p = p * z + splat(-1.0 / 39916800.0);
  p = p * z + splat(1.0 / 362880.0);
  p = p * z + splat(-1.0 / 5040.0);
  p = p * z + splat(1.0 / 120.0);
  p = p * z + splat(-1.0 / 6.0);
  const V sr = r + (r * z) * p;
  V qc = splat(1.0 / 20922789888000.0);
  qc = qc * z + splat(-1.0 / 87178291200.0);
  qc = qc * z + splat(1.0 / 479001600.0);
  qc = qc * z + splat(-1.0 / 3628800.0);
  qc = qc * z + splat(1.0 / 40320.0);
  qc = qc * z + splat(-1.0 / 720.0);
  qc = qc * z + splat(1.0 / 24.0);
  const V cr = (splat(1.0) - splat(0.5) * z) + (z * z) * qc;
  // x = n pi/2 + r: quadrant 1 swaps and negates the sine's source, 2 negates both, 3 the cosine.
  const M odd = (quadrant & 1) != 0;
  const V sv = odd ? cr : sr, cv = odd ? sr : cr;
  const M sneg = (quadrant == 2) | (quadrant == 3), cneg = (quadrant == 1) | (quadrant == 2);
  s = sneg ? -sv : sv;
  c = cneg ? -cv : cv;
  const M ok = vabs(x) <= splat(0x1p19);
  if (!all_lanes(ok)) {
    for (int k = 0; k < W; ++k) {
      if (ok[k]) continue;
      double sk, ck;  // (a vector element has no address)
      interval_detail::sincos(x[k], &sk, &ck);
      s[k] = sk;
      c[k] = ck;
    }
  }
}

// std::ceil on every lane: one vector rounding where the including file says the target has it
// (RAYCAST_LANES_AVX: upward, no inexact exception, the instruction std::ceil compiles to
// there, on all lanes at once).
inline V vceil(V x) {
#if defined(RAYCAST_LANES_AVX)
  return __builtin_ia32_roundpd256(x, 0x0A);
#else
  for (int k = 0; k < W; ++k) x[k] = std::ceil(x[k]);
  return x;
#endif
}

// interval_detail::hits_phase on every lane: the same operations elementwise.
inline M hits_phase_lanes(V lo, V hi, double c, double period) {
  const V k = vceil((lo - splat(c)) / splat(period) - splat(1e-9));
  return splat(c) + k * splat(period) <= hi + splat(1e-9) * (splat(1) + vabs(hi));
}

// std::min(a, b) and std::max(a, b) elementwise (the first argument on ties).
inline V vmin(V a, V b) { return b < a ? b : a; }
inline V vmax(V a, V b) { return a < b ? b : a; }

// sin and cos of variable lanes `x` whose intervals run between the points p[k], p[k + 1]
// (give or take the rounding of the intervals' ends), from sincos of those points.
// s[j], c[j]: sin and cos of p[j]. Every lane by the same elementwise operations as the scalar
// form (Interval's sin_cos bounds from the points' values, widened by their distance to the
// interval's ends, the extrema by hits_phase); empty lanes and lanes of a period or more are
// then set as that form sets them.
void sin_cos_var(const Slot& x, const double p[W + 1], const double* s, const double* c,
                 Slot& sin_x, Slot& cos_x) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  constexpr double kHalfPi = std::numbers::pi / 2;
  V p0, p1, s0, s1, c0, c1;
  for (int k = 0; k < W; ++k) {
    p0[k] = p[k];
    p1[k] = p[k + 1];
    s0[k] = s[k];
    s1[k] = s[k + 1];
    c0[k] = c[k];
    c1[k] = c[k + 1];
  }
  const V lo = x.lo, hi = x.hi, zero = splat(0), one = splat(1), minus_one = splat(-1);
  const V pmin = vmin(p0, p1), pmax = vmax(p0, p1);
  // Every point of x lies within e of [pmin, pmax] (e rounded up); as std::max({0, a, b}).
  V far = zero;
  far = vmax(far, pmin - lo);
  far = vmax(far, hi - pmax);
  const V e = far * splat(1 + 0x1p-50) + splat(0x1p-1074) + splat(kLaneSinCosError);
  V slo = vmin(s0, s1) - e, shi = vmax(s0, s1) + e;
  shi = hits_phase_lanes(lo, hi, kHalfPi, kTwoPi) ? one : shi;
  slo = hits_phase_lanes(lo, hi, -kHalfPi, kTwoPi) ? minus_one : slo;
  widen_ulps_clamped(slo, shi, sin_x.lo, sin_x.hi);
  V clo = vmin(c0, c1) - e, chi = vmax(c0, c1) + e;
  chi = hits_phase_lanes(lo, hi, 0, kTwoPi) ? one : chi;
  clo = hits_phase_lanes(lo, hi, std::numbers::pi, kTwoPi) ? minus_one : clo;
  widen_ulps_clamped(clo, chi, cos_x.lo, cos_x.hi);
  const M empty = ~(lo <= hi);
  const M whole = ~(hi - lo < splat(kTwoPi)) | (vabs(lo) > splat(1e15)) | (vabs(hi) > splat(1e15));
  sin_x.lo = empty ? lo : (whole ? minus_one : sin_x.lo);
  sin_x.hi = empty ? hi : (whole ? one : sin_x.hi);
  cos_x.lo = empty ? lo : (whole ? minus_one : cos_x.lo);
  cos_x.hi = empty ? hi : (whole ? one : cos_x.hi);
  // The derivatives cos(x) x' and -sin(x) x' on all lanes at once (mul is Interval's operator*
  // lane by lane, so the same bits as the one-interval form).
  mul(cos_x.lo, cos_x.hi, x.dlo, x.dhi, sin_x.dlo, sin_x.dhi);
  mul(-sin_x.hi, -sin_x.lo, x.dlo, x.dhi, cos_x.dlo, cos_x.dhi);
}

// sin (or cos) of lanes `a` whatever their argument: Interval's sin_cos lane by lane, with the
// ends' sines and cosines from sincos_points (so each bound also moves out by kLaneSinCosError),
// then the chain rule's product on all lanes. As vector code: the same elementwise operations on
// every lane, empty and whole-period lanes set by masks.
void sin_or_cos_lanes(Slot& a, bool want_sin) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  constexpr double kHalfPi = std::numbers::pi / 2;
  const V lo = a.lo, hi = a.hi, one = splat(1), minus_one = splat(-1),
          err = splat(kLaneSinCosError);
  V s0, c0, s1, c1;
  sincos_points(lo, s0, c0);
  sincos_points(hi, s1, c1);
  V slo = vmin(s0, s1) - err, shi = vmax(s0, s1) + err;
  shi = hits_phase_lanes(lo, hi, kHalfPi, kTwoPi) ? one : shi;
  slo = hits_phase_lanes(lo, hi, -kHalfPi, kTwoPi) ? minus_one : slo;
  V clo = vmin(c0, c1) - err, chi = vmax(c0, c1) + err;
  chi = hits_phase_lanes(lo, hi, 0, kTwoPi) ? one : chi;
  clo = hits_phase_lanes(lo, hi, std::numbers::pi, kTwoPi) ? minus_one : clo;
  V sil, sih, cil, cih;
  widen_ulps_clamped(slo, shi, sil, sih);
  widen_ulps_clamped(clo, chi, cil, cih);
  const M empty = ~(lo <= hi);
  const M whole = ~(hi - lo < splat(kTwoPi)) | (vabs(lo) > splat(1e15)) | (vabs(hi) > splat(1e15));
  const V inf = splat(kInf);
  // Interval::empty() for empty lanes; [-1, 1] for whole ones.
  sil = empty ? inf : (whole ? minus_one : sil);
  sih = empty ? -inf : (whole ? one : sih);
  cil = empty ? inf : (whole ? minus_one : cil);
  cih = empty ? -inf : (whole ? one : cih);
  // The result, and the derivative's factor: cos for sin, -sin for cos.
  const V rlo = want_sin ? sil : cil, rhi = want_sin ? sih : cih;
  const V glo = want_sin ? cil : -sih, ghi = want_sin ? cih : -sil;
  V dlo, dhi;
  mul(glo, ghi, a.dlo, a.dhi, dlo, dhi);
  a = {rlo, rhi, dlo, dhi};
}

// The operations without a lane form: each lane through Dual<Interval, 1>, as run() does.
DualI unary(Opcode op, const DualI& a, int n) {
  switch (op) {
    case Opcode::kPowInt:
      return pow_int(a, n);
    case Opcode::kSqrt:
      return sqrt(a);
    case Opcode::kExp:
      return exp(a);
    case Opcode::kLog:
      return log(a);
    case Opcode::kSin:
      return sin(a);
    case Opcode::kCos:
      return cos(a);
    case Opcode::kTan:
      return tan(a);
    case Opcode::kAbs:
      return abs(a);
    case Opcode::kFloor:
      return floor(a);
    default:
      return a;
  }
}
DualI binary(Opcode op, const DualI& a, const DualI& b) {
  switch (op) {
    case Opcode::kDiv:
      return a / b;
    case Opcode::kPow:
      return pow(a, b);
    case Opcode::kMin:
      return min(a, b);
    case Opcode::kMax:
      return max(a, b);
    case Opcode::kAtan2:
      return atan2(a, b);
    default:
      return a;
  }
}

}  // namespace

void sin_cos_point(double x, double* s, double* c) {
  V sv, cv;
  sincos_points(splat(x), sv, cv);
  *s = sv[0];
  *c = cv[0];
}

// The W lanes [t[k], t[k + 1]]: see run_lanes in formula_lanes.h. s[v], c[v] hold sin and cos of
// variable v at the W + 1 points; the last are given when last_known, the others are computed
// here (the first too when given: a caller's values are lane_sin_cos of the same point, so the
// same bits, and all W lanes stored at once are cheaper than skipping one).
void lanes_kernel(const Formula& f, const double o[3], const double d[3], const double* t,
                  bool last_known, double* const s_of[3], double* const c_of[3], double* out_lo,
                  double* out_hi, double* out_dlo, double* out_dhi) {
  // The variables as f_over builds them: Interval(o) + [t_k, t_k+1] * Interval(d), derivative d.
  Slot var[3];
  V tlo, thi;
  for (int k = 0; k < W; ++k) {
    tlo[k] = t[k];
    thi[k] = t[k + 1];
  }
  for (int v = 0; v < 3; ++v) {
    V ml, mh;
    mul(tlo, thi, splat(d[v]), splat(d[v]), ml, mh);
    add(splat(o[v]), splat(o[v]), ml, mh, false, var[v].lo, var[v].hi);
    var[v].dlo = var[v].dhi = splat(d[v]);
  }
  Slot sin_var[3], cos_var[3];
  if (f.trig_vars) {
    for (int v = 0; v < 3; ++v) {
      if (!(f.trig_vars & (1u << v))) continue;
      double p[W + 1];
      for (int j = 0; j <= W; ++j) p[j] = o[v] + t[j] * d[v];
      double* sv = s_of[v];
      double* cv = c_of[v];
      V x, sx, cx;
      for (int j = 0; j < W; ++j) x[j] = p[j];
      sincos_points(x, sx, cx);
      for (int j = 0; j < W; ++j) {
        sv[j] = sx[j];
        cv[j] = cx[j];
      }
      if (!last_known) {
        sincos_points(splat(p[W]), sx, cx);
        sv[W] = sx[0];
        cv[W] = cx[0];
      }
      sin_cos_var(var[v], p, sv, cv, sin_var[v], cos_var[v]);
    }
  }
  Slot s[kMaxFormulaStack];
  int top = -1;
  for (const Instruction& in : f.code) {
    switch (in.op) {
      case Opcode::kConst:
        ++top;
        s[top].lo = s[top].hi = splat(in.value);
        s[top].dlo = s[top].dhi = splat(0);
        break;
      case Opcode::kX:
      case Opcode::kY:
      case Opcode::kZ:
        s[++top] = var[static_cast<int>(in.op) - static_cast<int>(Opcode::kX)];
        break;
      case Opcode::kSinVar:
        s[++top] = sin_var[in.n];
        break;
      case Opcode::kCosVar:
        s[++top] = cos_var[in.n];
        break;
      case Opcode::kAdd:
        dual_add(s[top - 1], s[top], false, s[top - 1]);
        --top;
        break;
      case Opcode::kSub:
        dual_add(s[top - 1], s[top], true, s[top - 1]);
        --top;
        break;
      case Opcode::kMul:
        dual_mul(s[top - 1], s[top], s[top - 1]);
        --top;
        break;
      case Opcode::kNeg: {
        Slot& a = s[top];
        a = {-a.hi, -a.lo, -a.dhi, -a.dlo};
        break;
      }
      case Opcode::kPowInt:
        if (in.n >= 2) {
          dual_pow(s[top], in.n);
        } else {
          for (int k = 0; k < W; ++k) set_lane(s[top], k, unary(in.op, lane(s[top], k), in.n));
        }
        break;
      case Opcode::kSin:
      case Opcode::kCos:
        sin_or_cos_lanes(s[top], in.op == Opcode::kSin);
        break;
      case Opcode::kDiv:
      case Opcode::kPow:
      case Opcode::kMin:
      case Opcode::kMax:
      case Opcode::kAtan2:
        for (int k = 0; k < W; ++k)
          set_lane(s[top - 1], k, binary(in.op, lane(s[top - 1], k), lane(s[top], k)));
        --top;
        break;
      case Opcode::kNoise:
        for (int k = 0; k < W; ++k)
          set_lane(s[top - 2], k,
                   noise_of(lane(s[top - 2], k), lane(s[top - 1], k), lane(s[top], k), in.n));
        top -= 2;
        break;
      default:
        for (int k = 0; k < W; ++k) set_lane(s[top], k, unary(in.op, lane(s[top], k), in.n));
        break;
    }
  }
  // (Whole vectors copied: lane by lane, the compiler moves each element alone.)
  std::memcpy(out_lo, &s[0].lo, sizeof(V));
  std::memcpy(out_hi, &s[0].hi, sizeof(V));
  std::memcpy(out_dlo, &s[0].dlo, sizeof(V));
  std::memcpy(out_dhi, &s[0].dhi, sizeof(V));
}
