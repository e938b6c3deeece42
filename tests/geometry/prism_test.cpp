#include "geometry/prism.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "geometry/prism_spline.h"
#include "geometry/shape_checks.h"

namespace raycast {
namespace {

using Points = std::vector<std::array<double, 2>>;

Prism linear(const Points& p, double z0, double z1, bool conic = false, bool open = false) {
  return make_prism(spline_contours(p, PrismSpline::kLinear), z0, z1, conic, open);
}

// The unit square's ring: [-1, 1]^2 less [-0.5, 0.5]^2, z in [0, 1].
Prism square_ring() {
  return linear({{-1, -1},
                 {1, -1},
                 {1, 1},
                 {-1, 1},
                 {-1, -1},
                 {-0.5, -0.5},
                 {0.5, -0.5},
                 {0.5, 0.5},
                 {-0.5, 0.5},
                 {-0.5, -0.5}},
                0, 1);
}

// The region under the parabola y = 1 - x^2 above y = 0: one quadratic Bezier piece from (-1, 0)
// through the control point (0, 2) to (1, 0), and the straight piece back.
Prism parabola_prism() {
  ContourPiece arc;
  arc.degree = 2;
  arc.p[0] = {-1, 0};
  arc.p[1] = {0, 2};
  arc.p[2] = {1, 0};
  ContourPiece base;
  base.p[0] = {1, 0};
  base.p[1] = {-1, 0};
  return make_prism({{arc, base}}, -1, 1);
}

// The number of crossings intersect reports on the open segment from a to b, found by restarting
// just past each one.
int crossings_between(const Prism& s, const Vec3& a, const Vec3& b) {
  Ray r{a, b - a, 0, 1};
  int n = 0;
  LocalHit h;
  while (n < 64 && intersect(s, r, h)) {
    ++n;
    r.tmin = h.t + 1e-9;
  }
  return n;
}

TEST(Prism, SquareRing_SidesAndCapsAtKnownT) {
  const Prism s = square_ring();
  LocalHit h;
  // Along +x at y = 0.2: the outer side at x = -1 (t = 4).
  const Ray side{{-5, 0.2, 0.5}, {1, 0, 0}};
  ASSERT_TRUE(intersect(s, side, h));
  EXPECT_NEAR(h.t, 4, 1e-12);
  SurfaceInfo si = surface(s, side, h);
  EXPECT_NEAR(si.n.x, -1, 1e-12);
  EXPECT_NEAR(si.p.x, -1, 1e-12);
  // The spans: [-1, -0.5] and [0.5, 1].
  SpanList sl;
  spans(s, side, sl);
  ASSERT_EQ(sl.size(), 2u);
  EXPECT_NEAR(sl[0].in.t, 4, 1e-12);
  EXPECT_NEAR(sl[0].out.t, 4.5, 1e-12);
  EXPECT_NEAR(sl[1].in.t, 5.5, 1e-12);
  EXPECT_NEAR(sl[1].out.t, 6, 1e-12);
  // The inner side seen from the hole faces into the hole: -x at x = 0.5.
  si = surface(s, side, sl[1].in);
  EXPECT_NEAR(si.n.x, -1, 1e-12);
  si = surface(s, side, sl[0].out);
  EXPECT_NEAR(si.n.x, 1, 1e-12);
  // Down onto the ring: the top cap at z = 1 (t = 2), normal +z.
  const Ray down{{0.75, 0.75, 3}, {0, 0, -1}};
  ASSERT_TRUE(intersect(s, down, h));
  EXPECT_NEAR(h.t, 2, 1e-12);
  EXPECT_NEAR(surface(s, down, h).n.z, 1, 1e-12);
  // Up from below: the bottom cap, normal -z.
  const Ray up{{0.75, -0.75, -2}, {0, 0, 2}};
  ASSERT_TRUE(intersect(s, up, h));
  EXPECT_NEAR(h.t, 1, 1e-12);
  EXPECT_NEAR(surface(s, up, h).n.z, -1, 1e-12);
  // Down through the hole: nothing.
  EXPECT_FALSE(intersect(s, Ray{{0.1, -0.2, 3}, {0, 0, -1}}, h));
  EXPECT_FALSE(occluded(s, Ray{{0.1, -0.2, 3}, {0, 0, -1}}));
}

TEST(Prism, RayFromInside_LeavesThroughTheNearestWall) {
  const Prism s = square_ring();
  LocalHit h;
  const Ray r{{0.75, 0, 0.5}, {1, 0, 0}};
  ASSERT_TRUE(contains(s, r.o));
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 0.25, 1e-12);
  EXPECT_NEAR(surface(s, r, h).n.x, 1, 1e-12);
  const Ray r2{{0.75, 0, 0.5}, {-1, 0, 0}};
  ASSERT_TRUE(intersect(s, r2, h));
  EXPECT_NEAR(h.t, 0.25, 1e-12);
  EXPECT_NEAR(surface(s, r2, h).n.x, -1, 1e-12);  // the hole's wall faces into the hole
  const Ray r3{{0.75, 0, 0.25}, {0, 0, 1}};
  ASSERT_TRUE(intersect(s, r3, h));
  EXPECT_NEAR(h.t, 0.75, 1e-12);
}

TEST(Prism, QuadraticPiece_MatchesTheParabola) {
  const Prism s = parabola_prism();
  LocalHit h;
  for (double y : {0.1, 0.5, 0.75, 0.99}) {
    SCOPED_TRACE(y);
    // Along +x at height y: the parabola at x = -sqrt(1 - y).
    const Ray r{{-5, y, 0.3}, {2, 0, 0}};
    ASSERT_TRUE(intersect(s, r, h));
    EXPECT_NEAR(h.t, (5 - std::sqrt(1 - y)) / 2, 1e-12);
    const SurfaceInfo si = surface(s, r, h);
    // The outward normal of y = 1 - x^2 at x: (2x, 1) normalised.
    const double x = -std::sqrt(1 - y), len = std::hypot(2 * x, 1.0);
    EXPECT_NEAR(si.n.x, 2 * x / len, 1e-9);
    EXPECT_NEAR(si.n.y, 1 / len, 1e-9);
    SpanList sl;
    spans(s, r, sl);
    ASSERT_EQ(sl.size(), 1u);
    EXPECT_NEAR(sl[0].out.t, (5 + std::sqrt(1 - y)) / 2, 1e-12);
  }
  // Straight down onto the arc's slope at x = 0.5: y = 0.75.
  const Ray r{{0.5, 4, 0}, {0, -1, 0}};
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 4 - 0.75, 1e-12);
}

