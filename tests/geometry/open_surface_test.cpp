// Open surfaces (triangle, parallelogram, disk, partial sphere): spans are zero-length crossings
// on the whole line that agree with intersect, and nothing is ever inside.
#include <gtest/gtest.h>

#include <random>

#include "objects/object.h"
#include "shape_checks.h"

namespace raycast {
namespace {

void check_open(const ShapeVariant& shape, unsigned seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  Object o;
  o.shape = shape;
  EXPECT_FALSE(is_closed(o));
  int crossings = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = testing::random_ray(rng, 4, 2);
    EXPECT_FALSE(contains(o, ray.o));
    SpanList list;
    spans(o, ray, list);
    // The first crossing with t >= 0 is intersect's hit, with the same record.
    const Span* first = nullptr;
    for (const Span& s : list) {
      EXPECT_EQ(s.in.t, s.out.t);
      EXPECT_NE(s.in.part, kNoSurface);
      if (!first && s.in.t >= 0) first = &s;
      ++crossings;
    }
    LocalHit h;
    const bool hit = intersect(o, ray, h);
    ASSERT_EQ(hit, first != nullptr) << "case " << i;
    EXPECT_EQ(occluded(o, ray), hit);
    if (hit) {
      EXPECT_EQ(h.t, first->in.t);
      const SurfaceInfo a = surface(o, ray, h), b = surface(o, ray, first->in);
      EXPECT_EQ(a.p, b.p);
      EXPECT_EQ(a.n, b.n);
      EXPECT_EQ(a.u, b.u);
      EXPECT_EQ(a.v, b.v);
    }
  }
  EXPECT_GT(crossings, 100);
}

TEST(OpenSurface, Triangle_SpansAreItsCrossings) {
  check_open(make_triangle({-2, -1, 0.3}, {2, -1.5, -0.2}, {0.5, 2, 0.7}), 1);
}

TEST(OpenSurface, Parallelogram_SpansAreItsCrossings) {
  check_open(make_parallelogram({-1.5, -1, 0.2}, {3, 0.5, -0.3}, {0.2, 2.5, 0.6}), 2);
}

TEST(OpenSurface, Disk_SpansAreItsCrossings) {
  check_open(make_disk(2, 0.5, 0.3, 300), 3);
  check_open(make_disk({0.2, 0.1, -0.3}, {1, 2, 3}, 2, 0.25), 4);
}

TEST(OpenSurface, PartialSphere_SpansAreItsCrossings) {
  check_open(make_sphere({0, 0, 0}, 1.5, -1, 1.2, 250), 5);
}

}  // namespace
}  // namespace raycast
