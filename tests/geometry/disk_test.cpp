#include "geometry/disk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

constexpr double kPi = std::numbers::pi;

// The disk's parametrisation of docs/shapes-basic.md: r = radius - v (radius - inner), phi = u
// phi_max.
Vec3 point_from_uv(double radius, double inner, double height, double phi_max, double u, double v) {
  const double r = radius - v * (radius - inner);
  const double phi = u * phi_max;
  return {r * std::cos(phi), r * std::sin(phi), height};
}

TEST(Disk, MakeDisk_RejectsBadParameters) {
  EXPECT_THROW(make_disk(0), std::invalid_argument);
  EXPECT_THROW(make_disk(-1), std::invalid_argument);
  EXPECT_THROW(make_disk(kInfinity), std::invalid_argument);
  EXPECT_THROW(make_disk(1, 1), std::invalid_argument);
  EXPECT_THROW(make_disk(1, -0.5), std::invalid_argument);
  EXPECT_THROW(make_disk(1, std::nan("")), std::invalid_argument);
  EXPECT_THROW(make_disk(1, 0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(make_disk(1, 0, 0, 0), std::invalid_argument);
  EXPECT_THROW(make_disk(1, 0, 0, 360.5), std::invalid_argument);
  EXPECT_THROW(make_disk({0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(make_disk({0, kInfinity, 0}, {0, 0, 1}, 1), std::invalid_argument);
}

TEST(Disk, HandComputedHit_ExactTUvAndNormal) {
  const Disk d = make_disk(2, 1, 0.5, 180);
  const Ray ray{{0, 1.5, 4.5}, {0, 0, -2}};
  LocalHit h;
  ASSERT_TRUE(intersect(d, ray, h));
  EXPECT_EQ(h.t, 2);
  const SurfaceInfo si = surface(d, ray, h);
  EXPECT_EQ(si.p, Vec3(0, 1.5, 0.5));
  EXPECT_EQ(si.n, Vec3(0, 0, 1));
  EXPECT_NEAR(si.u, 0.5, 1e-15);  // phi = 90 of 180 degrees
  EXPECT_EQ(si.v, 0.5);           // (2 - 1.5) / (2 - 1)
  // From below: the normal is still +z (queries never flip).
  ASSERT_TRUE(intersect(d, Ray{{0, 1.5, -1}, {0, 0, 1}}, h));
  EXPECT_EQ(surface(d, Ray{{0, 1.5, -1}, {0, 0, 1}}, h).n, Vec3(0, 0, 1));
}

TEST(Disk, HoleSectorAndRim_AreHandledInclusively) {
  const Disk d = make_disk(2, 1, 0, 90);
  LocalHit h;
  EXPECT_FALSE(intersect(d, Ray{{0.5, 0.5, 1}, {0, 0, -1}}, h));   // in the hole
  EXPECT_TRUE(intersect(d, Ray{{1, 0, 1}, {0, 0, -1}}, h));        // on the inner rim, phi = 0
  EXPECT_TRUE(intersect(d, Ray{{0, 2, 1}, {0, 0, -1}}, h));        // outer rim at phi = 90
  EXPECT_FALSE(intersect(d, Ray{{-1.5, 0.1, 1}, {0, 0, -1}}, h));  // outside the sector
  EXPECT_FALSE(intersect(d, Ray{{1.5, -0.1, 1}, {0, 0, -1}}, h));  // phi just below 360
  EXPECT_FALSE(intersect(d, Ray{{2.0000001, 0, 1}, {0, 0, -1}}, h));
  EXPECT_FALSE(intersect(d, Ray{{1.5, 0.5, 1}, {1, 0, 0}}, h));  // parallel
  EXPECT_FALSE(intersect(d, Ray{{1.5, 0.5, 1}, {0, 0, 1}}, h));  // behind
}

TEST(Disk, TminTmax_InclusiveAtBothEnds) {
  const Disk d = make_disk(1);
  LocalHit h;
  EXPECT_TRUE(intersect(d, Ray{{0, 0, 3}, {0, 0, -1}, 0, 3}, h));
  EXPECT_FALSE(intersect(d, Ray{{0, 0, 3}, {0, 0, -1}, 0, std::nextafter(3.0, 0.0)}, h));
  EXPECT_TRUE(intersect(d, Ray{{0, 0, 3}, {0, 0, -1}, 3, 4}, h));
  EXPECT_FALSE(intersect(d, Ray{{0, 0, 3}, {0, 0, -1}, std::nextafter(3.0, 4.0), 4}, h));
}

TEST(Disk, CenterNormalForm_FacesAlongNormal) {
  const Disk d = make_disk({1, 2, 3}, {0, 2, 0}, 1, 0.5);
  LocalHit h;
  const Ray ray{{1.75, 10, 3}, {0, -4, 0}};
  ASSERT_TRUE(intersect(d, ray, h));
  EXPECT_EQ(h.t, 2);
  const SurfaceInfo si = surface(d, ray, h);
  EXPECT_NEAR(length(si.p - Vec3(1.75, 2, 3)), 0, 1e-15);
  EXPECT_EQ(si.n, Vec3(0, 1, 0));
  EXPECT_NEAR(si.v, 0.5, 1e-15);                                     // r = 0.75 between 0.5 and 1
  EXPECT_FALSE(intersect(d, Ray{{1.25, 10, 3.25}, {0, -1, 0}}, h));  // r = 0.35: in the hole
  const Aabb b = bounds(d);
  EXPECT_TRUE(b.contains({2, 2, 3}));
  EXPECT_TRUE(b.contains({1, 2, 2}));
  EXPECT_LT(b.hi.y - b.lo.y, 1e-12);
}

TEST(Disk, RandomRays_MatchPlaneThenRadiusAndAngle) {
  const unsigned seed = 99;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  std::uniform_real_distribution<double> uni(0, 1);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const double radius = 0.5 + 2 * uni(rng), inner = radius * uni(rng) * 0.8;
    const double height = 2 * uni(rng) - 1, phi_deg = 10 + 350 * uni(rng);
    const Disk d = make_disk(radius, inner, height, phi_deg);
    const Ray ray = testing::random_ray(rng, 4, 2.5);
    if (ray.d.z == 0) continue;
    const double tr = (height - ray.o.z) / ray.d.z;
    const Vec3 p = ray.at(tr);
    const double r = std::hypot(p.x, p.y);
    double phi = std::atan2(p.y, p.x);
    if (phi < 0) phi += 2 * kPi;
    const double phi_max = phi_deg * kPi / 180;
    if (std::abs(r - radius) < 1e-9 || std::abs(r - inner) < 1e-9 ||
        std::abs(phi - phi_max) < 1e-9 || phi < 1e-9)
      continue;
    const bool ref = tr >= 0 && r <= radius && r >= inner && phi <= phi_max;
    LocalHit h;
    const bool hit = intersect(d, ray, h);
    ASSERT_EQ(hit, ref) << "case " << i;
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(h.t, tr, 1e-12 * std::abs(tr) + 1e-15);
    const SurfaceInfo si = surface(d, ray, h);
    EXPECT_EQ(si.n, Vec3(0, 0, 1));
    EXPECT_EQ(si.p.z, height);
    const Vec3 q = point_from_uv(radius, inner, height, phi_max, si.u, si.v);
    EXPECT_NEAR(length(q - si.p), 0, 1e-9) << "case " << i;
  }
  EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace raycast
