// The implicit shape's root search never skips the first root: seeded random rays through a
// gyroid, Taubin's heart and the seed's sin/cos surface against an independent reference (dense
// sampling of f's sign in long double, each change bisected in long double), rays grazing a
// sphere, and pairs of roots closer than any sampling would separate.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "geometry/clipped_solid.h"
#include "geometry/implicit.h"
#include "reference_roots.h"

namespace raycast {
namespace {

using LongFn3 = long double (*)(long double, long double, long double);

long double gyroid_ld(long double x, long double y, long double z) {
  return std::sin(x) * std::cos(y) + std::sin(y) * std::cos(z) + std::sin(z) * std::cos(x);
}
long double heart_ld(long double x, long double y, long double z) {
  const long double q = x * x + 9.0L / 4 * y * y + z * z - 1;
  return q * q * q - x * x * z * z * z - 9.0L / 80 * y * y * z * z * z;
}
long double seed_ld(long double x, long double y, long double z) {
  return (2 - std::cos(x)) * std::cos(z) + (y + std::sin(x)) * std::sin(z) + std::cos(x + z);
}

struct Case {
  const char* function;
  LongFn3 reference;
  Aabb box;
};

const Case kCases[] = {
    {"sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", gyroid_ld, Aabb{{-4, -4, -4}, {4, 4, 4}}},
    {"(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3", heart_ld,
     Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}}},
    {"(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)", seed_ld,
     Aabb{{-4, -4, -4}, {4, 4, 4}}},
};

// Rays from a sphere around the box towards random points of it (an open surface, so every hit
// is a root of f): the hit is never beyond the reference's first root, and where it is before it,
// it is a root the sampling stepped over (f changes sign within a few ulps of it).
TEST(ImplicitSearch, RandomRays_FirstRootNeverSkipped) {
  for (const Case& k : kCases) {
    SCOPED_TRACE(k.function);
    const Implicit s = make_implicit(k.function, k.box, true);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    const Vec3 c = k.box.centre(), e = k.box.extent();
    int hits = 0, misses = 0, earlier = 0;
    for (int i = 0; i < 200; ++i) {
      SCOPED_TRACE(i);
      Vec3 dir{u(rng), u(rng), u(rng)};
      if (length_squared(dir) < 1e-4) continue;
      const Vec3 o = c + 1.5 * length(e) * normalize(dir);
      const Vec3 target = c + 0.5 * Vec3{e.x * u(rng), e.y * u(rng), e.z * u(rng)};
      const Ray r{o, target - o};
      BoxChord chord;
      ASSERT_TRUE(box_chord(k.box, r, chord));
      auto f = [&](long double t) {
        return k.reference(r.o.x + t * r.d.x, r.o.y + t * r.d.y, r.o.z + t * r.d.z);
      };
      const auto ref = testing_reference::sign_change_roots(f, chord.t0, chord.t1, 4000);
      LocalHit h;
      const bool hit = intersect(s, r, h);
      if (ref.empty()) {
        misses += !hit;
        if (hit) {
          // A pair of roots between two samples: f must change sign right at h.t.
          const long double dt = 1e-9L * (1 + std::abs(h.t));
          EXPECT_NE(f(h.t - dt) < 0, f(h.t + dt) < 0);
        }
        continue;
      }
      ASSERT_TRUE(hit) << "skipped the root at " << (double)ref[0];
      const double tol = 1e-9 * (1 + std::abs((double)ref[0]));
      EXPECT_LE(h.t, (double)ref[0] + tol);
      if (h.t < (double)ref[0] - tol) {
        ++earlier;
        const long double dt = 1e-9L * (1 + std::abs(h.t));
        EXPECT_NE(f(h.t - dt) < 0, f(h.t + dt) < 0);
      } else {
        ++hits;
      }
    }
    EXPECT_GT(hits, 50);
    EXPECT_LT(earlier, 10);
    RecordProperty(std::string("misses_") + k.function, misses);
  }
}

// Rays tangent to the unit sphere moved `depth` inside it cross twice, 2 sqrt(2 depth) apart:
// at depth 1e-12 the roots are 2.8e-6 apart and f stays within 1e-12 of 0 between them.
TEST(ImplicitSearch, GrazingSphere_NeverMissedJustInsideNeverHitJustOutside) {
  const Implicit s = make_implicit("x^2 + y^2 + z^2 - 1", Aabb{{-2, -2, -2}, {2, 2, 2}}, true);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (double depth : {1e-4, 1e-8, 1e-12}) {
    for (int i = 0; i < 300; ++i) {
      SCOPED_TRACE(testing::Message() << "depth " << depth << " ray " << i);
      Vec3 n{u(rng), u(rng), u(rng)};
      if (length_squared(n) < 1e-4) continue;
      n = normalize(n);
      Vec3 tangent = normalize(cross(n, Vec3{u(rng), u(rng), u(rng)}));
      const double dist = 1 + 2 * (u(rng) + 1);
      LocalHit h;
      const Ray inside{(1 - depth) * n - dist * tangent, tangent};
      ASSERT_TRUE(intersect(s, inside, h));
      EXPECT_NEAR(h.t, dist - std::sqrt(depth * (2 - depth)), 1e-6);
      SpanList l;
      spans(s, inside, l);
      EXPECT_EQ(l.size(), 2u);
      const Ray outside{(1 + depth) * n - dist * tangent, tangent};
      EXPECT_FALSE(intersect(s, outside, h));
    }
  }
}

