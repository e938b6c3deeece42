#include "geometry/implicit.h"
#include "geometry/shape_checks.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "geometry/clipped_solid.h"
#include "reference_roots.h"

namespace raycast {
namespace {

const Aabb kBox{{-2, -2, -2}, {2, 2, 2}};
constexpr const char* kSeed = "(2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z)";

long double seed_ld(long double x, long double y, long double z) {
  return (2 - std::cos(x)) * std::cos(z) + (y + std::sin(x)) * std::sin(z) + std::cos(x + z);
}

TEST(Implicit, Sphere_HandComputed) {
  const Implicit s = make_implicit("x^2 + y^2 + z^2 - 1", kBox);
  const Ray r{{-5, 0, 0}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 4, 1e-12);
  const SurfaceInfo si = surface(s, r, h);
  EXPECT_NEAR(si.n.x, -1, 1e-12);
  SpanList l;
  spans(s, r, l);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_NEAR(l[0].in.t, 4, 1e-12);
  EXPECT_NEAR(l[0].out.t, 6, 1e-12);
}

TEST(Implicit, TMinTMaxAndInside) {
  const Implicit s = make_implicit("x^2 + y^2 + z^2 - 1", kBox);
  LocalHit h;
  Ray r{{-5, 0, 0}, {1, 0, 0}, 0, 3.9};
  EXPECT_FALSE(intersect(s, r, h));
  r.tmin = 4.5;
  r.tmax = kInfinity;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 6, 1e-12);
  ASSERT_TRUE(intersect(s, Ray{{0, 0, 0}, {0, 0.5, 0}}, h));
  EXPECT_NEAR(h.t, 2, 1e-12);
  EXPECT_TRUE(contains(s, Vec3{0, 0, 0.5}));
  EXPECT_FALSE(contains(s, Vec3{0, 0, 1.5}));
}

TEST(Implicit, BoxFacesCloseTheSolid) {
  const Implicit s = make_implicit("z", kBox);  // the half-space z < 0 clipped: a box
  const Ray r{{0.5, 0.5, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_EQ(h.t, 3);
  EXPECT_EQ(surface(s, r, h).n, (Vec3{0, 0, -1}));
  SpanList l;
  spans(s, r, l);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_NEAR(l[0].out.t, 5, 1e-12);
  EXPECT_NEAR(surface(s, r, l[0].out).n.z, 1, 1e-12);
}

// A slab 2e-6 thick: sampling f along the ray (or a wrong gradient bound) steps over it.
TEST(Implicit, ThinFeature_NeverSkipped) {
  const Implicit s = make_implicit("abs(x - 0.123) - 1e-6", kBox);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 500; ++i) {
    SCOPED_TRACE(i);
    const Vec3 o{-1.9, u(rng), u(rng)};
    const Vec3 d{1, 0.2 * u(rng), 0.2 * u(rng)};
    LocalHit h;
    ASSERT_TRUE(intersect(s, Ray{o, d}, h));
    EXPECT_NEAR(o.x + h.t * d.x, 0.123 - 1e-6, 1e-9);
  }
}

TEST(Implicit, SeedSurface_RandomRaysMatchLongDoubleReference) {
  const Implicit s = make_implicit(kSeed, kBox);
  int compared = 0;
  for (unsigned seed = 0; seed < 200; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const Vec3 o{1.9 * u(rng), 1.9 * u(rng), 1.9 * u(rng)};
    const Ray r{o, Vec3{u(rng), u(rng), u(rng)}};
    BoxChord c;
    ASSERT_TRUE(box_chord(s.box, r, c));
    auto f = [&](long double t) {
      return seed_ld(r.o.x + t * r.d.x, r.o.y + t * r.d.y, r.o.z + t * r.d.z);
    };
    const auto ref = testing_reference::sign_change_roots(f, 0, c.t1, 2000);
    Ray rr = r;
    LocalHit h;
    // Start inside the box so that the first crossing is the curved surface or the exit.
    const bool hit = intersect(make_implicit(kSeed, kBox, true), rr, h);
    if (ref.empty()) {
      if (hit) {
        EXPECT_NEAR((double)f(h.t), 0.0, 1e-9);
      }
      continue;
    }
    ASSERT_TRUE(hit);
    if (h.t < (double)ref[0] * (1 - 1e-6)) {
      EXPECT_NEAR((double)f(h.t), 0.0, 1e-9);
      continue;
    }
    EXPECT_NEAR(h.t, (double)ref[0], 1e-6 * (double)ref[0]);
    ++compared;
  }
  EXPECT_GT(compared, 50);
}

TEST(Implicit, SeedSurface_SpansMatchInsideOracleAndNormalsOutward) {
  const Implicit s = make_implicit(kSeed, kBox);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  int normals = 0;
  for (int i = 0; i < 200; ++i) {
    SCOPED_TRACE(i);
    const Vec3 o{4 * u(rng), 4 * u(rng), 4 * u(rng)};
    const Ray r{o, Vec3{1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng)} - o};
    testing::check_spans_against_oracle(
        s, r, [&](const Vec3& p) { return contains(s, p); }, -1, 3.0, 300);
    LocalHit h;
    if (!intersect(s, r, h)) continue;
    const SurfaceInfo si = surface(s, r, h);
    EXPECT_NEAR(length(si.n), 1, 1e-12);
    if (h.part == 0) {
      EXPECT_FALSE(contains(s, si.p + 1e-6 * si.n));
      EXPECT_TRUE(contains(s, si.p - 1e-6 * si.n));
      ++normals;
    }
  }
  EXPECT_GT(normals, 20);
}

TEST(Implicit, DegenerateFormulas_ReturnQuickly) {
  const auto start = std::chrono::steady_clock::now();
  for (const char* text :
       {"x - x", "sin(1 / x)", "0 * x", "sqrt(-1 - x^2)", "log(x)", "tan(50 x)"}) {
    SCOPED_TRACE(text);
    const Implicit s = make_implicit(text, kBox);
    LocalHit h;
    intersect(s, Ray{{-3, 0.1, 0.2}, {1, 0.01, 0.02}}, h);
    SpanList l;
    spans(s, Ray{{-3, 0.1, 0.2}, {1, 0.01, 0.02}}, l);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0);
  LocalHit h;
  EXPECT_FALSE(intersect(make_implicit("sqrt(-1 - x^2)", kBox), Ray{{-3, 0, 0}, {1, 0, 0}}, h));
  ASSERT_TRUE(intersect(make_implicit("log(x + 2.5)", kBox, true), Ray{{-3, 0, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 1.5, 1e-12);  // undefined for x <= -2.5, the root at x = -1.5
}

TEST(Implicit, MakeImplicit_RejectsBadInput) {
  EXPECT_THROW(make_implicit("x", Aabb{{0, 0, 0}, {1, 1, -1}}), std::invalid_argument);
  EXPECT_THROW(make_implicit("x +", kBox), ExpressionError);
  EXPECT_THROW(make_implicit("cosh(x)", kBox), ExpressionError);
}

}  // namespace
}  // namespace raycast
