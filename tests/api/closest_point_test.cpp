// mesh/closest_point: the oriented-box tree returns exactly what a test of every triangle does
// (the same point, squared distance and, on ties, the least input triangle).
#include "mesh/closest_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "geometry/distance.h"

namespace raycast {
namespace {

struct Soup {
  std::vector<Vec3f> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// A UV sphere of radius r about c: smooth and curved, the case the oriented boxes are for.
Soup sphere(int rows, int cols, double r, const Vec3& c) {
  Soup s;
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double th = M_PI * i / rows, ph = 2 * M_PI * j / cols;
      s.positions.push_back(Vec3f(
          c + r * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th))));
    }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * cols + (j % cols)); };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      if (i + 1 < rows) s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      if (i > 0) s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return s;
}

// Random triangles of every size and orientation (thin slivers included) in a box of side 2.
Soup random_soup(std::mt19937& rng, int n, const Vec3& offset) {
  std::uniform_real_distribution<double> u(-1, 1), small(-0.05, 0.05);
  Soup s;
  for (int i = 0; i < n; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng));
    const bool sliver = i % 5 == 0;
    const Vec3 b = a + (sliver ? Vec3(u(rng), u(rng), u(rng)) : Vec3(small(rng), small(rng), 0));
    const Vec3 c =
        sliver ? a + 1e-4 * (b - a) + Vec3(0, 1e-6, 0) : a + Vec3(small(rng), 0, small(rng));
    for (const Vec3& v : {a, b, c}) s.positions.push_back(Vec3f(v + offset));
    const auto k = static_cast<std::uint32_t>(3 * i);
    s.triangles.push_back({k, k + 1, k + 2});
  }
  return s;
}

MeshDistance::Result brute_force(const Mesh& mesh, const std::optional<Transform>& xf,
                                 const Vec3& p) {
  MeshDistance::Result best;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = Vec3(mesh.positions[mesh.triangles[i][k]]);
      if (xf) v[k] = xf->point(v[k]);
    }
    const Vec3 q = closest_point_on_triangle(p, v[0], v[1], v[2]);
    const double d2 = length_squared(q - p);
    const auto prim = static_cast<std::int32_t>(mesh.source[i]);
    if (d2 < best.distance2 || (d2 == best.distance2 && prim < best.prim)) best = {q, d2, prim};
  }
  return best;
}

void expect_same_as_brute_force(const Soup& soup, const std::optional<Transform>& xf,
                                const std::vector<Vec3>& points) {
  const auto mesh = make_mesh(soup.positions, soup.triangles);
  const MeshDistance tree(*mesh, xf);
  for (const Vec3& p : points) {
    MeshDistance::Result got;
    tree.closest(p, got);
    const MeshDistance::Result want = brute_force(*mesh, xf, p);
    ASSERT_EQ(got.distance2, want.distance2) << p.x << " " << p.y << " " << p.z;
    ASSERT_EQ(got.prim, want.prim);
    ASSERT_EQ(got.point, want.point);
  }
}

std::vector<Vec3> points_around(std::mt19937& rng, const Soup& soup, double spread, int n) {
  std::uniform_real_distribution<double> u(-spread, spread);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  // On the surface: vertices, edge midpoints, and points just off them.
  for (std::size_t i = 0; i < soup.triangles.size(); i += 7) {
    const Vec3 a(soup.positions[soup.triangles[i][0]]), b(soup.positions[soup.triangles[i][1]]);
    points.push_back(a);
    points.push_back(0.5 * (a + b));
    points.push_back(0.5 * (a + b) + Vec3(1e-9, -1e-9, 1e-9));
  }
  return points;
}

TEST(MeshDistance, CurvedSphere_EqualsBruteForce) {
  std::mt19937 rng(1);
  const Soup s = sphere(40, 60, 1, {0.25, 0, 0});
  expect_same_as_brute_force(s, std::nullopt, points_around(rng, s, 1.6, 1500));
}

TEST(MeshDistance, SphereUnderRotationAndNonUniformScale_EqualsBruteForce) {
  std::mt19937 rng(2);
  const Soup s = sphere(30, 40, 1, {0, 0, 0});
  const Transform xf = Transform::translate({1, 2, 3}) * Transform::rotate({1, 2, 0.5}, 33) *
                       Transform::scale({1, 0.25, 3});
  std::vector<Vec3> points = points_around(rng, s, 2.5, 1000);
  for (Vec3& p : points) p += Vec3(1, 2, 3);
  expect_same_as_brute_force(s, xf, points);
}

