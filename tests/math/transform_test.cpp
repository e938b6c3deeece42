#include "math/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace raycast {
namespace {

void expect_vec_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol) << "x";
  EXPECT_NEAR(a.y, b.y, tol) << "y";
  EXPECT_NEAR(a.z, b.z, tol) << "z";
}

Transform random_affine(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1), s(0.2, 3), deg(-180, 180);
  const Vec3 axis{u(rng), u(rng), u(rng) + 1.5};
  return Transform::translate({5 * u(rng), 5 * u(rng), 5 * u(rng)}) *
         Transform::rotate(axis, deg(rng)) * Transform::scale({s(rng), s(rng), s(rng)});
}

TEST(Transform, Identity_LeavesPointsAndReportsIdentity) {
  const Transform id;
  EXPECT_TRUE(id.is_identity());
  EXPECT_EQ(id.point({1, 2, 3}), Vec3(1, 2, 3));
  EXPECT_FALSE(id.flips_handedness());
}

TEST(Transform, Translate_MovesPointsNotVectors) {
  const Transform t = Transform::translate({1, 2, 3});
  EXPECT_EQ(t.point({1, 1, 1}), Vec3(2, 3, 4));
  EXPECT_EQ(t.vector({1, 1, 1}), Vec3(1, 1, 1));
  EXPECT_EQ(t.inverse_point({2, 3, 4}), Vec3(1, 1, 1));
}

TEST(Transform, RotateAboutZ_FollowsRightHandRule) {
  expect_vec_near(Transform::rotate({0, 0, 1}, 90).point({1, 0, 0}), {0, 1, 0}, 1e-15);
  expect_vec_near(Transform::rotate({1, 0, 0}, 90).point({0, 1, 0}), {0, 0, 1}, 1e-15);
  expect_vec_near(Transform::rotate({0, 1, 0}, 90).point({0, 0, 1}), {1, 0, 0}, 1e-15);
  // A non-unit axis is normalised; a negative angle turns the other way.
  expect_vec_near(Transform::rotate({0, 0, 7}, -90).point({1, 0, 0}), {0, -1, 0}, 1e-15);
  // 120 degrees about (1, 1, 1) cycles the axes x -> y -> z.
  expect_vec_near(Transform::rotate({1, 1, 1}, 120).point({1, 0, 0}), {0, 1, 0}, 1e-15);
}

TEST(Transform, Compose_AppliesRightOperandFirst) {
  const Transform t = Transform::translate({1, 0, 0});
  const Transform s = Transform::scale({2, 2, 2});
  EXPECT_EQ((t * s).point({1, 1, 1}), Vec3(3, 2, 2));  // scale, then translate
  EXPECT_EQ((s * t).point({1, 1, 1}), Vec3(4, 2, 2));  // translate, then scale
  EXPECT_EQ((t * s).inverse_point({3, 2, 2}), Vec3(1, 1, 1));
}

TEST(Transform, RandomAffine_InverseTimesMatrixIsIdentity) {
  const unsigned seed = 7;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 1000; ++i) {
    const Transform xf = random_affine(rng);
    const auto inv = inverse(xf.matrix());
    ASSERT_TRUE(inv.has_value());
    const Mat4 p = xf.matrix() * *inv;
    const Mat4 q = xf.matrix() * xf.inverse_matrix();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        EXPECT_NEAR(p.m[r][c], r == c ? 1 : 0, 1e-13) << "case " << i;
        EXPECT_NEAR(q.m[r][c], r == c ? 1 : 0, 1e-13) << "case " << i;
      }
    const auto from = Transform::from_matrix(xf.matrix());
    ASSERT_TRUE(from.has_value());
    const Vec3 pt{1.5, -2, 0.25};
    expect_vec_near(from->inverse_point(xf.point(pt)), pt, 1e-12);
  }
}

TEST(Transform, SingularOrNonFiniteOrProjective_HasNoInverse) {
  Mat4 singular = Mat4::identity();
  singular.m[2][2] = 0;
  EXPECT_FALSE(inverse(singular).has_value());
  EXPECT_FALSE(Transform::from_matrix(singular).has_value());
  Mat4 rank2 = Mat4::identity();
  rank2.m[1] = rank2.m[0];
  EXPECT_FALSE(inverse(rank2).has_value());
  Mat4 nan = Mat4::identity();
  nan.m[0][1] = std::nan("");
  EXPECT_FALSE(inverse(nan).has_value());
  EXPECT_FALSE(inverse(Mat4{}).has_value());
  Mat4 projective = Mat4::identity();
  projective.m[3][2] = 1;
  EXPECT_TRUE(inverse(projective).has_value());
  EXPECT_FALSE(Transform::from_matrix(projective).has_value());
}

TEST(Transform, Normal_StaysPerpendicularToTransformedTangents) {
  const unsigned seed = 11;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 1000; ++i) {
    const Transform xf = random_affine(rng);
    const Vec3 n = normalize(Vec3{u(rng), u(rng), u(rng)});
    Vec3 s, t;
    make_frame(n, s, t);
    const Vec3 nw = normalize(xf.normal(n));
    EXPECT_NEAR(dot(nw, normalize(xf.vector(s))), 0, 1e-13) << "case " << i;
    EXPECT_NEAR(dot(nw, normalize(xf.vector(t))), 0, 1e-13) << "case " << i;
    // The normal keeps its side: transformed n and n's image as a vector agree in sign.
    EXPECT_GT(dot(nw, xf.vector(n)), 0) << "case " << i;
  }
  // Non-uniform scale: the normal of the plane x + y = 0 under scale (2, 1, 1) is (1, 2, 0)/sqrt5.
  const Vec3 n = normalize(Transform::scale({2, 1, 1}).normal({1, 1, 0}));
  expect_vec_near(n, normalize(Vec3{1, 2, 0}), 1e-15);
}

TEST(Transform, Mirror_FlipsHandedness) {
  EXPECT_TRUE(Transform::scale({-1, 1, 1}).flips_handedness());
  EXPECT_FALSE(Transform::scale({-1, -1, 1}).flips_handedness());
  EXPECT_FALSE(Transform::rotate({1, 2, 3}, 77).flips_handedness());
}

TEST(Transform, PointError_BoundsTheRoundingOfPoint) {
  const unsigned seed = 13;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), e(-8, 8);
  for (int i = 0; i < 10000; ++i) {
    const Transform xf = random_affine(rng) * Transform::translate({1e3 * u(rng), 0, 0});
    const Vec3 p = std::pow(10.0, e(rng)) * Vec3{u(rng), u(rng), u(rng)};
    const Vec3 q = xf.point(p);
    const Vec3 err = xf.point_error(p);
    const auto& m = xf.matrix().m;
    for (int r = 0; r < 3; ++r) {
      // Reference in long double (64-bit significand): its own error is far below the bound.
      const long double exact = static_cast<long double>(m[r][0]) * p.x +
                                static_cast<long double>(m[r][1]) * p.y +
                                static_cast<long double>(m[r][2]) * p.z + m[r][3];
      EXPECT_LE(std::abs(static_cast<long double>(q[r]) - exact), static_cast<long double>(err[r]))
          << "case " << i << " row " << r;
    }
  }
}

}  // namespace
}  // namespace raycast
