// run_lanes (several t-intervals per pass of a formula's bytecode): every lane holds f and df/dt
// sampled densely over its interval, equals run<Dual<Interval, 1>> bit for bit where no sin or
// cos of a bare variable and no whole power is involved (and is as tight within 1e-12 where one
// is), and the 2-lane and 4-lane kernels give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/ray.h"
#include "math/formula_lanes.h"
#include "math/formula_lanes_kernels.h"

namespace raycast {

namespace {

constexpr int W = kFormulaLanes;

const char* const kFormulas[] = {
    "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
    "(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)",
    "(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3",
    ("sqrt(x^2 + y^2 + 1) - log(z + 5) + min(x, y) * max(y, z) / (2 + abs(z)) + tan(0.1 * x) + "
     "pow(x^2 + 1, 0.5) + exp(-y) - 3"),
    "-x - (y - z) * 1e-3",
    "x*y - z*x + 0.5*y*y - 1 - x / (2 + z*z) + sqrt(abs(y))",
    "sin(x * y + 3) - cos(0.25 * z - x) * sin(2 * z) + cos(x * y * z)",
};

struct RaySetup {
  double o[3], d[3], t[W + 1];
};

RaySetup random_setup(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  RaySetup s;
  for (int i = 0; i < 3; ++i) {
    s.o[i] = 3 * u(rng);
    s.d[i] = u(rng);
  }
  const double a = 2 * u(rng), width = std::pow(10.0, -4 * (u(rng) + 1));  // 1e-8 .. 1
  for (int k = 0; k <= W; ++k) s.t[k] = a + width * k / W;
  return s;
}

// Lanes compute sin and cos and whole powers their own way (tested for tightness); every other
// operation as the one-interval evaluation, bit for bit.
bool computed_alike(const Formula& f) {
  if (f.trig_vars != 0) return false;
  for (const Instruction& in : f.code)
    if (in.op == Opcode::kPowInt || in.op == Opcode::kSin || in.op == Opcode::kCos) return false;
  return true;
}

TEST(FormulaLanes, LanesHoldSampledValuesAndMatchTheScalarInclusion) {
  for (const char* text : kFormulas) {
    SCOPED_TRACE(text);
    const Formula f = compile_formula(text);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 300; ++trial) {
      SCOPED_TRACE(trial);
      const RaySetup s = random_setup(rng);
      FormulaLanes out;
      LaneTrig trig;
      run_lanes(f, s.o, s.d, s.t, out, &trig);
      for (int k = 0; k < W; ++k) {
        // The scalar inclusion over the same interval, built as the implicit search used to.
        const Interval t{s.t[k], s.t[k + 1]};
        Dual<Interval, 1> c[3];
        for (int i = 0; i < 3; ++i) {
          c[i].v = Interval(s.o[i]) + t * Interval(s.d[i]);
          c[i].d[0] = Interval(s.d[i]);
        }
        const Dual<Interval, 1> ref = run<Dual<Interval, 1>>(f, c[0], c[1], c[2]);
        if (ref.v.is_empty()) {
          EXPECT_FALSE(out.lo[k] <= out.hi[k]);
          continue;
        }
        if (computed_alike(f)) {
          EXPECT_EQ(out.lo[k], ref.v.lo);
          EXPECT_EQ(out.hi[k], ref.v.hi);
          EXPECT_EQ(out.dlo[k], ref.d[0].lo);
          EXPECT_EQ(out.dhi[k], ref.d[0].hi);
        } else {
          const double tol = 1e-12 * (1 + std::abs(ref.v.lo) + std::abs(ref.v.hi));
          EXPECT_NEAR(out.lo[k], ref.v.lo, tol);
          EXPECT_NEAR(out.hi[k], ref.v.hi, tol);
          const double dtol = 1e-12 * (1 + std::abs(ref.d[0].lo) + std::abs(ref.d[0].hi));
          EXPECT_NEAR(out.dlo[k], ref.d[0].lo, dtol);
          EXPECT_NEAR(out.dhi[k], ref.d[0].hi, dtol);
        }
        // Samples of f and df/dt in double lie inside (their own rounding is far below the
        // inclusions' widening, but allow a few ulps of it).
        for (int j = 0; j <= 40; ++j) {
          const double tj = s.t[k] + (s.t[k + 1] - s.t[k]) * j / 40;
          Dual<double, 1> p[3];
          for (int i = 0; i < 3; ++i) {
            p[i] = Dual<double, 1>(s.o[i] + tj * s.d[i]);
            p[i].d[0] = s.d[i];
          }
          const Dual<double, 1> v = run<Dual<double, 1>>(f, p[0], p[1], p[2]);
          if (!std::isfinite(v.v)) continue;
          const double slack = 4e-16 * (1 + std::abs(v.v));
          EXPECT_LE(out.lo[k] - slack, v.v);
          EXPECT_GE(out.hi[k] + slack, v.v);
          const double dslack = 4e-16 * (1 + std::abs(v.d[0]));
          EXPECT_LE(out.dlo[k] - dslack, v.d[0]);
          EXPECT_GE(out.dhi[k] + dslack, v.d[0]);
        }
      }
    }
  }
}

// The AVX2 kernel (4 lanes, one pass) and the baseline one (2 lanes, two passes) agree bit for
// bit, also when the ends' sines are passed in; skipped where the CPU lacks AVX2.
// The scalar form the lanes' sin and cos of a variable follow (the one the kernel had before it
// ran them as vectors): each lane's interval of x, the points' sin and cos (lane_sin_cos), widened
// by the interval's distance to the points, the extrema by hits_phase, widened by kLibmUlps + 1
// ulps, clamped; a lane of a period or more is [-1, 1].
// sin_of_any: the ends of a are the points (sin and cos of any argument: e is the lanes' error
// alone, an empty lane is Interval::empty()).
void scalar_sin_cos_var(const Interval& a, double p0, double p1, Interval& si, Interval& ci,
                        bool sin_of_any = false) {
  using interval_detail::hits_phase;
  constexpr double kTwoPi = 2 * std::numbers::pi;
  if (a.is_empty()) {
    si = ci = sin_of_any ? Interval::empty() : a;
    return;
  }
  if (!(a.hi - a.lo < kTwoPi) || std::abs(a.lo) > 1e15 || std::abs(a.hi) > 1e15) {
    si = ci = {-1, 1};
    return;
  }
  double s0, c0, s1, c1;
  lane_sin_cos(p0, &s0, &c0);
  lane_sin_cos(p1, &s1, &c1);
  const double pmin = std::min(p0, p1), pmax = std::max(p0, p1);
  const double e = sin_of_any ? kLaneSinCosError
                              : std::max({0.0, pmin - a.lo, a.hi - pmax}) * (1 + 0x1p-50) +
                                    0x1p-1074 + kLaneSinCosError;
  auto finish = [](double lo, double hi) {
    constexpr double kSteps = 2 * (kLibmUlps + 1);
    lo -= kSteps * (std::abs(lo) * 0x1p-52 + 0x1p-1074);
    hi += kSteps * (std::abs(hi) * 0x1p-52 + 0x1p-1074);
    return Interval{std::max(lo, -1.0), std::min(hi, 1.0)};
  };
  double lo = std::min(s0, s1) - e, hi = std::max(s0, s1) + e;
  if (hits_phase(a.lo, a.hi, std::numbers::pi / 2, kTwoPi)) hi = 1;
  if (hits_phase(a.lo, a.hi, -std::numbers::pi / 2, kTwoPi)) lo = -1;
  si = finish(lo, hi);
  lo = std::min(c0, c1) - e;
  hi = std::max(c0, c1) + e;
  if (hits_phase(a.lo, a.hi, 0, kTwoPi)) hi = 1;
  if (hits_phase(a.lo, a.hi, std::numbers::pi, kTwoPi)) lo = -1;
  ci = finish(lo, hi);
}

// Lane k's value and derivative bounds are v's and dv's, bit for bit.
void expect_lane_bits(const FormulaLanes& out, int k, const Interval& v, const Interval& dv) {
  EXPECT_EQ(out.lo[k], v.lo) << k;
  EXPECT_EQ(out.hi[k], v.hi) << k;
  EXPECT_EQ(out.dlo[k], dv.lo) << k;
  EXPECT_EQ(out.dhi[k], dv.hi) << k;
}

// The lanes' ends t[0..W]: t[k] = k / W of a width from 1e-12 to about 40, plus its own random
// offset in (-1, 1) (lanes of any order and length) or, `at_zero`, none (W equal lanes from 0).
void lane_ends(std::uniform_real_distribution<double>& u, std::mt19937& rng, bool at_zero,
               double* t) {
  const double width = std::pow(10.0, -12 + 13.6 * std::abs(u(rng)));
  for (int k = 0; k <= W; ++k) t[k] = (at_zero ? 0 : u(rng)) + width * k / W;
}

// The vector form of sin and cos of a variable gives the scalar form's bits on every lane: lanes
// of 1e-12 to 40 in t (tiny, across extrema, more than a period), points up to 1e16 (past the
// reduction's range and past 1e15, where a lane is [-1, 1]), lanes starting exactly at extrema.
// The implicit search takes a part's certain sign as the sign of f at the part's ends as it
// evaluates f there (run<double> at ray.at(t)): that value must lie inside the lane's bounds
// exactly, no slack (every operation's rounding falls inside the bounds' outward widening).
// Random lines and widths, and lines through a zero of f (values near 0, where a sign matters).
TEST(FormulaLanes, PointValuesAtLaneEnds_InsideTheLaneExactly) {
  int checked = 0, small = 0;
  for (const char* text : kFormulas) {
    SCOPED_TRACE(text);
    const Formula f = compile_formula(text);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
      RaySetup s = random_setup(rng);
      const Ray ray{{s.o[0], s.o[1], s.o[2]}, {s.d[0], s.d[1], s.d[2]}};
      auto value = [&](double t) {
        const Vec3 p = ray.at(t);
        return run<double>(f, p.x, p.y, p.z);
      };
      if (trial % 2 == 1) {  // move the lanes onto a sign change of f along the line, if any
        double a = s.t[0] - 1, b = s.t[W] + 1;
        if ((value(a) < 0) == (value(b) < 0)) continue;
        for (int i = 0; i < 200 && a < b; ++i) {
          const double m = 0.5 * (a + b);
          if (!(m > a && m < b)) break;
          ((value(m) < 0) == (value(a) < 0) ? a : b) = m;
        }
        const double w = s.t[W] - s.t[0];
        const int k0 = static_cast<int>(unit(rng) * (W + 1)) % (W + 1);
        for (int k = 0; k <= W; ++k) s.t[k] = a + w * (k - k0) / W;
      }
      FormulaLanes out;
      LaneTrig trig;
      run_lanes(f, s.o, s.d, s.t, out, &trig);
      for (int k = 0; k < W; ++k) {
        if (!(out.lo[k] <= out.hi[k])) continue;  // undefined there
        for (const double t : {s.t[k], s.t[k + 1]}) {
          const double v = value(t);
          if (std::isnan(v)) continue;
          ++checked;
          small += std::abs(v) < 1e-12;
          ASSERT_LE(out.lo[k], v) << "trial " << trial << " lane " << k;
          ASSERT_GE(out.hi[k], v) << "trial " << trial << " lane " << k;
        }
      }
    }
  }
  EXPECT_GT(checked, 50000);
  EXPECT_GT(small, 200);
}

