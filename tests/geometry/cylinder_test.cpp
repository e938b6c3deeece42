#include "geometry/cylinder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "objects/object.h"
#include "shape_checks.h"

namespace raycast {
namespace {

using testing::Rng;

TEST(Cylinder, HandRayThroughTheSide_HitsAtFourAndLeavesAtSix) {
  const Cylinder c = make_cylinder(1, 0, 2);
  const Ray ray{{-5, 0, 1}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 4);
  const SurfaceInfo si = surface(c, ray, h);
  EXPECT_DOUBLE_EQ(si.n.x, -1);
  EXPECT_DOUBLE_EQ(si.u, 0.5);  // phi = pi
  EXPECT_DOUBLE_EQ(si.v, 0.5);
  SpanList sl;
  spans(c, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 6);
}

TEST(Cylinder, RayAlongTheAxis_EntersThroughTheBottomCap) {
  const Cylinder c = make_cylinder(1, 0, 2);
  const Ray ray{{0.5, 0, -5}, {0, 0, 2}};
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 2.5);
  EXPECT_EQ(h.part, kFrustumCap0);
  const SurfaceInfo si = surface(c, ray, h);
  EXPECT_EQ(si.n, (Vec3{0, 0, -1}));
  EXPECT_EQ(si.v, 0);
  SpanList sl;
  spans(c, ray, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_DOUBLE_EQ(sl[0].out.t, 3.5);
  EXPECT_EQ(sl[0].out.part, kFrustumCap1);
}

TEST(Cylinder, RayParallelToTheAxisOutside_Misses) {
  const Cylinder c = make_cylinder(1, 0, 2);
  LocalHit h;
  EXPECT_FALSE(intersect(c, Ray{{1.5, 0, -5}, {0, 0, 1}}, h));
  SpanList sl;
  spans(c, Ray{{1.5, 0, -5}, {0, 0, 1}}, sl);
  EXPECT_TRUE(sl.empty());
}

TEST(Cylinder, CutAwayWedge_RayEntersThroughItAndSeesTheInside) {
  // phi_max = 90: the crossing at phi = 150 degrees is cut away; the ray passes in and meets
  // the kept side at phi = 30 degrees from inside; the normal still points away from the axis.
  const Cylinder c = make_cylinder(1, 0, 2, 90);
  EXPECT_FALSE(is_closed(c));
  const Ray ray{{-5, 0.5, 1}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_NEAR(h.t, 5 + std::sqrt(0.75), 1e-15);
  const SurfaceInfo si = surface(c, ray, h);
  EXPECT_NEAR(si.n.x, std::sqrt(0.75), 1e-15);
  EXPECT_NEAR(si.n.y, 0.5, 1e-15);
  EXPECT_NEAR(si.u, 30.0 / 90, 1e-14);
  EXPECT_FALSE(contains(c, {0.1, 0.1, 1}));
}

TEST(Cylinder, PartialCaps_AreSectorsOfTheDisk) {
  const Cylinder c = make_cylinder(1, 0, 2, 90);
  LocalHit h;
  ASSERT_TRUE(intersect(c, Ray{{0.5, 0.5, -5}, {0, 0, 1}}, h));
  EXPECT_DOUBLE_EQ(h.t, 5);
  EXPECT_EQ(h.part, kFrustumCap0);
  EXPECT_FALSE(intersect(c, Ray{{-0.5, 0.5, -5}, {0, 0, 1}}, h));
  SpanList sl;
  spans(c, Ray{{0.5, 0.5, -5}, {0, 0, 1}}, sl);
  ASSERT_EQ(sl.size(), 2u);  // both caps, as zero-length spans
  EXPECT_EQ(sl[0].in.t, sl[0].out.t);
  EXPECT_DOUBLE_EQ(sl[1].in.t, 7);
}

TEST(Cylinder, Uncapped_IsAnOpenTube) {
  const Cylinder c = make_cylinder(1, 0, 2, 360, false);
  EXPECT_FALSE(is_closed(c));
  LocalHit h;
  EXPECT_FALSE(intersect(c, Ray{{0, 0, -5}, {0, 0, 1}}, h));
  // From inside the tube the side is hit from within, normal away from the axis.
  const Ray ray{{0, 0, 1}, {0, 2, 0}};
  ASSERT_TRUE(intersect(c, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  EXPECT_DOUBLE_EQ(surface(c, ray, h).n.y, 1);
}

TEST(Cylinder, TMinTMax_AreClosedAtBothEnds) {
  const Cylinder c = make_cylinder(1, 0, 2);
  LocalHit h;
  EXPECT_TRUE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, 0, 4}, h));
  EXPECT_FALSE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, 0, std::nextafter(4.0, 0.0)}, h));
  EXPECT_TRUE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, 6, 6}, h));
  EXPECT_FALSE(intersect(c, Ray{{-5, 0, 1}, {1, 0, 0}, std::nextafter(6.0, 7.0), 7}, h));
}

