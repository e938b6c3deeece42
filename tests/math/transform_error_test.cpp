// Transform's error bounds for transformed surface records: point_error, inverse_point_error and
// abs_vector must give the bits of the products of the absolute values taken per call
// (apply_point_error; |m| v summed in apply_vector's order), for translations (their shorter
// path) and general transforms, on every input.
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

// |M| v as object.cpp computed it before the magnitudes were kept.
Vec3 abs_product(const Mat4& a, const Vec3& v) {
  const auto& m = a.m;
  Vec3 r;
  for (int i = 0; i < 3; ++i)
    r[i] = std::abs(m[i][0]) * v.x + std::abs(m[i][1]) * v.y + std::abs(m[i][2]) * v.z;
  return r;
}

std::vector<Transform> transforms(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-10, 10);
  Mat4 minus_zero = Mat4::identity();
  minus_zero.m[0][1] = -0.0;  // not a translation: the general path
  minus_zero.m[1][3] = 2;
  std::vector<Transform> out = {
      Transform(),
      Transform::translate({-2, 0.45, -3.5}),
      Transform::translate({-0.0, 0.0, -0.0}),
      Transform::translate({1e300, -1e-310, 3}),
      Transform::scale({1.3, 1.3, 1.3}) * Transform::translate({2, 0.585, -3.5}),
      Transform::translate({-2.6, 1, 1}) * Transform::rotate({0, 1, 0}, 30),
      Transform::rotate({1, 2, -3}, 77) * Transform::scale({-1, 2, 0.5}),
      Transform(minus_zero, *inverse(minus_zero)),
  };
  for (int i = 0; i < 10; ++i) {
    out.push_back(Transform::translate({u(rng), u(rng), u(rng)}));
    out.push_back(Transform::translate({u(rng), u(rng), u(rng)}) *
                  Transform::rotate({u(rng), u(rng), u(rng) + 20}, u(rng) * 30) *
                  Transform::scale({u(rng) + 11, 0.5, u(rng) - 11}));
  }
  return out;
}

TEST(TransformError, TranslationPathsGiveThePerCallProductsBits) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-10, 10);
  std::uniform_int_distribution<int> pick(0, 2);
  for (const Transform& xf : transforms(rng)) {
    const Mat4& m = xf.matrix();
    const Mat4& inv = xf.inverse_matrix();
    for (int i = 0; i < 3000; ++i) {
      Vec3 v;
      for (int c = 0; c < 3; ++c) {
        const int k = pick(rng);
        v[c] = k == 0 ? u(rng) : k == 1 ? (rng() & 1 ? 0.0 : -0.0) : special_double(rng);
      }
      expect_same_bits(xf.point_error(v), Transform::apply_point_error(m, v), "point_error");
      expect_same_bits(xf.inverse_point_error(v), Transform::apply_point_error(inv, v),
                       "inverse_point_error");
      // Error bounds are >= 0; the magnitudes' products also for negative and -0 inputs.
      expect_same_bits(xf.abs_vector(abs(v)), abs_product(m, abs(v)), "abs_vector");
      expect_same_bits(xf.abs_vector(v), abs_product(m, v), "abs_vector (signed)");
    }
  }
}

}  // namespace
}  // namespace raycast