TEST(Prism, TangentAndGrazingRays) {
  const Prism s = parabola_prism();
  LocalHit h;
  // Tangent to the parabola's apex (0, 1): a touch or a miss, never a hit elsewhere.
  const Ray tangent{{-5, 1, 0}, {1, 0, 0}};
  if (intersect(s, tangent, h)) {
    EXPECT_NEAR(h.t, 5, 1e-6);
  }
  // Just above it: a miss; just below: two crossings close to x = -+1e-4.
  EXPECT_FALSE(intersect(s, Ray{{-5, 1 + 1e-8, 0}, {1, 0, 0}}, h));
  SpanList sl;
  spans(s, Ray{{-5, 1 - 1e-8, 0}, {1, 0, 0}}, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_NEAR(sl[0].in.t, 5 - 1e-4, 1e-9);
  EXPECT_NEAR(sl[0].out.t, 5 + 1e-4, 1e-9);
  // Grazing the top cap's plane just above it: a miss; just below it: the side walls.
  const Prism ring = square_ring();
  EXPECT_FALSE(intersect(ring, Ray{{-5, 0.8, 1 + 1e-12}, {1, 0, 0}}, h));
  ASSERT_TRUE(intersect(ring, Ray{{-5, 0.8, 1 - 1e-12}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.t, 4, 1e-12);
  // Along a side wall's plane: a ray at x = -1 exactly never reports a point off the wall.
  if (intersect(ring, Ray{{-1, -5, 0.5}, {0, 1, 0}}, h)) {
    EXPECT_NEAR(surface(ring, Ray{{-1, -5, 0.5}, {0, 1, 0}}, h).p.x, -1, 1e-12);
  }
}

TEST(Prism, ConicSweep_Pyramid) {
  // The square [-1, 1]^2 swept to the origin: the pyramid |x|, |y| <= z, z in [0, 1].
  const Prism s = linear({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}, 0, 1, true);
  LocalHit h;
  const Ray down{{0.2, 0.3, 5}, {0, 0, -1}};
  ASSERT_TRUE(intersect(s, down, h));
  EXPECT_NEAR(h.t, 4, 1e-12);
  EXPECT_NEAR(surface(s, down, h).n.z, 1, 1e-12);
  const Ray side{{-5, 0.1, 0.5}, {1, 0, 0}};
  ASSERT_TRUE(intersect(s, side, h));
  EXPECT_NEAR(h.t, 4.5, 1e-12);
  const SurfaceInfo si = surface(s, side, h);
  EXPECT_NEAR(si.n.x, -std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(si.n.y, 0, 1e-12);
  EXPECT_NEAR(si.n.z, -std::sqrt(0.5), 1e-12);
  SpanList sl;
  spans(s, side, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_NEAR(sl[0].out.t, 5.5, 1e-12);
  // Under the apex: nothing; inside near the top: contained.
  EXPECT_FALSE(intersect(s, Ray{{0.5, 0, -1}, {1, 0, 0}}, h));
  EXPECT_TRUE(contains(s, {0.4, -0.4, 0.5}));
  EXPECT_FALSE(contains(s, {0.6, 0, 0.5}));
  // The box: the square at z = 1 and the apex.
  EXPECT_EQ(bounds(s).lo.z, 0);
  EXPECT_EQ(bounds(s).hi.x, 1);
}

TEST(Prism, Open_HasNoCapsAndNoInside) {
  const Prism s = linear({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}, 0, 1, false, true);
  LocalHit h;
  EXPECT_FALSE(is_closed(s));
  EXPECT_FALSE(contains(s, {0, 0, 0.5}));
  const Ray down{{0.2, 0.3, 5}, {0, 0, -1}};
  EXPECT_FALSE(intersect(s, down, h));
  const Ray side{{-5, 0.1, 0.5}, {1, 0, 0}};
  SpanList sl;
  spans(s, side, sl);
  ASSERT_EQ(sl.size(), 2u);
  EXPECT_EQ(sl[0].in.t, sl[0].out.t);
}

// Random rays: crossings counted by intersect between two points match the change of contains,
// spans match contains, normals point out, and the nearest hit is the first span end.
void check_random_rays(const Prism& s, double reach, int seed) {
  std::mt19937 rng(static_cast<unsigned>(seed));
  std::uniform_real_distribution<double> u(-1, 1);
  const auto inside = [&](const Vec3& p) { return contains(s, p); };
  const Vec3 c = 0.5 * (bounds(s).lo + bounds(s).hi);
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE(i);
    const Vec3 a = c + reach * Vec3{u(rng), u(rng), u(rng)};
    const Vec3 b = c + reach * Vec3{u(rng), u(rng), u(rng)};
    const int n = crossings_between(s, a, b);
    EXPECT_EQ(n % 2 == 1, contains(s, a) != contains(s, b));
    const Ray r{a, b - a};
    testing::check_spans_against_oracle(s, r, inside, -2, 3, 300);
    LocalHit h;
    if (!intersect(s, r, h)) continue;
    ++hits;
    EXPECT_NEAR(h.t, testing::first_span_end(s, r), 1e-9);
    testing::expect_outward_normal(s, r, h, inside, 1e-6);
  }
  EXPECT_GT(hits, 50);
}

TEST(Prism, RandomRays_LinearRing) { check_random_rays(square_ring(), 1.5, 1); }
TEST(Prism, RandomRays_Parabola) { check_random_rays(parabola_prism(), 1.5, 2); }
TEST(Prism, RandomRays_CubicAndBezierAndQuadratic) {
  const Points star = {{1, 0},  {0.3, 0.3},   {0, 1},  {-0.3, 0.3},
                       {-1, 0}, {-0.3, -0.3}, {0, -1}, {0.3, -0.3}};
  Points cubic = {star.back()};
  cubic.insert(cubic.end(), star.begin(), star.end());
  cubic.push_back(star[0]);
  cubic.push_back(star[1]);
  check_random_rays(make_prism(spline_contours(cubic, PrismSpline::kCubic), -0.5, 0.5), 1.3, 3);
  Points quad = {star.back()};
  quad.insert(quad.end(), star.begin(), star.end());
  quad.push_back(star[0]);
  check_random_rays(make_prism(spline_contours(quad, PrismSpline::kQuadratic), -0.5, 0.5), 1.3, 4);
  const Points bez = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 1}, {-1, 1}, {-1, 0}, {0, 0}};
  check_random_rays(make_prism(spline_contours(bez, PrismSpline::kBezier), 0, 2), 1.5, 5);
  check_random_rays(make_prism(spline_contours(cubic, PrismSpline::kCubic), 0.2, 1.5, true), 1.5,
                    6);
}

TEST(Prism, SplineContours_ClosePointsAsPovRayReadsThem) {
  // Quadratic: P0 a control point, P1 the start, closing at P1: 4 pieces.
  const Points q = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}};
  const auto c = spline_contours(q, PrismSpline::kQuadratic);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].size(), 4u);
  // The piece from (1, 0) to (0, 1) with tangent ((0, 1) - (0, -1)) / 2 at its start.
  EXPECT_EQ(c[0][0].p[1][0], 1);
  EXPECT_EQ(c[0][0].p[1][1], 0.5);
  // Two linear sub-shapes.
  EXPECT_EQ(spline_contours({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {2, 2}, {3, 2}, {3, 3}, {2, 2}},
                            PrismSpline::kLinear)
                .size(),
            2u);
  EXPECT_THROW(spline_contours({{0, 0}, {1, 0}, {1, 1}}, PrismSpline::kBezier),
               std::invalid_argument);
  EXPECT_THROW(make_prism({}, 0, 1), std::invalid_argument);
  EXPECT_THROW(linear({{0, 0}, {1, 0}, {1, 1}, {0, 0}}, 1, 1), std::invalid_argument);
  EXPECT_THROW(linear({{0, 0}, {1, 0}, {1, 1}, {0, 0}}, -1, 1, true), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
