#include "geometry/triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

// Reference: the plane first, then the inside test by the three edge functions (signed areas).
// Returns the smallest normalised edge function in `margin` (negative outside).
bool plane_then_inside(const Triangle& tri, const Ray& ray, double& t, double& margin) {
  const Vec3 n = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
  const double dn = dot(n, ray.d);
  if (dn == 0) return false;
  t = dot(n, tri.p0 - ray.o) / dn;
  const Vec3 p = ray.at(t);
  const double area = length_squared(n);
  const double e0 = dot(cross(tri.p1 - tri.p0, p - tri.p0), n) / area;
  const double e1 = dot(cross(tri.p2 - tri.p1, p - tri.p1), n) / area;
  const double e2 = dot(cross(tri.p0 - tri.p2, p - tri.p2), n) / area;
  margin = std::min({e0, e1, e2});
  return margin >= 0;
}

TEST(Triangle, MakeTriangle_RejectsDegenerateOrNonFinite) {
  EXPECT_THROW(make_triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), std::invalid_argument);
  EXPECT_THROW(make_triangle({0, 0, 0}, {0, 0, 0}, {0, 1, 0}), std::invalid_argument);
  EXPECT_THROW(make_triangle({0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}), std::invalid_argument);
  EXPECT_THROW(make_triangle({0, 0, 0}, {1, 0, 0}, {0, 1e308, 1e308}), std::invalid_argument);
  // Nearly collinear beyond kDegenerateSine.
  EXPECT_THROW(make_triangle({0, 0, 0}, {1, 0, 0}, {2, 1e-14, 0}), std::invalid_argument);
  EXPECT_NO_THROW(make_triangle({0, 0, 0}, {1, 0, 0}, {2, 1e-9, 0}));
  EXPECT_THROW(make_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}),
               std::invalid_argument);
}

TEST(Triangle, HandComputedHit_ExactTBarycentricsAndCcwNormal) {
  const Triangle tri = make_triangle({0, 0, 0}, {4, 0, 0}, {0, 2, 0});
  const Ray ray{{1, 0.5, 3}, {0, 0, -2}};
  LocalHit h;
  ASSERT_TRUE(intersect(tri, ray, h));
  EXPECT_EQ(h.t, 1.5);
  const SurfaceInfo si = surface(tri, ray, h);
  EXPECT_EQ(si.u, 0.25);  // b1 = x / 4
  EXPECT_EQ(si.v, 0.25);  // b2 = y / 2
  EXPECT_EQ(si.p, Vec3(1, 0.5, 0));
  EXPECT_EQ(si.n, Vec3(0, 0, 1));  // p0 -> p1 -> p2 runs counter-clockwise seen from +z
  // Reversed winding: the normal flips, queries never flip it back towards the ray.
  const Triangle rev = make_triangle({0, 0, 0}, {0, 2, 0}, {4, 0, 0});
  ASSERT_TRUE(intersect(rev, ray, h));
  EXPECT_EQ(surface(rev, ray, h).n, Vec3(0, 0, -1));
}

TEST(Triangle, EdgesAndVertices_AreInclusive) {
  const Triangle tri = make_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  LocalHit h;
  EXPECT_TRUE(intersect(tri, Ray{{0.5, 0, 1}, {0, 0, -1}}, h));    // edge p0 p1
  EXPECT_TRUE(intersect(tri, Ray{{0.5, 0.5, 1}, {0, 0, -1}}, h));  // hypotenuse
  EXPECT_TRUE(intersect(tri, Ray{{1, 0, 1}, {0, 0, -1}}, h));      // vertex p1
  EXPECT_TRUE(intersect(tri, Ray{{0, 0, 1}, {0, 0, -1}}, h));      // vertex p0
  EXPECT_FALSE(intersect(tri, Ray{{-1e-12, 0.5, 1}, {0, 0, -1}}, h));
  EXPECT_FALSE(intersect(tri, Ray{{0.5, 0.5 + 1e-12, 1}, {0, 0, -1}}, h));
}