TEST(FormulaLanes, SinCosOfAVariable_BitEqualToTheScalarForm) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const char* text : {"sin(x)", "cos(x)"}) {
    SCOPED_TRACE(text);
    const Formula f = compile_formula(text);
    ASSERT_NE(f.trig_vars, 0u);
    const bool want_sin = text[0] == 's';
    for (int trial = 0; trial < 4000; ++trial) {
      SCOPED_TRACE(trial);
      double o[3] = {0, 0, 0}, d[3] = {0, 0, 0}, t[W + 1];
      const double scale = std::pow(10.0, 16 * std::abs(u(rng)));
      o[0] = trial % 7 == 0 ? std::numbers::pi / 2 * std::round(8 * u(rng)) : scale * u(rng);
      d[0] = trial % 11 == 0 ? 1 : u(rng);
      lane_ends(u, rng, trial % 7 == 0, t);
      FormulaLanes out;
      LaneTrig lt;
      run_lanes(f, o, d, t, out, &lt);
      for (int k = 0; k < W; ++k) {
        const Interval a = Interval{o[0], o[0]} + Interval{t[k], t[k + 1]} * Interval{d[0], d[0]};
        Interval si, ci;
        scalar_sin_cos_var(a, o[0] + t[k] * d[0], o[0] + t[k + 1] * d[0], si, ci);
        const Interval v = want_sin ? si : ci;
        const Interval dv = (want_sin ? ci : -si) * Interval{d[0], d[0]};
        expect_lane_bits(out, k, v, dv);
      }
    }
  }
}

