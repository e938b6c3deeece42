#include "geometry/quadric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "objects/object.h"
#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

constexpr QuadricKind kAllKinds[] = {QuadricKind::kEllipsoid,    QuadricKind::kParaboloid,
                                     QuadricKind::kHyperboloid1, QuadricKind::kHyperboloid2,
                                     QuadricKind::kCone,         QuadricKind::kCylinder};

Mat4 to_matrix(const QuadricCoefficients& c) {
  Mat4 q;
  q.m = {{{c[0], c[3] / 2, c[4] / 2, c[6] / 2},
          {c[3] / 2, c[1], c[5] / 2, c[7] / 2},
          {c[4] / 2, c[5] / 2, c[2], c[8] / 2},
          {c[6] / 2, c[7] / 2, c[8] / 2, c[9]}}};
  return q;
}

// f in long double, written out term by term (independent of quadric_value's nesting).
long double f_ld(const QuadricCoefficients& c, long double x, long double y, long double z) {
  return c[0] * x * x + c[1] * y * y + c[2] * z * z + c[3] * x * y + c[4] * x * z + c[5] * y * z +
         c[6] * x + c[7] * y + c[8] * z + c[9];
}
long double f_ld(const QuadricCoefficients& c, const Ray& r, long double t) {
  return f_ld(c, r.o.x + t * (long double)r.d.x, r.o.y + t * (long double)r.d.y,
              r.o.z + t * (long double)r.d.z);
}

// The well-conditioned real roots of f along the ray in long double: the line's polynomial from
// f at t = -1, 0, 1, the textbook roots, then Newton steps. Returns the count; 0 also when the
// roots are ill-conditioned (near tangency), which the caller skips.
int roots_ld(const QuadricCoefficients& c, const Ray& r, long double t[2]) {
  const long double f0 = f_ld(c, r, 0), fp = f_ld(c, r, 1), fm = f_ld(c, r, -1);
  const long double a2 = (fp + fm) / 2 - f0, a1 = (fp - fm) / 2, a0 = f0;
  const long double scale = std::abs(a2) + std::abs(a1) + std::abs(a0);
  if (std::abs(a2) < 1e-12L * scale) {
    if (std::abs(a1) < 1e-6L * scale) return 0;
    t[0] = -a0 / a1;
    return 1;
  }
  const long double disc = a1 * a1 - 4 * a2 * a0;
  if (disc < 1e-6L * a1 * a1 + 1e-6L * std::abs(a2 * a0)) return 0;
  const long double s = std::sqrt(disc);
  t[0] = (-a1 - s) / (2 * a2);
  t[1] = (-a1 + s) / (2 * a2);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 4; ++k) t[i] -= f_ld(c, r, t[i]) / (2 * a2 * t[i] + a1);
  if (t[0] > t[1]) std::swap(t[0], t[1]);
  return 2;
}

QuadricCoefficients kind_coefficients(QuadricKind k) { return quadric_of_kind(k, 0.7, 1.3, 0.9); }

TEST(Quadric, UnitSphereKind_HandRay_CrossesAtFourAndSix) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 1, 1));
  const Ray ray{{0, 0, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 4);
  const SurfaceInfo si = surface(q, ray, h);
  EXPECT_DOUBLE_EQ(si.n.z, -1);
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 6);
}

TEST(Quadric, KindCoefficientsAndMatrix_GiveTheSameHits) {
  for (QuadricKind k : kAllKinds) {
    const QuadricCoefficients c = kind_coefficients(k);
    const Quadric a = make_quadric(c);
    const Quadric b = make_quadric(quadric_from_matrix(to_matrix(c)));
    for (int i = 0; i < 10; ++i) EXPECT_DOUBLE_EQ(a.c[i], b.c[i]) << "coefficient " << i;
    Rng rng(7);
    for (int i = 0; i < 500; ++i) {
      const Ray ray = testing::random_ray(rng, 4, 2);
      LocalHit ha, hb;
      ASSERT_EQ(intersect(a, ray, ha), intersect(b, ray, hb)) << testing::describe(ray);
      if (ha.t < kInfinity) {
        EXPECT_EQ(ha.t, hb.t);
      }
    }
  }
}

