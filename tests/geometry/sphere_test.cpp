#include "geometry/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

constexpr double kPi = std::numbers::pi;

// The geometric solution (Pelikan): project the centre onto the line, then step back and forth
// by the half chord. Independent of the algebraic solver under test.
bool geometric_roots(const Vec3& c, double r, const Ray& ray, double& t0, double& t1) {
  const double dd = dot(ray.d, ray.d);
  const double tc = dot(c - ray.o, ray.d) / dd;
  const Vec3 closest = ray.at(tc);
  const double h2 = r * r - length_squared(closest - c);
  if (h2 < 0) return false;
  const double half = std::sqrt(h2 / dd);
  t0 = tc - half;
  t1 = tc + half;
  return true;
}

TEST(Sphere, MakeSphere_RejectsBadParameters) {
  EXPECT_THROW(make_sphere({0, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, -1), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, kInfinity), std::invalid_argument);
  EXPECT_THROW(make_sphere({kInfinity, 0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, 1, 0.5, 0.5), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, 1, 2, 3), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, 1, -1, 1, 0), std::invalid_argument);
  EXPECT_THROW(make_sphere({0, 0, 0}, 1, -1, 1, 361), std::invalid_argument);
}

TEST(Sphere, HeadOnRay_ExactDistanceNormalAndUv) {
  const Sphere s = make_sphere({0, 0, 0}, 1);
  const Ray ray{{0, 0, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, ray, h));
  EXPECT_EQ(h.t, 4);
  const SurfaceInfo si = surface(s, ray, h);
  EXPECT_EQ(si.p, Vec3(0, 0, -1));
  EXPECT_EQ(si.n, Vec3(0, 0, -1));
  EXPECT_EQ(si.v, 0);  // the south pole
  // t in units of d: a direction of length 2 halves t.
  ASSERT_TRUE(intersect(s, Ray{{0, 0, 5}, {0, 0, -2}}, h));
  EXPECT_EQ(h.t, 2);
}

TEST(Sphere, OffCentreRay_MatchesHandComputedValues) {
  // Sphere at (1, 2, 3), radius 5; ray along +x at y = 2 + 3, z = 3: half chord 4, so x = 1 +- 4.
  const Sphere s = make_sphere({1, 2, 3}, 5);
  const Ray ray{{-10, 5, 3}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, ray, h));
  EXPECT_NEAR(h.t, 7, 1e-12);
  const SurfaceInfo si = surface(s, ray, h);
  EXPECT_NEAR(si.n.x, -0.8, 1e-12);
  EXPECT_NEAR(si.n.y, 0.6, 1e-12);
  EXPECT_NEAR(si.n.z, 0, 1e-12);
  // phi = atan2(0.6, -0.8), theta = pi / 2 -> v = 0.5.
  EXPECT_NEAR(si.u, std::atan2(0.6, -0.8) / (2 * kPi), 1e-12);
  EXPECT_NEAR(si.v, 0.5, 1e-12);
}

TEST(Sphere, TangentRay_TouchesOnce) {
  const Sphere s = make_sphere({0, 0, 0}, 1);
  const Ray ray{{1, 0, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, ray, h));
  EXPECT_EQ(h.t, 5);
  EXPECT_EQ(surface(s, ray, h).n, Vec3(1, 0, 0));
  EXPECT_FALSE(intersect(s, Ray{{std::nextafter(1.0, 2.0), 0, -5}, {0, 0, 1}}, h));
}

TEST(Sphere, RayBehindOrigin_Misses) {
  const Sphere s = make_sphere({0, 0, 0}, 1);
  LocalHit h;
  EXPECT_FALSE(intersect(s, Ray{{0, 0, 5}, {0, 0, 1}}, h));
  SpanList list;
  spans(s, Ray{{0, 0, 5}, {0, 0, 1}}, list);  // the whole line still crosses it
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].in.t, -6);
  EXPECT_EQ(list[0].out.t, -4);
}