// The same for sin and cos of any argument (here x + y): the argument's lanes as Interval's and
// Dual's + give them, the ends' sin and cos from the lanes' own sincos.
TEST(FormulaLanes, SinCosOfAnyArgument_BitEqualToTheScalarForm) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const char* text : {"sin(x + y)", "cos(x + y)"}) {
    SCOPED_TRACE(text);
    const Formula f = compile_formula(text);
    ASSERT_EQ(f.trig_vars, 0u);
    const bool want_sin = text[0] == 's';
    for (int trial = 0; trial < 4000; ++trial) {
      SCOPED_TRACE(trial);
      double o[3] = {0, 0, 0}, d[3] = {0, 0, 0}, t[W + 1];
      const double scale = std::pow(10.0, 16 * std::abs(u(rng)));
      for (int v = 0; v < 2; ++v) {
        o[v] = trial % 7 == 0 ? std::numbers::pi / 4 * std::round(8 * u(rng)) : scale * u(rng);
        d[v] = trial % 11 == 0 ? 0.5 : u(rng);
      }
      lane_ends(u, rng, trial % 7 == 0, t);
      FormulaLanes out;
      LaneTrig lt;
      run_lanes(f, o, d, t, out, &lt);
      for (int k = 0; k < W; ++k) {
        const Interval tk{t[k], t[k + 1]};
        const Interval a = (Interval{o[0], o[0]} + tk * Interval{d[0], d[0]}) +
                           (Interval{o[1], o[1]} + tk * Interval{d[1], d[1]});
        const Interval da = Interval{d[0], d[0]} + Interval{d[1], d[1]};
        Interval si, ci;
        scalar_sin_cos_var(a, a.lo, a.hi, si, ci, true);
        const Interval v = want_sin ? si : ci;
        const Interval dv = (want_sin ? ci : -si) * da;
        expect_lane_bits(out, k, v, dv);
      }
    }
  }
}