TEST(Quadric, KindCoefficients_AreTheSpecFormulas) {
  // paraboloid x2/a2 + y2/b2 - z/c at (1, 2, 3) with a = 2, b = 4, c = 0.5: 1/4 + 4/16 - 6 = -5.5
  const auto c = quadric_of_kind(QuadricKind::kParaboloid, 2, 4, 0.5);
  EXPECT_DOUBLE_EQ(quadric_value(c, {1, 2, 3}), -5.5);
  // hyperboloid2 at (1, 2, 3): 1/4 + 4/16 - 9/0.25 + 1 = -34.5
  EXPECT_DOUBLE_EQ(quadric_value(quadric_of_kind(QuadricKind::kHyperboloid2, 2, 4, 0.5), {1, 2, 3}),
                   -34.5);
  EXPECT_DOUBLE_EQ(quadric_value(quadric_of_kind(QuadricKind::kHyperboloid1, 2, 4, 0.5), {1, 2, 3}),
                   -36.5);
  EXPECT_DOUBLE_EQ(quadric_value(quadric_of_kind(QuadricKind::kCone, 2, 4, 0.5), {1, 2, 3}), -35.5);
  EXPECT_DOUBLE_EQ(quadric_value(quadric_of_kind(QuadricKind::kCylinder, 2, 4, 0.5), {1, 2, 3}),
                   -0.5);
  EXPECT_DOUBLE_EQ(quadric_value(quadric_of_kind(QuadricKind::kEllipsoid, 2, 4, 0.5), {1, 2, 3}),
                   35.5);
}

TEST(Quadric, TransformedCoefficients_MatchTheTransformedObject) {
  // Q' = M^-T Q M^-1 is the quadric Q moved by M: its hits (all ten coefficients in play) must
  // equal those of the object-space quadric seen through the transform.
  const Transform xf = Transform::translate({0.3, -0.2, 0.5}) * Transform::rotate({1, 2, 3}, 37) *
                       Transform::scale({1.2, 0.8, 1.1});
  for (QuadricKind k : kAllKinds) {
    const QuadricCoefficients c = kind_coefficients(k);
    const Mat4 inv = xf.inverse_matrix();
    const Quadric moved = make_quadric(quadric_from_matrix(transpose(inv) * to_matrix(c) * inv));
    Object obj{make_quadric(c), xf, 0, 0};
    Rng rng(11);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
      const Ray ray = testing::random_ray(rng, 4, 2);
      SCOPED_TRACE(testing::describe(ray));
      LocalHit h1, h2;
      const bool b1 = intersect(moved, ray, h1), b2 = intersect(obj, ray, h2);
      long double r[2];
      if (roots_ld(moved.c, ray, r) == 0) continue;  // near-tangent: ill-conditioned
      ASSERT_EQ(b1, b2);
      if (!b1) continue;
      ++hits;
      EXPECT_NEAR(h1.t, h2.t, 1e-9 * std::max(1.0, std::abs(h1.t)));
    }
    EXPECT_GT(hits, 100);
  }
}

TEST(Quadric, RandomRays_RootsMatchLongDoubleTo1e9) {
  for (QuadricKind k : kAllKinds) {
    const Quadric q = make_quadric(kind_coefficients(k));
    Rng rng(23 + static_cast<int>(k));
    SCOPED_TRACE("seed " + std::to_string(23 + static_cast<int>(k)));
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
      Ray ray = testing::random_ray(rng, 6, 3);
      ray.tmin = -kInfinity;
      long double r[2];
      const int n = roots_ld(q.c, ray, r);
      if (n == 0) continue;
      SCOPED_TRACE(testing::describe(ray));
      LocalHit h;
      ASSERT_TRUE(intersect(q, ray, h));
      // The first crossing on the whole line is the smaller root.
      EXPECT_NEAR(h.t, (double)r[0], 1e-9 * std::max(1.0, std::abs(h.t)));
      ++checked;
    }
    EXPECT_GT(checked, 200);
  }
}

