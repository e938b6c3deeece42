#include "geometry/polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

// The winding number of the 2D polygon around q by summed angles in long double: an
// independent inside test for points off the edges.
bool winding_inside(const std::vector<Vec3>& v, double qx, double qy) {
  long double sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    const Vec3& b = v[(i + 1) % v.size()];
    const long double a1 = std::atan2((long double)a.y - qy, (long double)a.x - qx);
    const long double a2 = std::atan2((long double)b.y - qy, (long double)b.x - qx);
    long double d = a2 - a1;
    while (d > std::numbers::pi_v<long double>) d -= 2 * std::numbers::pi_v<long double>;
    while (d < -std::numbers::pi_v<long double>) d += 2 * std::numbers::pi_v<long double>;
    sum += d;
  }
  return std::abs(sum) > std::numbers::pi_v<long double>;
}

// A concave star-shaped polygon in the z = 0 plane, counter-clockwise seen from +z.
std::vector<Vec3> star(int points) {
  std::vector<Vec3> v;
  for (int i = 0; i < 2 * points; ++i) {
    const double a = i * std::numbers::pi / points, r = i % 2 ? 0.4 : 1.0;
    v.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  return v;
}

TEST(Polygon, SquareHitInTheMiddle_HasNormalPlusZAndPlaneCoordinates) {
  const Polygon p = make_polygon({{0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}});
  const Ray ray{{0.5, 1.5, 5}, {0, 0, -2}};
  LocalHit h;
  ASSERT_TRUE(intersect(p, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 2);
  const SurfaceInfo si = surface(p, ray, h);
  EXPECT_EQ(si.n, (Vec3{0, 0, 1}));
  EXPECT_DOUBLE_EQ(si.u, 0.5);  // along the first edge (+x) from the first vertex
  EXPECT_DOUBLE_EQ(si.v, 1.5);  // along n x u = +y
  EXPECT_FALSE(is_closed(p));
}

TEST(Polygon, ClockwiseVertices_FlipTheNormal) {
  const Polygon p = make_polygon({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}});
  EXPECT_EQ(p.n, (Vec3{0, 0, -1}));
}

TEST(Polygon, ConcaveStar_RandomRaysMatchTheWindingNumber) {
  const std::vector<Vec3> v = star(5);
  // Tilted out of an axis plane so the projection is not trivial.
  const Transform xf = Transform::rotate({1, 0.3, 0}, 50);
  std::vector<Vec3> tilted;
  for (const Vec3& q : v) tilted.push_back(xf.point(q));
  const Polygon p = make_polygon(tilted);
  Rng rng(17);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 q{rng.uniform(-1.1, 1.1), rng.uniform(-1.1, 1.1), 0};
    const Vec3 target = xf.point(q);
    const Vec3 o = target + 3.0 * rng.direction();
    const Ray ray{o, target - o};
    SCOPED_TRACE("seed 17, " + testing::describe(ray));
    LocalHit h;
    const bool hit = intersect(p, ray, h);
    EXPECT_EQ(hit, winding_inside(v, q.x, q.y));
    if (hit) {
      ++hits;
      EXPECT_NEAR(h.t, 1, 1e-9);
      EXPECT_NEAR(length(surface(p, ray, h).n), 1, 1e-15);
    }
  }
  EXPECT_GT(hits, 1000);
}

TEST(Polygon, PointOnASharedEdge_BelongsToExactlyOneOfTwoPolygons) {
  // A quad split along a skew diagonal; rays aimed at points on (rounded next to) the diagonal.
  const Vec3 a{0.1, 0.05, 0}, b{1, 0.1, 0}, c{0.93, 1.37, 0}, d{-0.2, 0.8, 0};
  const Polygon left = make_polygon({a, b, c});
  const Polygon right = make_polygon({a, c, d});
  Rng rng(19);
  int doubles = 0, holes = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 q = a + rng.uniform(0.01, 0.99) * (c - a);
    const Ray ray{{q.x, q.y, 1}, {0, 0, -1}};
    LocalHit h;
    const int count = intersect(left, ray, h) + intersect(right, ray, h);
    doubles += count == 2;
    holes += count == 0;
  }
  EXPECT_EQ(doubles, 0);
  EXPECT_EQ(holes, 0);
}

TEST(Polygon, ParallelRayAndTMinTMax) {
  const Polygon p = make_polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  LocalHit h;
  EXPECT_FALSE(intersect(p, Ray{{0.2, 0.2, 0}, {1, 0, 0}}, h));
  EXPECT_FALSE(intersect(p, Ray{{0.2, 0.2, 1}, {1, 0, 0}}, h));
  EXPECT_TRUE(intersect(p, Ray{{0.2, 0.2, 1}, {0, 0, -1}, 0, 1}, h));
  EXPECT_FALSE(intersect(p, Ray{{0.2, 0.2, 1}, {0, 0, -1}, 0, std::nextafter(1.0, 0.0)}, h));
  EXPECT_FALSE(intersect(p, Ray{{0.2, 0.2, 1}, {0, 0, -1}, std::nextafter(1.0, 2.0), 2}, h));
  SpanList sl;
  spans(p, Ray{{0.2, 0.2, 1}, {0, 0, 1}}, sl);  // spans cover the whole line
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].in.t, -1);
}

TEST(Polygon, MakePolygon_RejectsBadInput) {
  EXPECT_THROW(make_polygon({{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(make_polygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}),
               std::invalid_argument);  // zero area
  EXPECT_THROW(make_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.01}, {0, 1, 0}}),
               std::invalid_argument);  // not planar
  EXPECT_THROW(make_polygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}),
               std::invalid_argument);  // bow tie
  EXPECT_THROW(make_polygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}),
               std::invalid_argument);  // repeat
  // Planarity is relative to the size: the same shape scaled by 1e6 stays valid.
  EXPECT_NO_THROW(make_polygon({{0, 0, 0}, {1e6, 0, 0}, {1e6, 1e6, 1e-3}, {0, 1e6, 0}}));
  try {
    make_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.01}, {0, 1, 0}});
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("vertices[", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace raycast
