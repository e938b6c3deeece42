#include "geometry/torus.h"
#include "geometry/shape_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "math/float_error.h"
#include "math/polynomial_solver.h"
#include "reference_roots.h"

namespace raycast {
namespace {

const Torus kTorus = make_torus(2, 0.5);

long double torus_ld(const Torus& s, const Ray& r, long double t) {
  const long double x = r.o.x + t * r.d.x, y = r.o.y + t * r.d.y, z = r.o.z + t * r.d.z;
  const long double R2 = (long double)s.major_radius * s.major_radius;
  const long double a = x * x + y * y + z * z + R2 - (long double)s.minor_radius * s.minor_radius;
  return a * a - 4 * R2 * (x * x + y * y);
}

std::vector<double> all_crossings(const Torus& s, const Ray& r) {
  SpanList l;
  spans(s, r, l);
  std::vector<double> t;
  for (const Span& sp : l) {
    t.push_back(sp.in.t);
    t.push_back(sp.out.t);
  }
  return t;
}

TEST(Torus, MakeTorus_RejectsBadRadii) {
  EXPECT_THROW(make_torus(0, 1), std::invalid_argument);
  EXPECT_THROW(make_torus(1, -1), std::invalid_argument);
  EXPECT_THROW(make_torus(std::nan(""), 1), std::invalid_argument);
  EXPECT_THROW(make_torus(1, kInfinity), std::invalid_argument);
}

TEST(Torus, RayAlongX_FourHandComputedCrossings) {
  const Ray r{{-5, 0, 0}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(kTorus, r, h));
  EXPECT_NEAR(h.t, 2.5, 1e-14);
  const auto t = all_crossings(kTorus, r);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_NEAR(t[0], 2.5, 1e-14);
  EXPECT_NEAR(t[1], 3.5, 1e-14);
  EXPECT_NEAR(t[2], 6.5, 1e-14);
  EXPECT_NEAR(t[3], 7.5, 1e-14);
}

TEST(Torus, UnnormalisedDirection_TInUnitsOfD) {
  const Ray r{{-5, 0, 0}, {0.5, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(kTorus, r, h));
  EXPECT_NEAR(h.t, 5.0, 1e-13);
}

TEST(Torus, RayThroughTheHole_Misses) {
  LocalHit h;
  EXPECT_FALSE(intersect(kTorus, Ray{{0, 0, -5}, {0, 0, 1}}, h));
  EXPECT_FALSE(intersect(kTorus, Ray{{1.49, 0, -5}, {0, 0, 1}}, h));
  EXPECT_TRUE(intersect(kTorus, Ray{{1.51, 0, -5}, {0, 0, 1}}, h));
}

TEST(Torus, DownThroughTheTube_HandComputed) {
  const auto t = all_crossings(kTorus, Ray{{2, 0, 5}, {0, 0, -1}});
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 4.5, 1e-14);
  EXPECT_NEAR(t[1], 5.5, 1e-14);
}

TEST(Torus, TMinTMax_ClosedInterval) {
  const Ray base{{-5, 0, 0}, {1, 0, 0}};
  LocalHit h;
  Ray r = base;
  r.tmax = 2.5;
  ASSERT_TRUE(intersect(kTorus, r, h));
  EXPECT_EQ(h.t, 2.5);
  r.tmax = 2.5 - 1e-12;
  EXPECT_FALSE(intersect(kTorus, r, h));
  EXPECT_FALSE(occluded(kTorus, r));
  r = base;
  r.tmin = 3;
  ASSERT_TRUE(intersect(kTorus, r, h));
  EXPECT_NEAR(h.t, 3.5, 1e-14);
  r.tmin = 7.5;
  ASSERT_TRUE(intersect(kTorus, r, h));
  EXPECT_EQ(h.t, 7.5);
}

TEST(Torus, StartingInside_HitsTheExit) {
  LocalHit h;
  ASSERT_TRUE(intersect(kTorus, Ray{{-2, 0, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 0.5, 1e-14);
  EXPECT_TRUE(contains(kTorus, Vec3{-2, 0, 0}));
  EXPECT_FALSE(contains(kTorus, Vec3{0, 0, 0}));
}

TEST(Torus, GrazingTheTop_HitsJustBelowMissesJustAbove) {
  for (double eps : {1e-3, 1e-6, 1e-9}) {
    SCOPED_TRACE(eps);
    LocalHit h;
    const double z = 0.5 * (1 - eps);
    ASSERT_TRUE(intersect(kTorus, Ray{{-5, 0, z}, {1, 0, 0}}, h));
    const double half = std::sqrt(0.25 - z * z);
    EXPECT_NEAR(h.t, 5 - 2 - half, 1e-7);
    EXPECT_FALSE(intersect(kTorus, Ray{{-5, 0, 0.5 * (1 + eps)}, {1, 0, 0}}, h));
  }
}

TEST(Torus, GrazingTheInnerEquator_FourCrossings) {
  // The line y = R - r - tiny crosses the inner wall twice near x = 0.
  const double y = 1.5 - 1e-7;
  const auto t = all_crossings(kTorus, Ray{{-5, y, 0}, {1, 0, 0}});
  ASSERT_EQ(t.size(), 4u);
  const double half = std::sqrt(1.5 * 1.5 - y * y);
  EXPECT_NEAR(t[1], 5 - half, 1e-9);
  EXPECT_NEAR(t[2], 5 + half, 1e-9);
}

TEST(Torus, RandomRays_MatchLongDoubleReference) {
  const Torus s = make_torus(1.0, 0.3);
  int compared = 0;
  for (unsigned seed = 0; seed < 1500; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const Vec3 o{4 * u(rng), 4 * u(rng), 4 * u(rng)};
    const Vec3 target{1.3 * u(rng), 1.3 * u(rng), 0.3 * u(rng)};
    const Ray r{o, (target - o) * (0.5 + std::abs(u(rng)))};
    const auto ref = testing_reference::sign_change_roots(
        [&](long double t) { return torus_ld(s, r, t); }, 0, 4, 3000);
    LocalHit h;
    const bool hit = intersect(s, r, h);
    if (ref.empty()) continue;  // a pair closer than the sampling may still be hit: not compared
    ASSERT_TRUE(hit);
    if (h.t < (double)ref[0] - 1e-9 * (double)ref[0]) {
      // An earlier pair of roots the sampling stepped over: it must really be on the surface.
      EXPECT_NEAR((double)torus_ld(s, r, h.t), 0.0, 1e-9);
      continue;
    }
    EXPECT_NEAR(h.t, (double)ref[0], 1e-9 * (double)ref[0]);
    ++compared;
  }
  EXPECT_GT(compared, 500);
}

// Rays tangent to the torus at a random surface point, moved into the solid by a tiny amount:
// every one must hit (two crossings within the tiny chord).
TEST(Torus, RandomGrazingRays_NeverMissed) {
  const Torus s = make_torus(1.0, 0.25);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  int misses = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * u(rng), theta = 2 * M_PI * u(rng);
    const Vec3 radial{std::cos(phi), std::sin(phi), 0};
    const Vec3 normal = std::cos(theta) * radial + Vec3{0, 0, std::sin(theta)};
    const Vec3 p = s.major_radius * radial + s.minor_radius * normal;
    Vec3 a, b;
    make_frame(normal, a, b);
    const double w = 2 * M_PI * u(rng);
    const Vec3 tangent = std::cos(w) * a + std::sin(w) * b;
    const Vec3 inside = p - 1e-7 * normal;
    const Ray r{inside - 3.0 * tangent, tangent};
    LocalHit h;
    if (!intersect(s, r, h) || h.t > 3.0 + 1e-3) ++misses;
  }
  EXPECT_EQ(misses, 0) << "of " << n;
}

TEST(Torus, SpansMatchInsideOracle) {
  const Torus s = make_torus(1.0, 0.4);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE(i);
    const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    const Vec3 target{1.2 * u(rng), 1.2 * u(rng), 0.4 * u(rng)};
    const Ray r{o, target - o};
    testing::check_spans_against_oracle(
        s, r, [&](const Vec3& p) { return contains(s, p); }, -1, 3.0, 400);
  }
}

TEST(Torus, Normals_UnitAndOutward) {
  const Torus s = make_torus(1.0, 0.4);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    const Ray r{o, Vec3{1.2 * u(rng), 1.2 * u(rng), 0.4 * u(rng)} - o};
    LocalHit h;
    if (!intersect(s, r, h)) continue;
    const SurfaceInfo si = surface(s, r, h);
    EXPECT_NEAR(length(si.n), 1, 1e-12);
    EXPECT_FALSE(contains(s, si.p + 1e-6 * si.n));
    EXPECT_TRUE(contains(s, si.p - 1e-6 * si.n));
    EXPECT_NEAR(torus_function(s, si.p), 0, 1e-12);
    EXPECT_GE(si.u, 0);
    EXPECT_LT(si.u, 1);
    EXPECT_GE(si.v, 0);
    EXPECT_LT(si.v, 1);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(Torus, UV_HandComputed) {
  const Ray r{{5, 0, 0}, {-1, 0, 0}};  // hits (2.5, 0, 0): phi 0, theta 0
  LocalHit h;
  ASSERT_TRUE(intersect(kTorus, r, h));
  const SurfaceInfo si = surface(kTorus, r, h);
  EXPECT_NEAR(si.u, 0, 1e-12);
  EXPECT_NEAR(si.v, 0, 1e-12);
  const Ray top{{0, 2, 5}, {0, 0, -1}};  // hits (0, 2, 0.5): phi pi/2, theta pi/2
  ASSERT_TRUE(intersect(kTorus, top, h));
  const SurfaceInfo st = surface(kTorus, top, h);
  EXPECT_NEAR(st.u, 0.25, 1e-12);
  EXPECT_NEAR(st.v, 0.25, 1e-12);
  EXPECT_NEAR(st.n.z, 1, 1e-12);
}

// intersect's short cuts (the first root only, lines missing the slab or inside the hole skipped)
// against all the quartic's roots from find_real_roots over the same range: the same hit or miss,
// the same t. Rays aimed at the slab's faces |z| = r, at the hole's wall rho = R - r (from above,
// steeply and flatly), at the tube's top and through the hole, each moved off by a random amount
// from 1e-12 to 1 (both sides), with tmin and tmax cutting some chords.
TEST(Torus, ShortCuts_AgreeWithAllTheQuarticsRoots) {
  for (const Torus& s : {make_torus(2, 0.5), make_torus(1, 0.35), make_torus(0.5, 0.7)}) {
    std::mt19937 rng(91);
    std::uniform_real_distribution<double> u(0, 1);
    int hits = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
      SCOPED_TRACE(i);
      const double R = s.major_radius, r = s.minor_radius;
      const double phi = 2 * M_PI * u(rng), off = std::pow(10.0, -12 * u(rng)) * (u(rng) - 0.5);
      const Vec3 radial{std::cos(phi), std::sin(phi), 0};
      Vec3 target;
      switch (i % 4) {
        case 0:  // a slab face
          target = (R + (2 * u(rng) - 1) * r) * radial + Vec3{0, 0, (i % 8 < 4 ? r : -r) + off};
          break;
        case 1:  // the hole's wall
          target = (std::abs(R - r) + off) * radial + Vec3{0, 0, (2 * u(rng) - 1) * r};
          break;
        case 2:  // the tube's top
          target = (R + off) * radial + Vec3{0, 0, r + off};
          break;
        default:  // through the hole
          target = (std::abs(R - r) * u(rng)) * radial + Vec3{0, 0, (2 * u(rng) - 1) * r};
      }
      const double a = 2 * M_PI * u(rng), b = M_PI * (0.02 + 0.96 * u(rng));
      const Vec3 dir{std::sin(b) * std::cos(a), std::sin(b) * std::sin(a), std::cos(b)};
      Ray ray{target - 6.0 * dir, dir * (0.5 + u(rng))};
      if (i % 3 == 0) ray.tmin = 6.0 / (0.5 + u(rng)) * u(rng);
      if (i % 5 == 0) ray.tmax = ray.tmin + 12 * u(rng);
      TorusQuartic q;
      bool want = false;
      double want_t = 0;
      if (torus_quartic(s, ray, q)) {
        const double len = 1 / q.inv_len;
        const double margin = gamma(4) * (std::abs(q.t_c) * len + q.h);
        const double lo = std::max((ray.tmin - q.t_c) * len - margin, -q.h);
        const double hi = std::min((ray.tmax - q.t_c) * len + margin, q.h);
        double roots[4];
        const int n = find_real_roots(q.p, lo, hi, roots);
        for (int k = 0; k < n && !want; ++k) {
          const double t = q.t_c + roots[k] * q.inv_len;
          if (t >= ray.tmin && t <= ray.tmax) {
            want = true;
            want_t = t;
          }
        }
      }
      LocalHit h;
      const bool got = intersect(s, ray, h);
      ASSERT_EQ(got, want);
      if (got) {
        EXPECT_NEAR(h.t, want_t, 1e-12 * (1 + std::abs(want_t)));
      }
      (got ? hits : misses) += 1;
    }
    EXPECT_GT(hits, 2000);
    EXPECT_GT(misses, 2000);
  }
}

}  // namespace
}  // namespace raycast