TEST(Quadric, RandomRays_SpansMatchInsideOracle) {
  const Aabb box{{-1.5, -1, -2}, {1, 2, 1.5}};
  for (QuadricKind k : kAllKinds) {
    for (int bounded = 0; bounded < 2; ++bounded) {
      const Quadric q =
          bounded ? make_quadric(kind_coefficients(k), box) : make_quadric(kind_coefficients(k));
      auto inside = [&](const Vec3& p) { return contains(q, p); };
      Rng rng(101);
      for (int i = 0; i < 300; ++i) {
        const Ray ray = testing::random_ray(rng, 4, 2);
        SCOPED_TRACE(testing::describe(ray));
        ASSERT_EQ(testing::span_mismatches(q, ray, inside, -10, 10), 0)
            << "kind " << int(k) << " bounded " << bounded;
        LocalHit h;
        const bool hit = intersect(q, ray, h);
        const double first = testing::first_span_end(q, ray);
        EXPECT_EQ(hit, first < kInfinity);
        if (hit) {
          EXPECT_EQ(h.t, first);
        }
        EXPECT_EQ(occluded(q, ray), hit);
      }
    }
  }
}

TEST(Quadric, RandomRays_NormalsAreUnitAndOutward) {
  const Aabb box{{-1.5, -1, -2}, {1, 2, 1.5}};
  for (QuadricKind k : kAllKinds) {
    const Quadric q = make_quadric(kind_coefficients(k), box);
    auto inside = [&](const Vec3& p) { return contains(q, p); };
    Rng rng(202);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
      const Ray ray = testing::random_ray(rng, 4, 2);
      SCOPED_TRACE(testing::describe(ray));
      LocalHit h;
      if (!intersect(q, ray, h)) continue;
      ++hits;
      testing::expect_outward_normal(q, ray, h, inside, 1e-7);
    }
    EXPECT_GT(hits, 50);
  }
}

TEST(Quadric, ParaboloidRayAlongItsAxis_HasOneRoot) {
  // x^2 + y^2 - z along x = 0.5: a2 = 0, f = 0.25 - (t - 5): one root at t = 5.25.
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kParaboloid, 1, 1, 1));
  const Ray ray{{0.5, 0, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 5.25);
  const SurfaceInfo si = surface(q, ray, h);
  EXPECT_NEAR(si.n.x, 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(si.n.z, -1 / std::sqrt(2.0), 1e-15);
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].in.t, 5.25);
  EXPECT_EQ(sl[0].out.t, kInfinity);
  EXPECT_EQ(sl[0].out.part, kNoSurface);
}

TEST(Quadric, ParaboloidRayNearlyAlongItsAxis_KeepsTheFiniteRoot) {
  // a2 = 1e-20: the cancellation-free form gives the far root huge and the near one exact.
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kParaboloid, 1, 1, 1));
  const Ray ray{{0.5, 0, -5}, {1e-10, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_NEAR(h.t, 5.25, 1e-9);
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_GT(sl[0].out.t, 1e15);
}

TEST(Quadric, ConeRayParallelToAGenerator_HasOneRoot) {
  // x^2 + y^2 - z^2 along (1, 0, 0) + t (1, 0, 1): f = 1 + 2t, inside for t < -0.5.
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kCone, 1, 1, 1));
  Ray ray{{1, 0, 0}, {1, 0, 1}};
  LocalHit h;
  EXPECT_FALSE(intersect(q, ray, h));
  ray.tmin = -10;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_DOUBLE_EQ(h.t, -0.5);
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_EQ(sl[0].in.t, -kInfinity);
  EXPECT_DOUBLE_EQ(sl[0].out.t, -0.5);
}