TEST(Triangle, ParallelCoplanarOrBehind_Misses) {
  const Triangle tri = make_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  LocalHit h;
  EXPECT_FALSE(intersect(tri, Ray{{0.2, 0.2, 1}, {1, 0, 0}}, h));  // parallel above
  EXPECT_FALSE(intersect(tri, Ray{{-1, 0.2, 0}, {1, 0, 0}}, h));   // in its plane: no crossing
  EXPECT_FALSE(intersect(tri, Ray{{0.2, 0.2, 1}, {0, 0, 1}}, h));  // behind the origin
  SpanList s;
  spans(tri, Ray{{0.2, 0.2, 1}, {0, 0, 1}}, s);
  ASSERT_EQ(s.size(), 1u);  // an open surface's crossing: a zero-length span
  EXPECT_EQ(s[0].in.t, -1);
  EXPECT_EQ(s[0].out.t, -1);
  EXPECT_FALSE(is_closed(tri));
  EXPECT_FALSE(contains(tri, {0.2, 0.2, 0}));
}

TEST(Triangle, TminTmax_InclusiveAtBothEnds) {
  const Triangle tri = make_triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  LocalHit h;
  EXPECT_TRUE(intersect(tri, Ray{{1, 1, 3}, {0, 0, -1}, 0, 3}, h));
  EXPECT_FALSE(intersect(tri, Ray{{1, 1, 3}, {0, 0, -1}, 0, std::nextafter(3.0, 0.0)}, h));
  EXPECT_TRUE(intersect(tri, Ray{{1, 1, 3}, {0, 0, -1}, 3, 5}, h));
  EXPECT_FALSE(intersect(tri, Ray{{1, 1, 3}, {0, 0, -1}, std::nextafter(3.0, 4.0), 5}, h));
}

TEST(Triangle, ShadingNormals_InterpolatedAndOnTheGeometricSide) {
  const Triangle tri = make_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {1, 0, 1},
                                     {0, 0, -1});  // n2 points away: the result is turned back
  const Ray ray{{0.5, 0, 1}, {0, 0, -1}};          // b1 = 0.5, b2 = 0
  LocalHit h;
  ASSERT_TRUE(intersect(tri, ray, h));
  const SurfaceInfo si = surface(tri, ray, h);
  EXPECT_EQ(si.n, Vec3(0, 0, 1));
  const Vec3 expect =
      normalize(Vec3{0.5 * 0.70710678118654757, 0, 0.5 + 0.5 * 0.70710678118654757});
  EXPECT_NEAR(si.shading_n.x, expect.x, 1e-12);
  EXPECT_NEAR(si.shading_n.z, expect.z, 1e-12);
  testing::expect_unit(si.shading_n, "shading normal");
  EXPECT_GT(dot(si.shading_n, si.n), 0);
}

TEST(Triangle, RandomRays_MatchPlaneThenInsideTest) {
  const unsigned seed = 31337;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Triangle tri = make_triangle(rng.in_box(2), rng.in_box(2), rng.in_box(2));
    const Ray ray = testing::random_ray(rng, 5, 2);
    double tr = 0, margin = 0;
    const bool plane = plane_then_inside(tri, ray, tr, margin);
    if (std::abs(margin) < 1e-9) continue;  // within rounding of an edge: either answer is right
    const bool ref = plane && tr >= 0;
    LocalHit h;
    const bool hit = intersect(tri, ray, h);
    ASSERT_EQ(hit, ref) << "case " << i;
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(h.t, tr, 1e-9 * std::abs(tr) + 1e-12) << "case " << i;
    const SurfaceInfo si = surface(tri, ray, h);
    testing::expect_unit(si.n);
    EXPECT_NEAR(dot(si.n, cross(tri.p1 - tri.p0, tri.p2 - tri.p0)),
                length(cross(tri.p1 - tri.p0, tri.p2 - tri.p0)), 1e-9);
    // (u, v) = (b1, b2) reconstruct the hit point.
    const Vec3 p = (1 - si.u - si.v) * tri.p0 + si.u * tri.p1 + si.v * tri.p2;
    EXPECT_NEAR(length(p - ray.at(h.t)), 0, 1e-9) << "case " << i;
    EXPECT_GE(si.u, 0);
    EXPECT_GE(si.v, 0);
    EXPECT_LE(si.u + si.v, 1);
  }
  EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace raycast
