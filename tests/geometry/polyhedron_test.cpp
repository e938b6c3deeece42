#include "geometry/polyhedron.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

// The box [lo, hi] as six half-spaces.
Polyhedron box_polyhedron(const Vec3& lo, const Vec3& hi) {
  return make_polyhedron({{-1, 0, 0, lo.x},
                          {1, 0, 0, -hi.x},
                          {0, -2, 0, 2 * lo.y},
                          {0, 2, 0, -2 * hi.y},
                          {0, 0, -1, lo.z},
                          {0, 0, 1, -hi.z}});
}

TEST(Polyhedron, UnitCube_HandRay) {
  const Polyhedron p = box_polyhedron({-1, -1, -1}, {1, 1, 1});
  const Ray ray{{-5, 0.5, 0}, {2, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(p, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 2);
  EXPECT_EQ(surface(p, ray, h).n, (Vec3{-1, 0, 0}));
  SpanList sl;
  spans(p, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 3);
  EXPECT_EQ(surface(p, ray, sl[0].out).n, (Vec3{1, 0, 0}));
  const Aabb b = bounds(p);
  EXPECT_NEAR(b.lo.x, -1, 1e-6);
  EXPECT_NEAR(b.hi.z, 1, 1e-6);
}

TEST(Polyhedron, RandomRays_MatchTheBoxSlabTest) {
  const Vec3 lo{-0.5, -1, -0.2}, hi{1, 0.3, 0.9};
  const Polyhedron p = box_polyhedron(lo, hi);
  const Aabb box{lo, hi};
  Rng rng(83);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = testing::random_ray(rng, 3, 1.5);
    SCOPED_TRACE("seed 83, " + testing::describe(ray));
    double t0 = kInfinity, t1 = kInfinity;
    const bool expect = slab_interval(box, ray.o, reciprocal(ray.d), t0, t1) && t1 >= 0;
    LocalHit h;
    const bool hit = intersect(p, ray, h);
    if (hit != expect) {
      EXPECT_LT(std::abs(t1 - t0), 1e-9);  // only an edge graze may differ
      continue;
    }
    if (!hit) continue;
    ++hits;
    const double want = t0 >= 0 ? t0 : t1;
    EXPECT_NEAR(h.t, want, 1e-12 * std::max(1.0, std::abs(want)));
  }
  EXPECT_GT(hits, 1000);
}

TEST(Polyhedron, RandomRays_SpansMatchInsideOracleAndNormalsPointOut) {
  // An irregular closed polyhedron and an unbounded one (a wedge open along +z).
  const Polyhedron closed = make_polyhedron({{1, 1, 1, -1},
                                             {-1, 0.2, 0.1, -0.8},
                                             {0.1, -1, 0.3, -0.7},
                                             {0.2, 0.1, -1, -0.9},
                                             {0.5, 0.5, -0.3, -1}});
  const Polyhedron wedge =
      make_polyhedron({{1, 0, -0.2, -0.5}, {-1, 0, -0.2, -0.5}, {0, 1, 0, -1}, {0, -1, 0, -1}});
  EXPECT_TRUE(bounds(closed).is_bounded());
  EXPECT_FALSE(bounds(wedge).is_bounded());
  for (const Polyhedron* p : {&closed, &wedge}) {
    auto inside = [&](const Vec3& x) { return contains(*p, x); };
    Rng rng(89);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
      const Ray ray = testing::random_ray(rng, 3, 1.5);
      SCOPED_TRACE("seed 89, " + testing::describe(ray));
      ASSERT_EQ(testing::span_mismatches(*p, ray, inside, -20, 20), 0);
      LocalHit h;
      const bool hit = intersect(*p, ray, h);
      ASSERT_EQ(hit, testing::first_span_end(*p, ray) < kInfinity);
      if (!hit) continue;
      ++hits;
      EXPECT_EQ(h.t, testing::first_span_end(*p, ray));
      testing::expect_outward_normal(*p, ray, h, inside, 1e-7);
    }
    EXPECT_GT(hits, 300);
    // The hull holds every crossing.
    if (bounds(*p).is_bounded()) {
      for (int i = 0; i < 200; ++i) {
        const Ray ray = testing::random_ray(rng, 3, 1.5);
        LocalHit h;
        if (intersect(*p, ray, h)) {
          EXPECT_TRUE(bounds(*p).contains(ray.at(h.t)));
        }
      }
    }
  }
}