TEST(Quadric, SteepRayThroughConeApex_TouchesAtTheApex) {
  // (-1, 0, -2) + t (0.5, 0, 1) meets the apex at t = 2 and is inside both nappes around it.
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kCone, 1, 1, 1));
  const Ray ray{{-1, 0, -2}, {0.5, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 2);
  const SurfaceInfo si = surface(q, ray, h);
  EXPECT_NEAR(length(si.n), 1, 1e-15);  // grad f = 0 at the apex: the fallback faces the ray
  EXPECT_LT(dot(si.n, ray.d), 0);
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 2u);
  EXPECT_EQ(sl[0].in.t, -kInfinity);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 2);
  EXPECT_DOUBLE_EQ(sl[1].in.t, 2);
  EXPECT_EQ(sl[1].out.t, kInfinity);
}

TEST(Quadric, ShallowRayThroughConeApex_IsAZeroLengthTouch) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kCone, 1, 1, 1));
  const Ray ray{{-2, 0, -1}, {1, 0, 0.5}};
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].in.t, 2);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 2);
  EXPECT_TRUE(contains(q, {0, 0, 1}));
  EXPECT_FALSE(contains(q, {1, 0, 0}));
}

TEST(Quadric, RayAlongAGenerator_ReportsNoCrossingAndDoesNotCrash) {
  // f is identically 0 on the line: no sign change, nothing to report.
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kCone, 1, 1, 1));
  const Ray ray{{-1, 0, -1}, {1, 0, 1}};
  LocalHit h;
  EXPECT_FALSE(intersect(q, ray, h));
  SpanList sl;
  spans(q, ray, sl);
  EXPECT_TRUE(sl.empty());
}

TEST(Quadric, CylinderKindRayAlongTheAxisInside_IsInsideEverywhere) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kCylinder, 1, 1, 1));
  const Ray ray{{0.2, 0.3, -5}, {0, 0, 2}};
  LocalHit h;
  EXPECT_FALSE(intersect(q, ray, h));
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_EQ(sl[0].in.t, -kInfinity);
  EXPECT_EQ(sl[0].out.t, kInfinity);
}

TEST(Quadric, BoundedHemisphere_IsClosedByTheBoxFace) {
  const Quadric q =
      make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 1, 1), Aabb{{-2, -2, 0}, {2, 2, 2}});
  const Ray up{{0.5, 0, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, up, h));
  EXPECT_DOUBLE_EQ(h.t, 5);
  const SurfaceInfo si = surface(q, up, h);
  EXPECT_EQ(si.n, (Vec3{0, 0, -1}));
  EXPECT_EQ(si.p.z, 0);
  SpanList sl;
  spans(q, up, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_NEAR(sl[0].out.t, 5 + std::sqrt(0.75), 1e-15);
  EXPECT_EQ(sl[0].out.part, 0);
  EXPECT_EQ(bounds(q).lo.z, 0);  // the box, tightened to the sphere on x and y
  EXPECT_LT(bounds(q).hi.x, 1.01);
}

TEST(Quadric, OpenBoundedHemisphere_IsSeenFromInside) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 1, 1),
                                 Aabb{{-2, -2, 0}, {2, 2, 2}}, true);
  EXPECT_FALSE(is_closed(q));
  const Ray up{{0.5, 0, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, up, h));
  EXPECT_NEAR(h.t, 5 + std::sqrt(0.75), 1e-15);
  const SurfaceInfo si = surface(q, up, h);
  EXPECT_NEAR(si.n.x, 0.5, 1e-15);  // outward, as the closed solid's
  EXPECT_GT(dot(si.n, up.d), 0);
  EXPECT_FALSE(contains(q, {0, 0, 0.5}));
}

TEST(Quadric, OpenWithoutBounds_IsTheWholeCurvedSurface) {
  const Quadric q =
      make_quadric(quadric_of_kind(QuadricKind::kCylinder, 1, 1, 1), std::nullopt, true);
  EXPECT_FALSE(is_closed(q));
  EXPECT_FALSE(contains(q, {0, 0, 0}));
  const Ray ray{{0, 0, 100}, {0.5, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 2);
  EXPECT_DOUBLE_EQ(surface(q, ray, h).n.x, 1);
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 2u);
  EXPECT_DOUBLE_EQ(sl[0].in.t, -2);
  EXPECT_DOUBLE_EQ(sl[0].out.t, -2);
  EXPECT_DOUBLE_EQ(sl[1].in.t, 2);
}