TEST(Sphere, RayStartingInside_HitsTheFarSideWithOutwardNormal) {
  const Sphere s = make_sphere({0, 0, 0}, 2);
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, ray, h));
  EXPECT_EQ(h.t, 2);
  EXPECT_EQ(surface(s, ray, h).n, Vec3(1, 0, 0));
}

TEST(Sphere, TminTmax_InclusiveAtBothEnds) {
  const Sphere s = make_sphere({0, 0, 0}, 1);
  LocalHit h;
  EXPECT_TRUE(intersect(s, Ray{{0, 0, -5}, {0, 0, 1}, 0, 4}, h));
  EXPECT_FALSE(intersect(s, Ray{{0, 0, -5}, {0, 0, 1}, 0, std::nextafter(4.0, 0.0)}, h));
  ASSERT_TRUE(intersect(s, Ray{{0, 0, -5}, {0, 0, 1}, 6, kInfinity}, h));
  EXPECT_EQ(h.t, 6);
  EXPECT_FALSE(intersect(s, Ray{{0, 0, -5}, {0, 0, 1}, std::nextafter(6.0, 7.0), kInfinity}, h));
  ASSERT_TRUE(intersect(s, Ray{{0, 0, -5}, {0, 0, 1}, std::nextafter(4.0, 5.0), kInfinity}, h));
  EXPECT_EQ(h.t, 6);
}

TEST(Sphere, RandomRays_MatchGeometricSolution) {
  const unsigned seed = 2024;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  std::uniform_real_distribution<double> rad(0.1, 3);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 c = rng.in_box(2);
    const Sphere s = make_sphere(c, rad(rng));
    Ray ray = testing::random_ray(rng, 6, 3);
    ray.o += c;
    double g0 = 0, g1 = 0;
    const bool g = geometric_roots(c, s.radius, ray, g0, g1);
    LocalHit h;
    const bool hit = intersect(s, ray, h);
    // Skip near-tangent lines, where either method may round to the other answer.
    double tc0 = 0, tc1 = 0;
    if (g && g1 - g0 < 1e-6 * (std::abs(g0) + 1)) continue;
    if (!g && sphere_line_roots(ray.o - c, ray.d, s.radius, tc0, tc1)) continue;
    const double expect = g0 >= 0 ? g0 : g1;
    ASSERT_EQ(hit, g && g1 >= 0) << "case " << i;
    if (!hit) continue;
    EXPECT_NEAR(h.t, expect, 1e-9 * std::abs(expect) + 1e-12) << "case " << i;
    const SurfaceInfo si = surface(s, ray, h);
    testing::expect_unit(si.n);
    EXPECT_GT(dot(si.n, si.p - c), 0) << "normal points inwards, case " << i;
    EXPECT_NEAR(length(si.p - c), s.radius, 1e-12 * s.radius + 1e-12);
    EXPECT_GE(si.u, 0);
    EXPECT_LE(si.u, 1);
    EXPECT_GE(si.v, 0);
    EXPECT_LE(si.v, 1);
  }
}

// intersect() rejects early (outside and moving away; |f| clearly above r) before the roots:
// its answer must be exactly the roots' answer, also for rays leaving the surface (shadow and
// secondary rays), near-tangent lines and tmin < 0.
TEST(Sphere, EarlyRejections_AgreeExactlyWithTheRoots) {
  testing::Rng rng(77);
  int rejected_moving_away = 0, hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 c = rng.in_box(2);
    const Sphere s = make_sphere(c, rng.uniform(0.1, 3));
    Ray ray = testing::random_ray(rng, 6, 3);
    ray.o += c;
    if (i % 4 == 1) {  // from just off the surface, leaving it or grazing it
      const Vec3 n = rng.direction();
      ray.o = c + s.radius * (1 + 1e-9 * rng.uniform(-1, 1)) * n;
      ray.d = normalize(n * rng.uniform(-1, 1) + rng.in_box(1));
    }
    if (i % 4 == 2) {  // tangent to within rounding
      const Vec3 n = rng.direction();
      const Vec3 t = normalize(cross(n, rng.direction()));
      ray.o = c + s.radius * n - 4.0 * t;
      ray.d = t;
    }
    if (i % 8 == 3) ray.tmin = rng.uniform(-2, 1);
    double t0 = 0, t1 = 0;
    bool expect = false;
    double expect_t = 0;
    if (sphere_line_roots(ray.o - c, ray.d, s.radius, t0, t1)) {
      for (double t : {t0, t1})
        if (t >= ray.tmin && t <= ray.tmax) {
          expect = true;
          expect_t = t;
          break;
        }
    }
    LocalHit h;
    const bool hit = intersect(s, ray, h);
    ASSERT_EQ(hit, expect) << "case " << i;
    if (hit) {
      ++hits;
      EXPECT_EQ(h.t, expect_t) << "case " << i;
    }
    const Vec3 o = ray.o - c;
    rejected_moving_away += dot(o, o) > s.radius * s.radius && dot(o, ray.d) > 0;
  }
  EXPECT_GT(rejected_moving_away, 1000);  // the cases reach both early exits and the roots
  EXPECT_GT(hits, 1000);
}

