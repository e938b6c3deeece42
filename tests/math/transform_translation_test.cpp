// Translations take a shorter path in Transform (no products by 1, the products by +0 shared):
// its points, vectors and normals must be the general matrix products' bits, for every input.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "math/transform.h"
#include "same_bits.h"

namespace raycast {
namespace {

// The general products, as Transform computed them before the translation path.
Vec3 general_normal(const Mat4& inv, const Vec3& n) {
  return Transform::apply_vector(transpose(inv), n);
}

void expect_general(const Transform& xf, const Vec3& v) {
  const Mat4& m = xf.matrix();
  const Mat4& inv = xf.inverse_matrix();
  expect_same_bits(xf.point(v), Transform::apply_point(m, v), "point");
  expect_same_bits(xf.vector(v), Transform::apply_vector(m, v), "vector");
  expect_same_bits(xf.inverse_point(v), Transform::apply_point(inv, v), "inverse_point");
  expect_same_bits(xf.inverse_vector(v), Transform::apply_vector(inv, v), "inverse_vector");
  expect_same_bits(xf.normal(v), general_normal(inv, v), "normal");
}

std::vector<Transform> translations(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-10, 10);
  std::vector<Transform> out = {
      Transform(),
      Transform::translate({-2, 0.45, -3.5}),
      Transform::translate({0, 1, 2.5}),
      Transform::translate({-0.0, 0.0, -0.0}),
      Transform::translate({1e300, -1e-310, 3}),
      Transform::translate({0.1, 0.2, 0.3}) * Transform::translate({-0.1, 0.7, 1e-17}),
      Transform::scale({1, 1, 1}) * Transform::translate({2, 0.585, -3.5}),
  };
  for (int i = 0; i < 20; ++i) out.push_back(Transform::translate({u(rng), u(rng), u(rng)}));
  for (int i = 0; i < 10; ++i) {
    const Vec3 t{special_double(rng), special_double(rng), special_double(rng)};
    if (std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z))
      out.push_back(Transform::translate(t));
  }
  return out;
}

TEST(TransformTranslation, SameBitsAsTheMatrixProducts) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-10, 10);
  std::uniform_int_distribution<int> pick(0, 3);
  for (const Transform& xf : translations(rng)) {
    for (int i = 0; i < 3000; ++i) {
      Vec3 v;
      for (int c = 0; c < 3; ++c) {
        // Random values, exact zeros of both signs, the translation's own negation (sums of 0),
        // and special values.
        const int k = pick(rng);
        v[c] = k == 0   ? u(rng)
               : k == 1 ? (rng() & 1 ? 0.0 : -0.0)
               : k == 2 ? -xf.matrix().m[c][3]
                        : special_double(rng);
      }
      expect_general(xf, v);
    }
  }
}

TEST(TransformTranslation, NearTranslationsTakeTheGeneralPath) {
  // A -0 off the diagonal, a diagonal a hair from 1, and a rotation: the general products.
  Mat4 m = Mat4::identity();
  m.m[0][1] = -0.0;
  m.m[1][3] = 2;
  const Mat4 inv = *inverse(m);
  Mat4 near = Mat4::identity();
  near.m[2][2] = std::nextafter(1.0, 2.0);
  near.m[0][3] = 1;
  const Transform cases[] = {Transform(m, inv), *Transform::from_matrix(near),
                             Transform::rotate({0, 1, 0}, 30) * Transform::translate({1, 2, 3})};
  std::mt19937_64 rng(7);
  for (const Transform& xf : cases)
    for (int i = 0; i < 2000; ++i)
      expect_general(xf, {special_double(rng), special_double(rng), special_double(rng)});
}

}  // namespace
}  // namespace raycast