TEST(Polyhedron, ParallelRayOutsideOnePlane_MissesEarly) {
  const Polyhedron p = box_polyhedron({-1, -1, -1}, {1, 1, 1});
  LocalHit h;
  EXPECT_FALSE(intersect(p, Ray{{-5, 2, 0}, {1, 0, 0}}, h));
  SpanList sl;
  spans(p, Ray{{-5, 2, 0}, {1, 0, 0}}, sl);
  EXPECT_TRUE(sl.empty());
}

TEST(Polyhedron, HalfSpace_IsUnboundedWithOneCrossing) {
  const Polyhedron p = make_polyhedron({{0, 0, 1, -2}});  // z <= 2
  SpanList sl;
  spans(p, Ray{{0, 0, 0}, {0, 0, 1}}, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_EQ(sl[0].in.t, -kInfinity);
  EXPECT_EQ(sl[0].in.part, kNoSurface);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 2);
  LocalHit h;
  ASSERT_TRUE(intersect(p, Ray{{0, 0, 0}, {0, 0, 1}}, h));
  EXPECT_DOUBLE_EQ(h.t, 2);
  EXPECT_FALSE(intersect(p, Ray{{0, 0, 0}, {0, 0, -1}}, h));
}

TEST(Polyhedron, TMinTMax_AreClosedAtBothEnds) {
  const Polyhedron p = box_polyhedron({-1, -1, -1}, {1, 1, 1});
  LocalHit h;
  EXPECT_TRUE(intersect(p, Ray{{-5, 0, 0}, {1, 0, 0}, 0, 4}, h));
  EXPECT_FALSE(intersect(p, Ray{{-5, 0, 0}, {1, 0, 0}, 0, std::nextafter(4.0, 0.0)}, h));
  EXPECT_TRUE(intersect(p, Ray{{-5, 0, 0}, {1, 0, 0}, 6, 7}, h));
  EXPECT_FALSE(intersect(p, Ray{{-5, 0, 0}, {1, 0, 0}, std::nextafter(6.0, 7.0), 7}, h));
  EXPECT_FALSE(occluded(p, Ray{{-5, 0, 0}, {1, 0, 0}, 4.5, 5.5}));
}

TEST(Polyhedron, EmptyOrDegenerate_IsRejected) {
  EXPECT_THROW(make_polyhedron({}), std::invalid_argument);
  EXPECT_THROW(make_polyhedron({{0, 0, 1, -1}, {0, 0, -1, 2}}),
               std::invalid_argument);  // z <= 1 and z >= 2
  EXPECT_THROW(make_polyhedron({{0, 0, 1, 0}, {0, 0, -1, 0}}),
               std::invalid_argument);  // z = 0: no interior
  EXPECT_THROW(make_polyhedron({{1, 1, 1, 1}, {-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}}),
               std::invalid_argument);  // x + y + z <= -1 in the positive octant
  EXPECT_THROW(make_polyhedron({{0, 0, 0, 1}}), std::invalid_argument);
  EXPECT_THROW(make_polyhedron({{0, 0, 1, std::nan("")}}), std::invalid_argument);
  EXPECT_NO_THROW(
      make_polyhedron({{1, 1, 1, 1}, {-1, 0, 0, 0}, {0, -1, 0, 0}}));  // unbounded, not empty
  EXPECT_THROW(make_polyhedron({{0, 0, 1, 0}, {0, 0, -1, 0}, {-1, 0, 0, 0}, {0, -1, 0, 0}}),
               std::invalid_argument);  // a flat unbounded quadrant: no interior
  std::vector<std::array<double, 4>> many(kMaxPolyhedronPlanes + 1, {0, 0, 1, -1});
  EXPECT_THROW(make_polyhedron(many), std::invalid_argument);
}

TEST(Polyhedron, HundredPlanes_LoadWithTheirHull) {
  // The largest allowed polyhedron: 100 tangent planes of the unit sphere, and the same with
  // every normal in the upper half (unbounded below).
  Rng rng(97);
  std::vector<std::array<double, 4>> closed, open;
  for (std::size_t i = 0; i < kMaxPolyhedronPlanes; ++i) {
    const Vec3 n = rng.direction();
    closed.push_back({n.x, n.y, n.z, -1});
    open.push_back({n.x, n.y, std::abs(n.z), -1});
  }
  const Polyhedron a = make_polyhedron(closed), b = make_polyhedron(open);
  EXPECT_TRUE(bounds(a).is_bounded());
  EXPECT_LT(bounds(a).hi.x, 3);
  EXPECT_FALSE(bounds(b).is_bounded());
  EXPECT_TRUE(contains(a, {0, 0, 0}));
  EXPECT_TRUE(contains(b, {0, 0, -100}));
}

}  // namespace
}  // namespace raycast