TEST(Sphere, Spans_AgreeWithInsideOracle) {
  const unsigned seed = 77;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  const Sphere s = make_sphere({0.5, -0.25, 0.1}, 1.5);
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, 4, 2);
    testing::check_spans_against_oracle(s, ray, [&](const Vec3& p) { return contains(s, p); });
  }
}

TEST(Sphere, PartialUv_ReconstructsThePoint) {
  // pbrt's convention: phi = u phi_max, theta from theta(z_min) at v = 0 to theta(z_max) at v = 1.
  const double r = 2, z_min = -1, z_max = 1.5, phi_deg = 270;
  const Sphere s = make_sphere({0, 0, 0}, r, z_min, z_max, phi_deg);
  EXPECT_TRUE(s.is_partial());
  EXPECT_FALSE(is_closed(s));
  EXPECT_FALSE(contains(s, {0, 0, 0}));
  const unsigned seed = 3;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  const double th_lo = std::acos(z_min / r), th_hi = std::acos(z_max / r);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = testing::random_ray(rng, 5, 2);
    double g0 = 0, g1 = 0;
    const bool g = geometric_roots({0, 0, 0}, r, ray, g0, g1);
    LocalHit h;
    const bool hit = intersect(s, ray, h);
    // Reference: the first geometric root >= 0 whose point lies on the kept part.
    bool expect = false, ambiguous = false;
    double te = 0;
    if (g) {
      for (double t : {g0, g1}) {
        if (t < 0) continue;
        const Vec3 p = ray.at(t);
        double phi = std::atan2(p.y, p.x);
        if (phi < 0) phi += 2 * kPi;
        // Skip points within rounding of the cut, where either answer is right.
        if (std::abs(p.z - z_min) < 1e-9 || std::abs(p.z - z_max) < 1e-9 ||
            std::abs(phi - phi_deg * kPi / 180) < 1e-9 || phi < 1e-9)
          ambiguous = true;
        if (ambiguous) break;
        if (p.z >= z_min && p.z <= z_max && phi <= phi_deg * kPi / 180) {
          expect = true;
          te = t;
          break;
        }
      }
    }
    if (ambiguous) continue;
    ASSERT_EQ(hit, expect) << "case " << i;
    if (hit) {
      ++hits;
      EXPECT_NEAR(h.t, te, 1e-9 * std::abs(te) + 1e-12);
      const SurfaceInfo si = surface(s, ray, h);
      const double phi = si.u * phi_deg * kPi / 180;
      const double theta = th_lo - si.v * (th_lo - th_hi);
      const Vec3 p{r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                   r * std::cos(theta)};
      EXPECT_NEAR(p.x, si.p.x, 1e-9);
      EXPECT_NEAR(p.y, si.p.y, 1e-9);
      EXPECT_NEAR(p.z, si.p.z, 1e-9);
      // Normals of a partial sphere point away from the centre, as the closed solid's would.
      EXPECT_GT(dot(si.n, si.p), 0);
    }
  }
  EXPECT_GT(hits, 300);
}

}  // namespace
}  // namespace raycast