TEST(FormulaLanes, TwoAndFourLaneKernelsAgree) {
  if (!run_lanes_avx2()) GTEST_SKIP() << "no AVX2 on this CPU (or RAYCAST_ISA narrower)";
  for (const char* text : kFormulas) {
    SCOPED_TRACE(text);
    const Formula f = compile_formula(text);
    std::mt19937 rng(9);
    for (int trial = 0; trial < 200; ++trial) {
      const RaySetup s = random_setup(rng);
      double s4[3][W + 1], c4[3][W + 1], s2[3][W + 1], c2[3][W + 1];
      for (int v = 0; v < 3; ++v) {
        for (int j : {0, W}) {
          const double p = s.o[v] + s.t[j] * s.d[v];
          lane_sin_cos(p, &s4[v][j], &c4[v][j]);  // given ends are the lanes' own values
          s2[v][j] = s4[v][j];
          c2[v][j] = c4[v][j];
        }
      }
      const bool known = trial % 2 == 1;
      double* ps4[3] = {s4[0], s4[1], s4[2]};
      double* pc4[3] = {c4[0], c4[1], c4[2]};
      FormulaLanes a, b;
      lanes_w4::lanes_kernel(f, s.o, s.d, s.t, known, ps4, pc4, a.lo, a.hi, a.dlo, a.dhi);
      double* ps2[3] = {s2[0], s2[1], s2[2]};
      double* pc2[3] = {c2[0], c2[1], c2[2]};
      lanes_w2::lanes_kernel(f, s.o, s.d, s.t, false, ps2, pc2, b.lo, b.hi, b.dlo, b.dhi);
      double* qs2[3] = {s2[0] + 2, s2[1] + 2, s2[2] + 2};
      double* qc2[3] = {c2[0] + 2, c2[1] + 2, c2[2] + 2};
      lanes_w2::lanes_kernel(f, s.o, s.d, s.t + 2, known, qs2, qc2, b.lo + 2, b.hi + 2, b.dlo + 2,
                             b.dhi + 2);
      for (int k = 0; k < W; ++k) {
        EXPECT_EQ(a.lo[k], b.lo[k]);
        EXPECT_EQ(a.hi[k], b.hi[k]);
        EXPECT_EQ(a.dlo[k], b.dlo[k]);
        EXPECT_EQ(a.dhi[k], b.dhi[k]);
      }
    }
  }
}

}  // namespace
// The lanes' own sin and cos (no libm) are within kLaneSinCosError of sinl and cosl, with a
// margin: at multiples of pi/2 and pi/4 and next to them (the reduction's and the quadrants'
// edges), at random points up to 2^19 (the reduction's range) and past it (libm).
TEST(FormulaLanes, LaneSinCos_WithinItsErrorBound) {
  std::mt19937 rng(7);
  std::vector<double> xs = {0.0, -0.0, 1e-300, -1e-300, 0.5, 1, 2, 3, 4, 1e5, -1e5};
  for (int k = -40000; k <= 40000; k += 7) {
    for (const double base : {k * (std::numbers::pi / 2), k * (std::numbers::pi / 4)}) {
      xs.push_back(base);
      xs.push_back(std::nextafter(base, 1e300));
      xs.push_back(std::nextafter(base, -1e300));
    }
  }
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200000; ++i) xs.push_back(u(rng) * std::pow(2.0, 20 * std::abs(u(rng))));
  double worst = 0;
  for (const double x : xs) {
    double s, c;
    lane_sin_cos(x, &s, &c);
    const long double xl = x;
    const double es = static_cast<double>(std::abs(s - sinl(xl)));
    const double ec = static_cast<double>(std::abs(c - cosl(xl)));
    worst = std::max({worst, es, ec});
    ASSERT_LE(es, 0.5 * kLaneSinCosError) << x;
    ASSERT_LE(ec, 0.5 * kLaneSinCosError) << x;
  }
  std::printf("worst lane sin/cos error %.3g (bound %.3g)\n", worst, kLaneSinCosError);
}

}  // namespace raycast