// f = (x - a)(x - a - gap) along the x axis: both roots found, in order, for gaps down to 1e-9.
TEST(ImplicitSearch, TwoCloseRoots_BothFoundInOrder) {
  for (const char* gap : {"1e-3", "1e-6", "1e-9"}) {
    SCOPED_TRACE(gap);
    const std::string f = std::string("(x - 0.3141) * (x - 0.3141 - ") + gap + ")";
    const double g = std::stod(gap);
    const Implicit s = make_implicit(f, Aabb{{-1, -1, -1}, {1, 1, 1}}, true);
    const Ray r{{-3, 0.2, -0.1}, {1, 0, 0}};
    LocalHit h;
    ASSERT_TRUE(intersect(s, r, h));
    EXPECT_NEAR(h.t, 3.3141, 1e-12);
    SpanList l;
    spans(s, r, l);
    ASSERT_EQ(l.size(), 2u);
    EXPECT_NEAR(l[0].in.t, 3.3141, 1e-12);
    EXPECT_NEAR(l[1].in.t, 3.3141 + g, 1e-12);
    const Ray back{{3, 0.2, -0.1}, {-1, 0, 0}};
    ASSERT_TRUE(intersect(s, back, h));
    EXPECT_NEAR(h.t, 3 - 0.3141 - g, 1e-12);
  }
}

// sin(x) = 1 - eps holds at pi/2 +- delta (delta = acos(1 - eps), 1.4e-6 for eps 1e-12) and
// at -3 pi/2 +- delta: two pairs of near-double roots at the sine's maxima, where the interval
// sine's ends both lie below 1 - eps and only its extremum test keeps the piece. Rays at random
// slopes through the box (x from -8 to 4): every root is found, in order; at 1 + eps none is.
TEST(ImplicitSearch, NearDoubleRootsAtTrigExtremum_AllFoundNoneInvented) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const Aabb box{{-8, -4, -4}, {4, 4, 4}};
  for (double eps : {1e-6, 1e-10, 1e-12}) {
    std::ostringstream below, above;
    below.precision(17);
    above.precision(17);
    below << "sin(x) - " << (1 - eps) << " + 0 * cos(y)";
    above << "sin(x) - " << (1 + eps) << " + 0 * cos(y)";
    const Implicit s = make_implicit(below.str(), box, true);
    const Implicit solid = make_implicit(below.str(), box, false);
    const Implicit never = make_implicit(above.str(), box, true);
    const long double delta = std::acos(1 - static_cast<long double>(eps));
    const long double half_pi = std::acos(-1.0L) / 2;
    const long double xs[4] = {-3 * half_pi - delta, -3 * half_pi + delta, half_pi - delta,
                               half_pi + delta};
    for (int i = 0; i < 100; ++i) {
      SCOPED_TRACE(testing::Message() << "eps " << eps << " ray " << i);
      const Vec3 o{-10, 0.5 * u(rng), 0.5 * u(rng)};
      const Vec3 d{1, 0.2 * u(rng), 0.2 * u(rng)};
      const Ray r{o, d};
      LocalHit h;
      ASSERT_TRUE(intersect(s, r, h));
      const double t0 = static_cast<double>((xs[0] - o.x) / d.x);
      EXPECT_NEAR(h.t, t0, 1e-8);
      SpanList l;
      spans(solid, r, l);
      ASSERT_EQ(l.size(), 3u);  // f < 0 on [-8, x0], [x1, x2], [x3, 4]
      EXPECT_NEAR(l[0].out.t, t0, 1e-8);
      EXPECT_NEAR(l[1].in.t, static_cast<double>((xs[1] - o.x) / d.x), 1e-8);
      EXPECT_NEAR(l[1].out.t, static_cast<double>((xs[2] - o.x) / d.x), 1e-8);
      EXPECT_NEAR(l[2].in.t, static_cast<double>((xs[3] - o.x) / d.x), 1e-8);
      EXPECT_FALSE(intersect(never, r, h));
    }
  }
}

}  // namespace
}  // namespace raycast

namespace raycast {
namespace {

// occluded searches as intersect does but skips refining the root it finds: on random segments
// (tmin and tmax inside the box) through the gyroid, the seed's sin/cos surface and a thin sphere
// shell, open and closed, and on shadow rays leaving their hits, it must answer as intersect.
TEST(ImplicitSearch, Occluded_AgreesWithIntersectOnSegmentsAndShadowRays) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  int hits = 0, shadows = 0;
  for (const char* f : {"sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
                        "(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)",
                        "(x^2 + y^2 + z^2 - 4)^2 - 1e-6"}) {
    for (const bool open : {true, false}) {
      const Implicit s = make_implicit(f, Aabb{{-3, -3, -3}, {3, 3, 3}}, open);
      for (int i = 0; i < 300; ++i) {
        const Vec3 o{5 * u(rng), 5 * u(rng), 5 * u(rng)};
        const Vec3 target{2 * u(rng), 2 * u(rng), 2 * u(rng)};
        Ray r{o, target - o};
        r.tmin = unit(rng) < 0.3 ? 0 : 0.8 * unit(rng);
        r.tmax = unit(rng) < 0.3 ? kInfinity : r.tmin + 0.5 * unit(rng);
        LocalHit h;
        const bool hit = intersect(s, r, h);
        hits += hit;
        ASSERT_EQ(occluded(s, r), hit) << f << " ray " << i;
        if (!hit) continue;
        const Vec3 p = r.at(h.t), light{6 * u(rng), 6 * u(rng), 6 * u(rng)};
        for (const double tmax : {1.0, 0.1, 0.01}) {
          const Ray sr{p + 1e-9 * (light - p), light - p, 0, tmax};
          LocalHit sh;
          ASSERT_EQ(occluded(s, sr), intersect(s, sr, sh)) << f << " shadow " << i;
          ++shadows;
        }
      }
    }
  }
  EXPECT_GT(hits, 600);
  EXPECT_GT(shadows, 1800);
}

}  // namespace
}  // namespace raycast