TEST(Cylinder, RandomRays_SpansMatchInsideOracleAndNormalsPointOut) {
  const Cylinder c = make_cylinder(0.8, -0.5, 1.2);
  auto inside = [&](const Vec3& p) { return contains(c, p); };
  Rng rng(31);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = testing::random_ray(rng, 3, 1.5);
    SCOPED_TRACE("seed 31, " + testing::describe(ray));
    ASSERT_EQ(testing::span_mismatches(c, ray, inside, -10, 10), 0);
    LocalHit h;
    const bool hit = intersect(c, ray, h);
    ASSERT_EQ(hit, testing::first_span_end(c, ray) < kInfinity);
    if (!hit) continue;
    ++hits;
    EXPECT_EQ(h.t, testing::first_span_end(c, ray));
    testing::expect_outward_normal(c, ray, h, inside, 1e-7);
  }
  EXPECT_GT(hits, 500);
}

// Every crossing of the partial shape is a crossing of the closed one that lies on the kept
// part, and the other way round (two different code paths: open crossings, clipped intervals).
void expect_partial_matches_closed(double phi_max) {
  const Cylinder part = make_cylinder(0.8, -0.5, 1.2, phi_max);
  const Cylinder full = make_cylinder(0.8, -0.5, 1.2);
  Rng rng(37);
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = testing::random_ray(rng, 3, 1.5);
    SCOPED_TRACE("seed 37, " + testing::describe(ray));
    SpanList sp, sf;
    spans(part, ray, sp);
    spans(full, ray, sf);
    std::vector<double> expect;
    for (const Span& s : sf)
      for (const LocalHit& h : {s.in, s.out}) {
        const Vec3 p = ray.at(h.t);
        double phi = std::atan2(p.y, p.x) * 180 / std::numbers::pi;
        if (phi < 0) phi += 360;
        if (std::abs(phi - phi_max) < 1e-6 || std::abs(phi) < 1e-6) goto skip;  // on the cut
        if (phi <= phi_max && (expect.empty() || expect.back() != h.t)) expect.push_back(h.t);
      }
    ASSERT_EQ(sp.size(), expect.size());
    for (std::size_t k = 0; k < expect.size(); ++k)
      EXPECT_NEAR(sp[k].in.t, expect[k], 1e-12 * (1 + std::abs(expect[k])));
  skip:;
  }
}

TEST(Cylinder, RandomRays_PartialCrossingsAreTheClosedOnesOnTheKeptPart) {
  for (const double phi_max : {250.0, 90.0, 180.0, 1.0}) {
    SCOPED_TRACE("phi_max " + std::to_string(phi_max));
    expect_partial_matches_closed(phi_max);
  }
}

TEST(Cylinder, FromTo_MatchesTheCanonicalCylinderMoved) {
  const Vec3 from{1, -2, 0.5}, to{-0.5, 1, 2};
  const Cylinder moved = make_cylinder(from, to, 0.7);
  // The canonical cylinder along z of the same length, rotated onto from->to and translated.
  const Vec3 axis = normalize(to - from);
  const Vec3 rot_axis = cross(Vec3{0, 0, 1}, axis);
  const double degrees = std::acos(axis.z) * 180 / std::numbers::pi;
  const Transform xf = Transform::translate(from) * Transform::rotate(rot_axis, degrees);
  const Object obj{make_cylinder(0.7, 0, length(to - from)), xf, 0, 0};
  Rng rng(41);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = testing::random_ray(rng, 4, 2, 0.5 * (from + to));
    SCOPED_TRACE("seed 41, " + testing::describe(ray));
    LocalHit a, b;
    const bool ha = intersect(moved, ray, a), hb = intersect(obj, ray, b);
    if (ha != hb) {
      // Only a graze of an edge may differ.
      EXPECT_TRUE(std::abs(a.t - b.t) < 1e-6 || !std::isfinite(a.t) || !std::isfinite(b.t));
      continue;
    }
    if (!ha) continue;
    ++hits;
    EXPECT_NEAR(a.t, b.t, 1e-9 * std::max(1.0, std::abs(a.t)));
    const SurfaceInfo sa = surface(moved, ray, a), sb = surface(obj, ray, b);
    EXPECT_NEAR(dot(sa.n, sb.n), 1, 1e-9);
  }
  EXPECT_GT(hits, 500);
}

TEST(Cylinder, MakeCylinder_RejectsBadInput) {
  EXPECT_THROW(make_cylinder(0, 0, 1), std::invalid_argument);
  EXPECT_THROW(make_cylinder(1, 1, 1), std::invalid_argument);
  EXPECT_THROW(make_cylinder(1, 0, 1, 0), std::invalid_argument);
  EXPECT_THROW(make_cylinder(1, 0, 1, 361), std::invalid_argument);
  EXPECT_THROW(make_cylinder({1, 1, 1}, {1, 1, 1}, 1), std::invalid_argument);
  EXPECT_THROW(make_cylinder(std::nan(""), 0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
