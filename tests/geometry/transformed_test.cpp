// Shapes placed by a transform (through objects/object.h's Object) against the same shape built
// directly in world space.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "objects/object.h"
#include "shape_checks.h"
#include "support/objects.h"

namespace raycast {
namespace {

using testing::object_of;

Transform random_placement(testing::Rng& rng, bool uniform_scale) {
  std::uniform_real_distribution<double> s(0.3, 2.5), deg(-180, 180);
  const double k = s(rng);
  const Vec3 scale = uniform_scale ? Vec3{k, k, k} : Vec3{s(rng), s(rng), s(rng)};
  return Transform::translate(rng.in_box(2)) * Transform::rotate(rng.direction(), deg(rng)) *
         Transform::scale(scale);
}

// Runs random rays at both objects and compares t, hit point and normal; `uv` also compares
// (u, v) (those invariant under the placement).
void compare(const Object& a, const Object& b, testing::Rng& rng, bool uv, int* hits) {
  const Ray ray = testing::random_ray(rng, 6, 2.5);
  LocalHit ha, hb;
  const bool hit_a = intersect(a, ray, ha), hit_b = intersect(b, ray, hb);
  if (hit_a != hit_b) {
    // Allowed only within rounding of an edge: the other must be near-tangent or near a rim.
    ADD_FAILURE() << "hit mismatch: transformed " << hit_a << " world " << hit_b;
    return;
  }
  if (!hit_a) return;
  ++*hits;
  EXPECT_NEAR(ha.t, hb.t, 1e-9 * std::abs(hb.t) + 1e-12);
  const SurfaceInfo sa = surface(a, ray, ha), sb = surface(b, ray, hb);
  EXPECT_NEAR(length(sa.p - sb.p), 0, 1e-9 * (1 + length(sb.p)));
  testing::expect_unit(sa.n);
  EXPECT_NEAR(length(sa.n - sb.n), 0, 1e-9);
  if (uv) {
    EXPECT_NEAR(sa.u, sb.u, 1e-9);
    EXPECT_NEAR(sa.v, sb.v, 1e-9);
  }
  // The reported point is within its error bound of the exact crossing (t carries the solver's
  // relative error, so allow that too).
  for (int i = 0; i < 3; ++i)
    EXPECT_LE(std::abs(sa.p[i] - sb.p[i]),
              sa.p_error[i] + sb.p_error[i] + 1e-9 * (1 + length(sb.p)));
}

TEST(Transformed, Box_MatchesTranslatedBox) {
  const Box b = make_box({-1, -2, -0.5}, {1, 0.5, 2});
  const Vec3 shift{3, -1, 0.25};
  const Object moved = object_of(b, Transform::translate(shift));
  const Object world = object_of(make_box(b.lo + shift, b.hi + shift));
  const unsigned seed = 41;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) compare(moved, world, rng, true, &hits);
  EXPECT_GT(hits, 500);
}

TEST(Transformed, Sphere_MatchesScaledAndMovedSphere) {
  const unsigned seed = 42;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Transform xf = random_placement(rng, true);
    const double k = length(xf.vector({1, 0, 0}));
    const Object a = object_of(make_sphere({0, 0, 0}, 1), xf);
    const Object b = object_of(make_sphere(xf.point({0, 0, 0}), k));
    compare(a, b, rng, false, &hits);
  }
  EXPECT_GT(hits, 500);
}

TEST(Transformed, Triangle_MatchesTriangleOfTransformedVertices) {
  const unsigned seed = 43;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  const Vec3 p0{-1, -1, 0}, p1{2, -1, 0.5}, p2{0, 2, -0.5};
  for (int i = 0; i < 5000; ++i) {
    const Transform xf = random_placement(rng, false);
    const Object a = object_of(make_triangle(p0, p1, p2), xf);
    const Object b = object_of(make_triangle(xf.point(p0), xf.point(p1), xf.point(p2)));
    compare(a, b, rng, true, &hits);  // barycentrics are affine invariants
  }
  EXPECT_GT(hits, 500);
}

TEST(Transformed, Parallelogram_MatchesTransformedEdges) {
  const unsigned seed = 44;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  const Vec3 o{-1, -1, 0.5}, u{2, 0.5, 0}, v{0.25, 2, 0.5};
  for (int i = 0; i < 5000; ++i) {
    const Transform xf = random_placement(rng, false);
    const Object a = object_of(make_parallelogram(o, u, v), xf);
    const Object b = object_of(make_parallelogram(xf.point(o), xf.vector(u), xf.vector(v)));
    compare(a, b, rng, true, &hits);
  }
  EXPECT_GT(hits, 500);
}

TEST(Transformed, Disk_MatchesCenterNormalForm) {
  const unsigned seed = 45;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Transform xf = random_placement(rng, true);
    const double k = length(xf.vector({1, 0, 0}));
    const Object a = object_of(make_disk(1.5, 0.5, 0.25), xf);
    const Object b =
        object_of(make_disk(xf.point({0, 0, 0.25}), xf.normal({0, 0, 1}), 1.5 * k, 0.5 * k));
    const Ray ray = testing::random_ray(rng, 6, 2.5);
    LocalHit ha, hb;
    const bool hit_a = intersect(a, ray, ha), hit_b = intersect(b, ray, hb);
    if (hit_a != hit_b) {
      // Only a ray within rounding of a rim may disagree.
      const SurfaceInfo s = surface(hit_a ? a : b, ray, hit_a ? ha : hb);
      EXPECT_TRUE(s.v < 1e-9 || s.v > 1 - 1e-9) << "case " << i;
      continue;
    }
    if (!hit_a) continue;
    ++hits;
    EXPECT_NEAR(ha.t, hb.t, 1e-9 * std::abs(hb.t) + 1e-12);
    const SurfaceInfo sa = surface(a, ray, ha), sb = surface(b, ray, hb);
    EXPECT_NEAR(length(sa.n - sb.n), 0, 1e-9);
    EXPECT_NEAR(sa.v, sb.v, 1e-9);  // radial: invariant; u depends on each form's phi origin
  }
  EXPECT_GT(hits, 500);
}

TEST(Transformed, RotatedScaledBox_SpansMatchContainsAndNormalsPointOut) {
  const unsigned seed = 46;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  for (int i = 0; i < 300; ++i) {
    const Object o = object_of(make_box({-1, -0.5, -2}, {1, 0.5, 1}), random_placement(rng, false));
    const Ray ray = testing::random_ray(rng, 6, 2);
    testing::check_spans_against_oracle(o, ray, [&](const Vec3& p) { return contains(o, p); });
    LocalHit h;
    if (!intersect(o, ray, h)) continue;
    const SurfaceInfo si = surface(o, ray, h);
    testing::expect_unit(si.n);
    EXPECT_FALSE(contains(o, si.p + 1e-6 * si.n)) << "case " << i;
    EXPECT_TRUE(contains(o, si.p - 1e-6 * si.n)) << "case " << i;
  }
}

TEST(Transformed, MirroredBox_NormalsStillPointOut) {
  const Object o = object_of(make_box({0, -1, -1}, {2, 1, 1}), Transform::scale({-1, 1, 1}));
  LocalHit h;
  const Ray ray{{-5, 0, 0}, {1, 0, 0}};
  ASSERT_TRUE(intersect(o, ray, h));
  EXPECT_EQ(h.t, 3);
  EXPECT_EQ(surface(o, ray, h).n, Vec3(-1, 0, 0));
}

}  // namespace
}  // namespace raycast