TEST(MeshDistance, RandomSoupWithSlivers_EqualsBruteForce) {
  std::mt19937 rng(3);
  const Soup s = random_soup(rng, 600, {0, 0, 0});
  expect_same_as_brute_force(s, std::nullopt, points_around(rng, s, 3, 1500));
}

TEST(MeshDistance, FarFromOrigin_EqualsBruteForce) {
  // Coordinates near 1e5: float rounding of the boxes is large against the triangles' sizes.
  std::mt19937 rng(4);
  const Vec3 offset(1e5, -2e5, 3e5);
  const Soup s = random_soup(rng, 300, offset);
  std::vector<Vec3> points = points_around(rng, s, 1.5, 800);
  for (std::size_t i = 0; i < 800; ++i) points[i] += offset;
  expect_same_as_brute_force(s, std::nullopt, points);
}

TEST(MeshDistance, CentreOfSphere_EqualsBruteForce) {
  // Every leaf about equally near: the best-first walk's queue holds most of the tree.
  const Soup s = sphere(60, 80, 1, {0, 0, 0});
  expect_same_as_brute_force(s, std::nullopt, {{0, 0, 0}, {1e-9, 0, 0}, {0, 0, 1e-3}});
}

TEST(MeshDistance, HugeCoordinates_EqualsBruteForce) {
  // A mesh scaled to 4e15 (beyond float's exact integers; squares near 1e32), and points 1e17
  // away from a unit mesh.
  std::mt19937 rng(7);
  const Soup s = sphere(20, 30, 1, {0, 0, 0});
  std::vector<Vec3> points = points_around(rng, s, 1.6, 400);
  std::vector<Vec3> scaled;
  for (const Vec3& p : points) scaled.push_back(4e15 * p);
  expect_same_as_brute_force(s, Transform::scale({4e15, 4e15, 4e15}), scaled);
  std::vector<Vec3> far;
  for (int i = 0; i < 200; ++i) far.push_back(1e17 * points[static_cast<std::size_t>(i)]);
  expect_same_as_brute_force(s, std::nullopt, far);
}

TEST(MeshDistance, FewTrianglesAndFarPoints_EqualsBruteForce) {
  std::mt19937 rng(5);
  for (int n : {1, 3, 4, 5, 9}) {
    const Soup s = random_soup(rng, n, {0, 0, 0});
    expect_same_as_brute_force(s, std::nullopt, points_around(rng, s, 1e6, 200));
  }
}

TEST(MeshDistance, EquidistantTriangles_LeastInputIndexWins) {
  // Two copies of one triangle, then a third: every point is equally near to copies 0 and 1.
  Soup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.triangles = {{3, 4, 5}, {0, 1, 2}};
  for (int i = 0; i < 20; ++i) {
    const auto k = static_cast<std::uint32_t>(s.positions.size());
    s.positions.push_back(Vec3f(5.f + static_cast<float>(i), 0, 0));
    s.positions.push_back(Vec3f(6.f + static_cast<float>(i), 0, 0));
    s.positions.push_back(Vec3f(5.f + static_cast<float>(i), 1, 0));
    s.triangles.push_back({k, k + 1, k + 2});
  }
  const auto mesh = make_mesh(s.positions, s.triangles);
  const MeshDistance tree(*mesh, std::nullopt);
  MeshDistance::Result r;
  tree.closest({0.25, 0.25, 1}, r);
  EXPECT_EQ(r.prim, 0);
  EXPECT_EQ(r.distance2, 1);
}

TEST(MeshDistance, BoundAlreadyBetter_LeavesResultUnchanged) {
  std::mt19937 rng(6);
  const Soup s = sphere(20, 20, 1, {0, 0, 0});
  const auto mesh = make_mesh(s.positions, s.triangles);
  const MeshDistance tree(*mesh, std::nullopt);
  MeshDistance::Result r;
  r.distance2 = 0.25;  // the sphere is 1.5 from this point: nothing is nearer than 0.5
  EXPECT_FALSE(tree.closest({0, 0, 2.5}, r));
  EXPECT_EQ(r.prim, -1);
  EXPECT_TRUE(tree.closest({0, 0, 1.25}, r));
  EXPECT_NEAR(std::sqrt(r.distance2), 0.25, 0.02);  // the polygon is within 0.013 of the sphere
}

}  // namespace
}  // namespace raycast
