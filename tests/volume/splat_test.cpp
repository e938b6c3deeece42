// Splatting against a direct sum over all particles, determinism across thread counts, and one
// particle's iso-surface radius against the kernel's closed form.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <random>

#include "volume/isosurface.h"
#include "volume/splat.h"

namespace raycast {
namespace {

std::vector<Vec3> random_particles(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<Vec3> p(static_cast<std::size_t>(n));
  for (Vec3& q : p) q = {u(rng), 0.6 * u(rng), 1.3 * u(rng)};
  return p;
}

TEST(Splat, Kernel_ClosedFormAndNormalised) {
  const double h = 0.7;
  EXPECT_DOUBLE_EQ(cubic_spline_kernel(0, h), 1 / (std::numbers::pi * h * h * h));
  EXPECT_DOUBLE_EQ(cubic_spline_kernel(h, h), 0.25 / (std::numbers::pi * h * h * h));
  EXPECT_EQ(cubic_spline_kernel(2 * h, h), 0);
  EXPECT_EQ(cubic_spline_kernel(3 * h, h), 0);
  // Integral over space is 1 (midpoint rule in r).
  double sum = 0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    const double r = (i + 0.5) * 2 * h / steps;
    sum += 4 * std::numbers::pi * r * r * cubic_spline_kernel(r, h) * 2 * h / steps;
  }
  EXPECT_NEAR(sum, 1, 1e-6);
}

TEST(Splat, EqualsDirectSumOverAllParticles) {
  const std::vector<Vec3> p = random_particles(400, 3);
  SplatParams sp;
  sp.h = 0.08;
  sp.particle_volume = 0.0005;
  sp.cell_size = 0.045;
  const ScalarGrid g = splat_particles(p, sp);
  const double mass = 1000 * 0.0005;
  int nonzero = 0;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const Vec3 x = g.lo + Vec3{i * g.cell.x, j * g.cell.y, k * g.cell.z};
        double direct = 0;
        for (const Vec3& q : p) direct += mass * cubic_spline_kernel(length(q - x), sp.h);
        // Same terms in the same order (the splat only leaves out exact zeros): equal floats.
        ASSERT_EQ(g.at(i, j, k), float(direct)) << i << " " << j << " " << k;
        nonzero += direct > 0;
      }
  EXPECT_GT(nonzero, 1000);
}

TEST(Splat, Layout_DomainAndCellSize) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0.5, 0.25}};
  SplatParams sp;
  sp.h = 0.1;
  ScalarGrid g = splat_layout(p, sp);
  EXPECT_EQ(g.lo, (Vec3{-0.2, -0.2, -0.2}));
  EXPECT_EQ(g.cell, (Vec3{0.05, 0.05, 0.05}));
  EXPECT_EQ(g.n[0], int(std::ceil(1.4 / 0.05)) + 1);
  sp.resolution = std::array<int, 3>{11, 5, 3};
  g = splat_layout(p, sp);
  EXPECT_EQ(g.n, (std::array<int, 3>{11, 5, 3}));
  EXPECT_DOUBLE_EQ(g.cell.x, 1.4 / 10);
  sp.cell_size = 0.1;
  EXPECT_THROW(splat_layout(p, sp), std::invalid_argument);  // both
  sp.resolution.reset();
  sp.cell_size = 1e-7;  // far too many nodes: refused before allocating, with the size
  try {
    splat_layout(p, sp);
    FAIL();
  } catch (const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("bytes"), std::string::npos) << e.what();
  }
  sp.cell_size.reset();
  sp.h = -1;
  EXPECT_THROW(splat_layout(p, sp), std::invalid_argument);
  sp.h = 0.1;
  EXPECT_THROW(splat_particles({}, sp), std::invalid_argument);
  EXPECT_THROW(splat_particles({{0, std::nan(""), 0}}, sp), std::invalid_argument);
}

TEST(Splat, SameResultForAnyThreadCount) {
  const std::vector<Vec3> p = random_particles(3000, 4);
  SplatParams sp;
  sp.h = 0.05;
  ScalarGrid one;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = splat_particles(p, sp);
  }
  tbb::global_control c(tbb::global_control::max_allowed_parallelism, 4);
  const ScalarGrid many = splat_particles(p, sp);
  ASSERT_EQ(one.v.size(), many.v.size());
  EXPECT_TRUE(one.v == many.v);
}

// rho(r) = V rho0 f(r / h) / (pi h^3) = iso with 1 <= q < 2: r = h (2 - cbrt(4 pi h^3 iso / m)).
TEST(Splat, OneParticle_RadiusMatchesKernelClosedForm) {
  const double h = 1, v = 1, rho0 = 1;
  const double radius = 1.25;
  const double iso = v * rho0 * 0.25 * std::pow(2 - radius / h, 3) / (std::numbers::pi * h * h * h);
  EXPECT_NEAR(h * (2 - std::cbrt(4 * std::numbers::pi * h * h * h * iso / (v * rho0))), radius,
              1e-14);
  for (const double cell : {0.05, 0.2}) {
    SplatParams sp;
    sp.h = h;
    sp.rest_density = rho0;
    sp.particle_volume = v;
    sp.cell_size = cell;
    const Isosurface s = make_isosurface(splat_particles({{0, 0, 0}}, sp), iso);
    // Along a node line the field is the linear interpolation of exact kernel values: the
    // error is below c^2 max|f''| / (8 |f'|) ~ 0.34 c^2 near q = 1.25.
    const double bound = 0.34 * cell * cell;
    LocalHit hit;
    ASSERT_TRUE(intersect(s, Ray{{-5, 0, 0}, {1, 0, 0}}, hit));
    EXPECT_NEAR(5 - hit.t, radius, bound) << cell;
    if (cell == 0.2) {
      EXPECT_GT(std::abs(5 - hit.t - radius), 1e-4);  // the bound is not vacuous
    }
    // Off the node lines (trilinear in 3 axes) the error is of the same order.
    const Vec3 d = normalize(Vec3{1, 0.37, -0.61});
    ASSERT_TRUE(intersect(s, Ray{-4.0 * d, d}, hit));
    EXPECT_NEAR(4 - hit.t, radius, 3 * bound) << cell;
    // Inside at the centre, outside beyond the radius.
    EXPECT_TRUE(contains(s, {0, 0, 0}));
    EXPECT_FALSE(contains(s, {0, radius + 4 * bound, 0}));
  }
}

}  // namespace
}  // namespace raycast
