#include "geometry/parallelogram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

// Reference (the seed's linear system): the plane first, then (a, b) from the 2x2 Gram system
// [u.u u.v; u.v v.v] (a, b) = (u.r, v.r) with r = p - origin.
bool plane_then_solve(const Parallelogram& q, const Ray& ray, double& t, double& a, double& b) {
  const Vec3 n = cross(q.u, q.v);
  const double dn = dot(n, ray.d);
  if (dn == 0) return false;
  t = dot(n, q.origin - ray.o) / dn;
  const Vec3 r = ray.at(t) - q.origin;
  const double uu = dot(q.u, q.u), uv = dot(q.u, q.v), vv = dot(q.v, q.v);
  const double ur = dot(q.u, r), vr = dot(q.v, r);
  const double det = uu * vv - uv * uv;
  a = (ur * vv - vr * uv) / det;
  b = (vr * uu - ur * uv) / det;
  return true;
}

TEST(Parallelogram, MakeParallelogram_RejectsParallelZeroOrNonFiniteEdges) {
  EXPECT_THROW(make_parallelogram({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), std::invalid_argument);
  EXPECT_THROW(make_parallelogram({0, 0, 0}, {0, 0, 0}, {0, 1, 0}), std::invalid_argument);
  EXPECT_THROW(make_parallelogram({0, 0, std::nan("")}, {1, 0, 0}, {0, 1, 0}),
               std::invalid_argument);
  EXPECT_THROW(make_parallelogram({0, 0, 0}, {kInfinity, 0, 0}, {0, 1, 0}), std::invalid_argument);
}

TEST(Parallelogram, HandComputedHit_ExactTUvAndNormal) {
  // Corners (1,1,2), (5,1,2), (7,3,2), (3,3,2): u = (4,0,0), v = (2,2,0).
  const Parallelogram q = make_parallelogram({1, 1, 2}, {4, 0, 0}, {2, 2, 0});
  const Ray ray{{4, 2, 6}, {0, 0, -2}};
  LocalHit h;
  ASSERT_TRUE(intersect(q, ray, h));
  EXPECT_EQ(h.t, 2);
  const SurfaceInfo si = surface(q, ray, h);
  EXPECT_EQ(si.v, 0.5);  // y = 1 + 2 v
  EXPECT_EQ(si.u, 0.5);  // x = 1 + 4 u + 2 v
  EXPECT_EQ(si.p, Vec3(4, 2, 2));
  EXPECT_EQ(si.n, Vec3(0, 0, 1));  // normalize(u x v)
  EXPECT_FALSE(is_closed(q));
}

TEST(Parallelogram, EdgesInclusive_OutsideMisses) {
  const Parallelogram q = make_parallelogram({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  LocalHit h;
  for (const Vec3 o : {Vec3{0, 0, 1}, Vec3{1, 1, 1}, Vec3{1, 0.5, 1}, Vec3{0.5, 1, 1}})
    EXPECT_TRUE(intersect(q, Ray{o, {0, 0, -1}}, h)) << o.x << " " << o.y;
  EXPECT_FALSE(intersect(q, Ray{{1 + 1e-12, 0.5, 1}, {0, 0, -1}}, h));
  EXPECT_FALSE(intersect(q, Ray{{0.5, -1e-12, 1}, {0, 0, -1}}, h));
  EXPECT_FALSE(intersect(q, Ray{{0.5, 0.5, 1}, {1, 0, 0}}, h));  // parallel
  EXPECT_FALSE(intersect(q, Ray{{0.5, 0.5, 1}, {0, 0, 1}}, h));  // behind
}

TEST(Parallelogram, TminTmax_InclusiveAtBothEnds) {
  const Parallelogram q = make_parallelogram({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  LocalHit h;
  EXPECT_TRUE(intersect(q, Ray{{0.5, 0.5, 2}, {0, 0, -1}, 0, 2}, h));
  EXPECT_FALSE(intersect(q, Ray{{0.5, 0.5, 2}, {0, 0, -1}, 0, std::nextafter(2.0, 0.0)}, h));
  EXPECT_TRUE(intersect(q, Ray{{0.5, 0.5, 2}, {0, 0, -1}, 2, 3}, h));
  EXPECT_FALSE(intersect(q, Ray{{0.5, 0.5, 2}, {0, 0, -1}, std::nextafter(2.0, 3.0), 3}, h));
}

TEST(Parallelogram, RandomRays_MatchPlaneThenLinearSystem) {
  const unsigned seed = 555;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Parallelogram q = make_parallelogram(rng.in_box(1.5), rng.in_box(2), rng.in_box(2));
    const Ray ray = testing::random_ray(rng, 5, 2);
    double tr = 0, a = 0, b = 0;
    if (!plane_then_solve(q, ray, tr, a, b)) continue;
    const double margin = std::min({a, 1 - a, b, 1 - b});
    if (std::abs(margin) < 1e-9) continue;
    const bool ref = margin > 0 && tr >= 0;
    LocalHit h;
    const bool hit = intersect(q, ray, h);
    ASSERT_EQ(hit, ref) << "case " << i;
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(h.t, tr, 1e-9 * std::abs(tr) + 1e-12) << "case " << i;
    const SurfaceInfo si = surface(q, ray, h);
    EXPECT_NEAR(si.u, a, 1e-9);
    EXPECT_NEAR(si.v, b, 1e-9);
    testing::expect_unit(si.n);
    EXPECT_GT(dot(si.n, cross(q.u, q.v)), 0);
    EXPECT_NEAR(length(q.origin + si.u * q.u + si.v * q.v - ray.at(h.t)), 0, 1e-9);
  }
  EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace raycast
