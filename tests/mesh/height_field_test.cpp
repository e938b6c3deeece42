// The height field's mesh against a brute-force loop over the triangles the grid defines, its
// orientation (POV-Ray's: the image's top row at z = 1), the water level and smooth normals.
#include "mesh/height_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "support/random.h"

namespace raycast {
namespace {

using testing::Rng;

HeightGrid random_grid(Rng& rng, int w, int d) {
  HeightGrid g{w, d, {}};
  for (int i = 0; i < w * d; ++i) g.y.push_back(rng.uniform(0, 0.8));
  return g;
}

double height(const HeightGrid& g, int i, int j) {
  return g.y[std::size_t(j) * std::size_t(g.width) + std::size_t(i)];
}

// Moller-Trumbore in double; the barycentrics' distance from the triangle's edges in `margin`.
std::optional<double> hit_triangle(const Ray& r, const Vec3& a, const Vec3& b, const Vec3& c,
                                   double& margin) {
  const Vec3 e1 = b - a, e2 = c - a, pv = cross(r.d, e2);
  const double det = dot(e1, pv);
  if (std::abs(det) < 1e-300) return std::nullopt;
  const Vec3 tv = r.o - a;
  const double u = dot(tv, pv) / det;
  const Vec3 qv = cross(tv, e1);
  const double v = dot(r.d, qv) / det, t = dot(e2, qv) / det;
  if (u < 0 || v < 0 || u + v > 1 || t < r.tmin || t > r.tmax) return std::nullopt;
  margin = std::min({u, v, 1 - u - v});
  return t;
}

// The nearest hit over every cell's two triangles, split on the diagonal from (i+1, j) to
// (i, j+1), with no water level; `margin` of the hit found.
std::optional<double> brute_force(const HeightGrid& g, const Ray& r, double& margin) {
  std::optional<double> best;
  auto p = [&](int i, int j) {
    return Vec3{double(i) / (g.width - 1), height(g, i, j), double(j) / (g.depth - 1)};
  };
  for (int j = 0; j + 1 < g.depth; ++j)
    for (int i = 0; i + 1 < g.width; ++i) {
      double m = 0;
      for (const auto& t : {std::array<Vec3, 3>{p(i, j), p(i + 1, j), p(i, j + 1)},
                            std::array<Vec3, 3>{p(i + 1, j + 1), p(i, j + 1), p(i + 1, j)}}) {
        const auto h = hit_triangle(r, t[0], t[1], t[2], m);
        if (h && (!best || *h < *best)) best = h, margin = m;
      }
    }
  return best;
}

TEST(HeightField, ImageRowsAndColumnsAsPovRayLaysThemOut) {
  HeightImage img{3, 2, {1, 2, 3, 4, 5, 6}};  // top row 1 2 3, bottom row 4 5 6
  const HeightGrid g = height_grid_of(img);
  ASSERT_EQ(g.width, 3);
  ASSERT_EQ(g.depth, 2);
  EXPECT_EQ(height(g, 0, 0), 4 / 65536.0);  // bottom-left pixel at x = 0, z = 0
  EXPECT_EQ(height(g, 2, 0), 6 / 65536.0);
  EXPECT_EQ(height(g, 0, 1), 1 / 65536.0);  // top row at z = 1
}

TEST(HeightField, MeshMatchesABruteForceTriangleLoop) {
  Rng rng(4);
  const HeightGrid g = random_grid(rng, 9, 6);
  const MeshShape m{make_height_field(g, {})};
  int compared = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 o{rng.uniform(-0.5, 1.5), rng.uniform(0.9, 2), rng.uniform(-0.5, 1.5)};
    const Vec3 target{rng.uniform(0, 1), rng.uniform(0, 0.8), rng.uniform(0, 1)};
    const Ray r{o, target - o};
    double margin = 0;
    const std::optional<double> want = brute_force(g, r, margin);
    LocalHit h;
    const bool got = intersect(m, r, h);
    if (want && margin < 1e-5) continue;  // on an edge: float and double may pick either side
    ASSERT_EQ(got, want.has_value()) << k;
    if (got) {
      EXPECT_NEAR(h.t, *want, 1e-5 * (1 + *want)) << k;
      const SurfaceInfo si = surface(m, r, h);
      EXPECT_GT(si.n.y, 0);  // every face looks up
    }
    ++compared;
  }
  EXPECT_GT(compared, 3900);
}

TEST(HeightField, WaterLevelCutsTheSurfaceAtItsHeight) {
  // One cell: three corners at 0.2, one at 0.8; water at 0.5 leaves only the part above it.
  HeightGrid g{2, 2, {0.2, 0.2, 0.2, 0.8}};
  HeightFieldOptions o;
  o.water_level = 0.5;
  const MeshShape m{make_height_field(g, o)};
  LocalHit h;
  EXPECT_FALSE(intersect(m, Ray{{0.1, 2, 0.1}, {0, -1, 0}}, h));  // below the water: a hole
  ASSERT_TRUE(intersect(m, Ray{{0.95, 2, 0.95}, {0, -1, 0}}, h));
  // On triangle (1,1), (0,1), (1,0): y = 0.8 - 0.6 (1 - x) - 0.6 (1 - z) at x = z = 0.95.
  EXPECT_NEAR(2 - h.t, 0.8 - 0.6 * 0.05 * 2, 1e-6);
  const HeightFieldTriangles t = height_field_triangles(g, o);
  ASSERT_EQ(t.soup.positions.size(), 6u);  // the grid's 4 and the cut's 2, at the water
  EXPECT_FLOAT_EQ(t.soup.positions[4].y, 0.5f);
  EXPECT_FLOAT_EQ(t.soup.positions[5].y, 0.5f);
  o.water_level = 0.9;
  EXPECT_EQ(height_field_triangles(g, o).soup.triangles.size(), 0u);
}

TEST(HeightField, SmoothNormalsAreInterpolatedAndFlatGroundIsUp) {
  Rng rng(8);
  const HeightGrid g = random_grid(rng, 5, 5);
  HeightFieldOptions o;
  o.smooth = true;
  const HeightFieldTriangles t = height_field_triangles(g, o);
  ASSERT_EQ(t.normals.size(), t.soup.positions.size());
  for (const Vec3f& n : t.normals) {
    EXPECT_NEAR(length(n), 1, 1e-6);
    EXPECT_GT(n.y, 0);
  }
  const MeshShape m{make_height_field(g, o)};
  const Ray r{{0.4, 2, 0.55}, {0, -1, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(m, r, h));
  const SurfaceInfo si = surface(m, r, h);
  EXPECT_GT(length(si.shading_n - si.n), 1e-6);  // interpolated, not the face's
  HeightGrid flat{3, 4, std::vector<double>(12, 0.3)};
  for (const Vec3f& n : height_field_triangles(flat, o).normals) EXPECT_NEAR(n.y, 1, 1e-6);
}

TEST(HeightField, MirroredZKeepsTheFacesUp) {
  Rng rng(2);
  const HeightGrid g = random_grid(rng, 4, 3);
  HeightFieldOptions o;
  o.mirror_z = true;
  const MeshShape m{make_height_field(g, o)};
  LocalHit h;
  const Ray r{{0.3, 2, -0.6}, {0, -1, 0}};
  ASSERT_TRUE(intersect(m, r, h));
  EXPECT_GT(surface(m, r, h).n.y, 0);
  double margin;
  const auto want = brute_force(g, Ray{{0.3, 2, 0.6}, {0, -1, 0}}, margin);
  ASSERT_TRUE(want);
  EXPECT_NEAR(h.t, *want, 1e-6);
}

TEST(HeightField, GridsUnderTwoByTwoAreRejected) {
  EXPECT_THROW(height_field_triangles(HeightGrid{1, 5, std::vector<double>(5, 0)}, {}),
               std::invalid_argument);
  EXPECT_THROW(height_field_triangles(HeightGrid{2, 2, {0, 0, 0, NAN}}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
