#pragma once
// SPH particles to a density grid (see docs/iso-surfaces.md): rho(x_i) = sum_j V_j rho0
// W(|x_j - x_i|, h) at every grid node x_i, with the cubic spline kernel.
#include <array>
#include <optional>
#include <vector>

#include "volume/grid.h"

namespace raycast {

/// The cubic spline kernel (Monaghan 1992): W = f(q) / (pi h^3), q = r / h, f = 1 - 1.5 q^2 +
/// 0.75 q^3 for q < 1, 0.25 (2 - q)^3 for 1 <= q < 2, else 0.
double cubic_spline_kernel(double r, double h);

/// How particles become a grid. Defaults follow docs/iso-surfaces.md.
struct SplatParams {
  double h = 0;                                  // smoothing length, > 0
  double rest_density = 1000;                    // rho0, > 0
  std::optional<double> particle_volume;         // V; default (h / 1.3)^3
  std::optional<Aabb> domain;                    // default: the particles' bounds grown by 2h
  std::optional<std::array<int, 3>> resolution;  // nodes per axis (>= 2), spanning the domain
  std::optional<double> cell_size;               // default h / 2 (when no resolution)
};

/// The grid the parameters define, without values (n, lo, cell). Throws std::invalid_argument for
/// bad parameters and std::length_error (with the bytes needed) for a grid that does not fit.
ScalarGrid splat_layout(const std::vector<Vec3>& particles, const SplatParams& p);

/// The density grid. Parallel over slabs of z-planes (oneTBB); every node sums its particles in
/// particle order, in double, so the result does not depend on the thread count. Each particle
/// touches only the nodes within 2h of it: the work is linear in the particle count.
ScalarGrid splat_particles(const std::vector<Vec3>& particles, const SplatParams& p);

}  // namespace raycast
