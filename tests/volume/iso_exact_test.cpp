// The iso-surface's hits against exact roots of the trilinear interpolant computed independently
// in rational arithmetic (data/make_reference.py), and hand-computed cases.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "volume/grid_file.h"
#include "volume/isosurface.h"

namespace raycast {
namespace {

std::string data(const std::string& name) {
  return std::string(RAYCAST_SOURCE_DIR) + "/tests/volume/data/" + name;
}

void check_reference(const std::string& name) {
  const Isosurface s = [&] {
    std::ifstream in(data(name + "_rays.txt"));
    std::string line, word;
    std::getline(in, line);
    std::getline(in, line);
    std::istringstream ls(line);
    double iso;
    ls >> word >> iso;
    return make_isosurface(read_raw_grid(data(name + ".raw")), iso);
  }();
  std::ifstream in(data(name + "_rays.txt"));
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  int rays = 0, hits = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    Vec3 o, d;
    std::string ts;
    ls >> o.x >> o.y >> o.z >> d.x >> d.y >> d.z >> ts;
    const double expected = ts == "inf" ? kInfinity : std::stod(ts);
    LocalHit h;
    const bool hit = intersect(s, Ray{o, d}, h);
    ++rays;
    if (std::isinf(expected)) {
      EXPECT_FALSE(hit) << line << " got t = " << h.t;
      continue;
    }
    ++hits;
    ASSERT_TRUE(hit) << line;
    // The cell cubics are computed in double from float32 nodes: far inside 1e-6 relative.
    EXPECT_NEAR(h.t, expected, 1e-12 * std::max(1.0, expected)) << line;
    EXPECT_TRUE(occluded(s, Ray{o, d}));
  }
  EXPECT_GT(rays, 40);
  EXPECT_GT(hits, 15);
}

TEST(IsoExact, SphereDistance_MatchesRationalRoots) { check_reference("sphere_sdf"); }
TEST(IsoExact, Gaussians_MatchesRationalRoots) { check_reference("gaussians"); }

// One cell whose field along its diagonal is 3 s (1 - s): two crossings inside the cell.
ScalarGrid one_cell() {
  ScalarGrid g;
  g.n = {2, 2, 2};
  g.lo = {0, 0, 0};
  g.cell = {1, 1, 1};
  g.v.resize(8);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        g.v[g.index(i, j, k)] = (i + j + k == 1 || i + j + k == 2) ? 1 : 0;
  return g;
}

TEST(IsoExact, TwoCrossingsInOneCell_BothFound) {
  for (const double iso : {0.5, 0.74}) {
    const Isosurface s = make_isosurface(one_cell(), iso);
    const double root = std::sqrt(1 - 4 * iso / 3);
    const double s0 = (1 - root) / 2, s1 = (1 + root) / 2;
    const Ray r{{0, 0, 0}, {1, 1, 1}};
    LocalHit h;
    ASSERT_TRUE(intersect(s, r, h)) << iso;
    EXPECT_NEAR(h.t, s0, 1e-15);
    SpanList l;
    spans(s, r, l);
    ASSERT_EQ(l.size(), 1u) << iso;
    EXPECT_NEAR(l[0].in.t, s0, 1e-15);
    EXPECT_NEAR(l[0].out.t, s1, 1e-15);
    // From inside the thin feature the first crossing is the exit.
    const Ray inside{{0.5, 0.5, 0.5}, {1, 1, 1}};
    ASSERT_TRUE(intersect(s, inside, h));
    EXPECT_NEAR(h.t, s1 - 0.5, 1e-15);
    // The exit's normal points along the ray (out of the solid), the entry's against it.
    const SurfaceInfo out = surface(s, inside, h);
    EXPECT_GT(dot(out.n, Vec3{1, 1, 1}), 0);
    ASSERT_TRUE(intersect(s, r, h));
    EXPECT_LT(dot(surface(s, r, h).n, Vec3{1, 1, 1}), 0);
  }
}

TEST(IsoExact, BeyondTheMaximum_NoHit) {
  // The diagonal's maximum is 0.75: iso 0.76 is never reached there (nor anywhere: corners <= 1
  // but the field exceeds 0.76 only near the corners with value 1, off this ray).
  const Isosurface s = make_isosurface(one_cell(), 0.76);
  LocalHit h;
  EXPECT_FALSE(intersect(s, Ray{{0, 0, 0}, {1, 1, 1}}, h));
  SpanList l;
  spans(s, Ray{{0, 0, 0}, {1, 1, 1}}, l);
  EXPECT_TRUE(l.empty());
}

TEST(IsoExact, BoundaryAboveIso_ClosedByTheGridFaces) {
  ScalarGrid g;
  g.n = {3, 3, 3};
  g.lo = {0, 0, 0};
  g.cell = {0.5, 0.5, 0.5};
  g.v.assign(27, 2.0f);
  const Isosurface s = make_isosurface(g, 1);
  const Ray r{{-1, 0.3, 0.7}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_EQ(h.t, 1);
  const SurfaceInfo si = surface(s, r, h);
  EXPECT_EQ(si.n, (Vec3{-1, 0, 0}));
  SpanList l;
  spans(s, r, l);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].in.t, 1);
  EXPECT_EQ(l[0].out.t, 2);
  EXPECT_TRUE(contains(s, {0.5, 0.5, 0.5}));
  EXPECT_FALSE(contains(s, {1.5, 0.5, 0.5}));
}

TEST(IsoExact, TMinTMax_Respected) {
  const Isosurface s = make_isosurface(one_cell(), 0.5);
  const double s0 = (1 - std::sqrt(1 - 2.0 / 3)) / 2, s1 = 1 - s0;
  LocalHit h;
  EXPECT_FALSE(intersect(s, Ray{{0, 0, 0}, {1, 1, 1}, 0, s0 * 0.99}, h));
  ASSERT_TRUE(intersect(s, Ray{{0, 0, 0}, {1, 1, 1}, s0 * 1.01, 1}, h));
  EXPECT_NEAR(h.t, s1, 1e-15);
  EXPECT_FALSE(intersect(s, Ray{{0, 0, 0}, {1, 1, 1}, s1 * 1.01, 10}, h));
  EXPECT_FALSE(occluded(s, Ray{{0, 0, 0}, {-1, -1, -1}}));
}

TEST(IsoExact, BadInput_Rejected) {
  EXPECT_THROW(make_isosurface(one_cell(), -1), std::invalid_argument);
  EXPECT_THROW(make_isosurface(one_cell(), std::nan("")), std::invalid_argument);
  ScalarGrid g = one_cell();
  g.v[3] = std::nanf("");
  EXPECT_THROW(make_isosurface(g, 0.5), std::invalid_argument);
  g = one_cell();
  g.n = {1, 2, 4};
  EXPECT_THROW(make_isosurface(g, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
