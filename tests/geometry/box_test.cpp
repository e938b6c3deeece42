#include "geometry/box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shape_checks.h"

namespace raycast {
namespace {

const Box kBox = make_box({-1, -2, -3}, {1, 2, 3});

// Reference: each face plane in turn, keeping crossings inside the face rectangle (closed).
bool brute_force_nearest(const Box& b, const Ray& ray, double& t_best, int& face_best) {
  t_best = kInfinity;
  face_best = -1;
  for (int face = 0; face < 6; ++face) {
    const int a = face / 2;
    const double plane = face % 2 ? b.hi[a] : b.lo[a];
    if (ray.d[a] == 0) continue;
    const double t = (plane - ray.o[a]) / ray.d[a];
    if (t < ray.tmin || t > ray.tmax || t >= t_best) continue;
    const Vec3 p = ray.at(t);
    bool inside = true;
    for (int k = 1; k <= 2; ++k) {
      const int c = (a + k) % 3;
      inside = inside && p[c] >= b.lo[c] && p[c] <= b.hi[c];
    }
    if (inside) {
      t_best = t;
      face_best = face;
    }
  }
  return face_best >= 0;
}

TEST(Box, MakeBox_RejectsInvertedFlatOrNonFiniteCorners) {
  EXPECT_THROW(make_box({0, 0, 0}, {0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(make_box({0, 0, 2}, {1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(make_box({0, 0, std::nan("")}, {1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(make_box({0, 0, 0}, {1, kInfinity, 1}), std::invalid_argument);
  EXPECT_NO_THROW(make_box({0, 0, 0}, {1e-300, 1, 1}));
}

TEST(Box, RaysAlongEachAxis_HitTheFacingFace) {
  for (int face = 0; face < 6; ++face) {
    const int a = face / 2;
    const double s = face % 2 ? 1 : -1;  // the face's outward direction along a
    Ray ray;
    ray.o[a] = 10 * s;
    ray.d[a] = -4 * s;
    LocalHit h;
    ASSERT_TRUE(intersect(kBox, ray, h)) << "face " << face;
    EXPECT_EQ(h.t, (10 - kBox.hi[a]) / 4) << "face " << face;
    EXPECT_EQ(h.part, face);
    const SurfaceInfo si = surface(kBox, ray, h);
    Vec3 n;
    n[a] = s;
    EXPECT_EQ(si.n, n);
    EXPECT_EQ(si.u, 0.5);  // the face's centre
    EXPECT_EQ(si.v, 0.5);
  }
}

TEST(Box, FaceUv_FollowsTheCyclicAxesFromMin) {
  // Hit the +x face at (1, y, z): u along y, v along z, from min to max.
  const Ray ray{{5, 1, -1.5}, {-1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(kBox, ray, h));
  const SurfaceInfo si = surface(kBox, ray, h);
  EXPECT_EQ(si.p, Vec3(1, 1, -1.5));
  EXPECT_EQ(si.u, 0.75);  // (1 - -2) / 4
  EXPECT_EQ(si.v, 0.25);  // (-1.5 - -3) / 6
  // The -z face: u along x, v along y.
  const Ray down{{0.5, -1, -7}, {0, 0, 1}};
  ASSERT_TRUE(intersect(kBox, down, h));
  EXPECT_EQ(h.part, 4);
  const SurfaceInfo sz = surface(kBox, down, h);
  EXPECT_EQ(sz.u, 0.75);
  EXPECT_EQ(sz.v, 0.25);
}

TEST(Box, RayStartingInside_ExitsWithOutwardNormal) {
  const Ray ray{{0, 0, 0}, {0, 0, 0.5}};
  LocalHit h;
  ASSERT_TRUE(intersect(kBox, ray, h));
  EXPECT_EQ(h.t, 6);
  EXPECT_EQ(h.part, 5);
  EXPECT_EQ(surface(kBox, ray, h).n, Vec3(0, 0, 1));
  EXPECT_TRUE(contains(kBox, ray.o));
}

TEST(Box, GrazingAlongFaceAndThroughEdgeOrCorner_Hit) {
  LocalHit h;
  // In the plane y = 2 of the +y face, travelling along x: enters through the -x face's edge.
  ASSERT_TRUE(intersect(kBox, Ray{{-5, 2, 0}, {1, 0, 0}}, h));
  EXPECT_EQ(h.t, 4);
  EXPECT_EQ(h.part, 0);
  // Through the corner (1, 2, 3) only.
  ASSERT_TRUE(intersect(kBox, Ray{{2, 1, 3}, {-1, 1, 0}}, h));
  EXPECT_EQ(h.t, 1);
  EXPECT_FALSE(intersect(kBox, Ray{{2, 1, std::nextafter(3.0, 4.0)}, {-1, 1, 0}}, h));
  // Parallel to a face just outside it.
  EXPECT_FALSE(intersect(kBox, Ray{{-5, std::nextafter(2.0, 3.0), 0}, {1, 0, 0}}, h));
}

TEST(Box, BehindOrigin_MissesButSpansCoverTheLine) {
  const Ray ray{{5, 0, 0}, {1, 0, 0}};
  LocalHit h;
  EXPECT_FALSE(intersect(kBox, ray, h));
  SpanList s;
  spans(kBox, ray, s);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].in.t, -6);
  EXPECT_EQ(s[0].in.part, 0);
  EXPECT_EQ(s[0].out.t, -4);
  EXPECT_EQ(s[0].out.part, 1);
}

TEST(Box, TminTmax_InclusiveAtBothEnds) {
  const Ray base{{-5, 0, 0}, {1, 0, 0}};
  LocalHit h;
  Ray r = base;
  r.tmax = 4;
  EXPECT_TRUE(intersect(kBox, r, h));
  r.tmax = std::nextafter(4.0, 0.0);
  EXPECT_FALSE(intersect(kBox, r, h));
  r = base;
  r.tmin = 6;
  ASSERT_TRUE(intersect(kBox, r, h));
  EXPECT_EQ(h.t, 6);
  EXPECT_EQ(h.part, 1);
  r.tmin = std::nextafter(6.0, 7.0);
  EXPECT_FALSE(intersect(kBox, r, h));
  EXPECT_FALSE(occluded(kBox, r));
}

TEST(Box, RandomRays_MatchBruteForceFaces) {
  const unsigned seed = 4242;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  for (int i = 0; i < 20000; ++i) {
    const Ray ray = testing::random_ray(rng, 6, 4);
    double tr = 0;
    int fr;
    const bool ref = brute_force_nearest(kBox, ray, tr, fr);
    LocalHit h;
    const bool hit = intersect(kBox, ray, h);
    ASSERT_EQ(hit, ref) << "case " << i;
    ASSERT_EQ(occluded(kBox, ray), ref) << "case " << i;
    if (!hit) continue;
    EXPECT_NEAR(h.t, tr, 1e-12 * std::abs(tr)) << "case " << i;
    const SurfaceInfo si = surface(kBox, ray, h);
    testing::expect_unit(si.n);
    // The normal is the face's: outward, axis-aligned; (u, v) in [0, 1].
    EXPECT_GT(dot(si.n, si.p), 0);
    EXPECT_GE(si.u, 0);
    EXPECT_LE(si.u, 1);
    EXPECT_GE(si.v, 0);
    EXPECT_LE(si.v, 1);
    EXPECT_TRUE(contains(kBox, si.p));
  }
}

TEST(Box, Spans_AgreeWithInsideOracle) {
  const unsigned seed = 8;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  for (int i = 0; i < 500; ++i) {
    const Ray ray = testing::random_ray(rng, 6, 3);
    testing::check_spans_against_oracle(kBox, ray, [](const Vec3& p) { return contains(kBox, p); });
  }
  // Axis-parallel lines, whose other slabs are unconstrained.
  testing::check_spans_against_oracle(kBox, Ray{{0, 0, 0}, {0, 1, 0}},
                                      [](const Vec3& p) { return contains(kBox, p); });
}

}  // namespace
}  // namespace raycast