TEST(Quadric, TMinTMax_AreClosedAtBothEnds) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 1, 1));
  LocalHit h;
  EXPECT_TRUE(intersect(q, Ray{{0, 0, -5}, {0, 0, 1}, 0, 4}, h));
  EXPECT_DOUBLE_EQ(h.t, 4);
  EXPECT_FALSE(intersect(q, Ray{{0, 0, -5}, {0, 0, 1}, 0, std::nextafter(4.0, 0.0)}, h));
  EXPECT_TRUE(intersect(q, Ray{{0, 0, -5}, {0, 0, 1}, 6, 10}, h));
  EXPECT_DOUBLE_EQ(h.t, 6);
  EXPECT_FALSE(intersect(q, Ray{{0, 0, -5}, {0, 0, 1}, std::nextafter(6.0, 10.0), 10}, h));
  EXPECT_FALSE(occluded(q, Ray{{0, 0, -5}, {0, 0, 1}, 4.5, 5.5}));
}

TEST(Quadric, StartingInside_ReturnsTheExit) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kHyperboloid1, 1, 1, 1));
  const Ray ray{{0, 0, 0}, {3, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 1.0 / 3);
  EXPECT_DOUBLE_EQ(surface(q, ray, h).n.x, 1);
}

TEST(Quadric, TangentRay_IsATouch) {
  const Quadric q = make_quadric(quadric_of_kind(QuadricKind::kEllipsoid, 1, 1, 1));
  const Ray ray{{-5, 1, 0}, {1, 0, 0}};
  SpanList sl;
  spans(q, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].in.t, 5);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 5);
}

TEST(Quadric, MakeQuadric_RejectsBadInput) {
  QuadricCoefficients zero{};
  zero[9] = 1;
  EXPECT_THROW(make_quadric(zero), std::invalid_argument);
  QuadricCoefficients nan = quadric_of_kind(QuadricKind::kCone, 1, 1, 1);
  nan[2] = std::nan("");
  EXPECT_THROW(make_quadric(nan), std::invalid_argument);
  EXPECT_THROW(make_quadric({1, 1, 1, 0, 0, 0, 0, 0, 0, 1}),
               std::invalid_argument);  // empty inside
  EXPECT_THROW(make_quadric(kind_coefficients(QuadricKind::kCone), Aabb{{0, 0, 0}, {1, 0, 1}}),
               std::invalid_argument);
  EXPECT_THROW(make_quadric(kind_coefficients(QuadricKind::kEllipsoid), Aabb{{5, 5, 5}, {6, 6, 6}}),
               std::invalid_argument);  // the box misses the ellipsoid
  Mat4 m = to_matrix(kind_coefficients(QuadricKind::kCone));
  m.m[0][1] = 0.5;
  EXPECT_THROW(quadric_from_matrix(m), std::invalid_argument);
  EXPECT_THROW(quadric_of_kind(QuadricKind::kCone, 0, 1, 1), std::invalid_argument);
}

TEST(Quadric, GeneralEllipsoidCoefficients_HaveTightFiniteBounds) {
  // (x - 1)^2 / 4 + (y + 2)^2 + z^2 / 9 - 1, expanded.
  const Quadric q = make_quadric({0.25, 1, 1.0 / 9, 0, 0, 0, -0.5, 4, 0, 0.25 + 4 - 1});
  const Aabb b = bounds(q);
  EXPECT_NEAR(b.lo.x, -1, 1e-8);
  EXPECT_NEAR(b.hi.x, 3, 1e-8);
  EXPECT_NEAR(b.lo.y, -3, 1e-8);
  EXPECT_NEAR(b.hi.z, 3, 1e-8);
  EXPECT_FALSE(make_quadric(kind_coefficients(QuadricKind::kHyperboloid1)).hull.is_bounded());
}

}  // namespace
}  // namespace raycast
