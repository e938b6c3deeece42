// The box's surface record (geometry/box.cpp) against its definition with the library's
// std::fmax / std::fmin clamp onto the face (bit for bit but for the sign of a zero): hits inside
// faces, on edges and corners, points beyond the face (rounding), zeros of both signs, a NaN
// coordinate; and surface_geometry equal to surface() but for (u, v).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "geometry/box.h"

namespace raycast {
namespace {

SurfaceInfo by_definition(const Box& b, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  const int face = hit.part >= 0 && hit.part < 6 ? hit.part : 0;
  const int a = face / 2;
  const bool at_hi = face % 2 == 1;
  Vec3 p = ray.at(hit.t);
  si.p_error = gamma(5) * (abs(ray.o) + abs(hit.t * ray.d));
  p[a] = at_hi ? b.hi[a] : b.lo[a];
  si.p_error[a] = 0;
  for (int c : {(a + 1) % 3, (a + 2) % 3}) p[c] = std::fmin(std::fmax(p[c], b.lo[c]), b.hi[c]);
  si.p = p;
  si.n = Vec3{};
  si.n[a] = at_hi ? 1 : -1;
  si.shading_n = si.n;
  const int ub = (a + 1) % 3, vc = (a + 2) % 3;
  si.u = (p[ub] - b.lo[ub]) / (b.hi[ub] - b.lo[ub]);
  si.v = (p[vc] - b.lo[vc]) / (b.hi[vc] - b.lo[vc]);
  return si;
}

bool same_bits(const Vec3& x, const Vec3& y) { return std::memcmp(&x, &y, sizeof x) == 0; }
bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

void expect_definition(const Box& b, const Ray& ray, const LocalHit& hit) {
  const SurfaceInfo want = by_definition(b, ray, hit);
  const SurfaceInfo got = surface(b, ray, hit);
  const SurfaceInfo geometry = surface_geometry(b, ray, hit);
  for (const SurfaceInfo* s : {&got, &geometry}) {
    // The same values; the bits too unless a coordinate is a zero (fmax / fmin leave the sign of
    // a tie of zeros unspecified: GCC may swap their operands).
    for (int c = 0; c < 3; ++c) {
      if (std::isnan(want.p[c])) {
        ASSERT_TRUE(std::isnan(s->p[c]));
        continue;
      }
      ASSERT_EQ(s->p[c], want.p[c]) << c << " face " << hit.part;
      if (want.p[c] != 0) {
        ASSERT_TRUE(same_bits(s->p[c], want.p[c]));
      }
    }
    ASSERT_TRUE(same_bits(s->p_error, want.p_error));
    ASSERT_TRUE(same_bits(s->n, want.n));
    ASSERT_TRUE(same_bits(s->shading_n, want.shading_n));
  }
  ASSERT_EQ(got.u, want.u);
  ASSERT_EQ(got.v, want.v);
}

TEST(BoxSurface, EqualsTheFmaxFminDefinitionBitForBit) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Boxes with faces through zero (signed zeros at the clamp) and off it.
  const Box boxes[] = {make_box({-1, -2, -3}, {1, 2, 3}), make_box({0, 0, 0}, {1, 1, 1}),
                       make_box({-1, -1, -1}, {0, 0, 0}),
                       make_box({-0.0, 0.25, -5}, {3, 0.5, -0.0})};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.5, 1.5);
  for (const Box& b : boxes) {
    for (int face = 0; face < 6; ++face) {
      // Points on the face's plane, inside and (as rounding leaves them) just outside the face,
      // on its edges, and zeros of both signs; the ray ends there at t = 1.
      for (int i = 0; i < 4000; ++i) {
        Vec3 q;
        for (int c = 0; c < 3; ++c) {
          const double span = b.hi[c] - b.lo[c];
          const double pick = unit(rng);
          q[c] = i % 7 == 0   ? (pick < 0 ? b.lo[c] : b.hi[c])
                 : i % 7 == 1 ? (pick < 0 ? 0.0 : -0.0)
                 : i % 7 == 2 ? std::nextafter(pick < 0 ? b.lo[c] : b.hi[c], pick < 0 ? -9 : 9)
                              : b.lo[c] + (pick + 1.5) / 3 * span;
        }
        const Vec3 o{unit(rng) * 4, unit(rng) * 4, unit(rng) * 4};
        const Ray ray{o, q - o, 0, kInfinity};
        LocalHit hit;
        hit.t = 1;
        hit.part = face;
        expect_definition(b, ray, hit);
      }
      // A NaN coordinate clamps to the lower bound, as std::fmax gives it.
      LocalHit hit;
      hit.t = 1;
      hit.part = face;
      expect_definition(b, Ray{{0, 0, 0}, {nan, nan, nan}, 0, kInfinity}, hit);
    }
  }
}

}  // namespace
}  // namespace raycast
