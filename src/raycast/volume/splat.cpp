#include "volume/splat.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace raycast {

namespace {

// z-planes per parallel task: enough work per task, few particles visited twice at slab edges.
constexpr int kPlanesPerTask = 4;

std::string str(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

}  // namespace

double cubic_spline_kernel(double r, double h) {
  const double q = r / h;
  double f = 0;
  if (q < 1)
    f = 1 - 1.5 * q * q + 0.75 * q * q * q;
  else if (q < 2)
    f = 0.25 * (2 - q) * (2 - q) * (2 - q);
  return f / (std::numbers::pi * h * h * h);
}

ScalarGrid splat_layout(const std::vector<Vec3>& particles, const SplatParams& p) {
  if (!(p.h > 0) || !std::isfinite(p.h))
    throw std::invalid_argument("smoothing_length must be finite and > 0");
  if (!(p.rest_density > 0) || !std::isfinite(p.rest_density))
    throw std::invalid_argument("rest_density must be finite and > 0");
  if (p.particle_volume && (!(*p.particle_volume > 0) || !std::isfinite(*p.particle_volume)))
    throw std::invalid_argument("particle_volume must be finite and > 0");
  Aabb dom;
  if (p.domain) {
    dom = *p.domain;
    if (!dom.is_bounded() || !(dom.lo.x < dom.hi.x && dom.lo.y < dom.hi.y && dom.lo.z < dom.hi.z))
      throw std::invalid_argument("domain.min must be < domain.max on every axis (finite)");
  } else {
    if (particles.empty()) throw std::invalid_argument("there are no particles");
    for (const Vec3& q : particles) dom.grow(q);
    const Vec3 r(2 * p.h, 2 * p.h, 2 * p.h);
    dom.lo -= r;
    dom.hi += r;
  }
  ScalarGrid g;
  g.lo = dom.lo;
  std::array<std::uint64_t, 3> n{};
  if (p.resolution) {
    if (p.cell_size) throw std::invalid_argument("give either resolution or cell_size, not both");
    for (int a = 0; a < 3; ++a) {
      if ((*p.resolution)[a] < 2) throw std::invalid_argument("resolution must be >= 2 per axis");
      n[a] = std::uint64_t((*p.resolution)[a]);
      g.cell[a] = (dom.hi[a] - dom.lo[a]) / double(n[a] - 1);
    }
  } else {
    const double c = p.cell_size ? *p.cell_size : p.h / 2;
    if (!(c > 0) || !std::isfinite(c)) throw std::invalid_argument("cell_size must be > 0");
    for (int a = 0; a < 3; ++a) {
      const double count = std::ceil((dom.hi[a] - dom.lo[a]) / c) + 1;
      if (!(count < 2e9))
        throw std::length_error("cell_size " + str(c) + " gives " + str(count) +
                                " nodes on one axis: too many");
      n[a] = std::max<std::uint64_t>(2, std::uint64_t(count));
      g.cell[a] = c;
    }
  }
  for (int a = 0; a < 3; ++a)
    if (n[a] > 2000000000) throw std::length_error("too many grid nodes on one axis");
  check_grid_fits(n);
  for (int a = 0; a < 3; ++a) g.n[a] = int(n[a]);
  return g;
}

ScalarGrid splat_particles(const std::vector<Vec3>& particles, const SplatParams& p) {
  for (const Vec3& q : particles)
    if (!is_finite(q)) throw std::invalid_argument("a particle position is not finite");
  ScalarGrid g = splat_layout(particles, p);
  const double h = p.h, support = 2 * h, support2 = support * support;
  const double mass =
      p.rest_density * (p.particle_volume ? *p.particle_volume : std::pow(h / 1.3, 3));
  const int nx = g.n[0], ny = g.n[1], nz = g.n[2];
  g.v.assign(std::size_t(nx) * ny * nz, 0.0f);

  // Node-index range [first, last] on axis a within the support of coordinate x (empty if none).
  auto range = [&](double x, int a, int& first, int& last) {
    const double lo = std::ceil((x - support - g.lo[a]) / g.cell[a]);
    const double hi = std::floor((x + support - g.lo[a]) / g.cell[a]);
    first = int(std::max(lo, 0.0));
    last = int(std::min(hi, double(g.n[a] - 1)));
  };
  // Bin particles by the task (slab of z-planes) of their first plane; a particle reaches at
  // most a fixed number of slabs after its own. Counting sort keeps particle order in each bin.
  const int tasks = (nz + kPlanesPerTask - 1) / kPlanesPerTask;
  std::vector<std::uint32_t> start(std::size_t(tasks) + 1, 0);
  std::vector<int> first_plane(particles.size()), last_plane(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    range(particles[i].z, 2, first_plane[i], last_plane[i]);
    if (first_plane[i] <= last_plane[i]) ++start[std::size_t(first_plane[i] / kPlanesPerTask) + 1];
  }
  for (int t = 0; t < tasks; ++t) start[t + 1] += start[t];
  std::vector<std::uint32_t> order(start[tasks]);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < particles.size(); ++i)
      if (first_plane[i] <= last_plane[i])
        order[fill[std::size_t(first_plane[i] / kPlanesPerTask)]++] = std::uint32_t(i);
  }
  // A particle starting in slab s reaches planes up to first + 4h / c: the slabs to look back.
  const int reach = int(std::ceil(2 * support / g.cell.z)) / kPlanesPerTask + 1;

  tbb::parallel_for(tbb::blocked_range<int>(0, tasks), [&](const tbb::blocked_range<int>& r) {
    std::vector<double> acc;
    for (int task = r.begin(); task != r.end(); ++task) {
      const int k0 = task * kPlanesPerTask, k1 = std::min(k0 + kPlanesPerTask, nz);
      acc.assign(std::size_t(nx) * ny * (k1 - k0), 0.0);
      for (int b = std::max(0, task - reach); b <= task; ++b)
        for (std::uint32_t s = start[b]; s < start[b + 1]; ++s) {
          const std::uint32_t i = order[s];
          const int z0 = std::max(first_plane[i], k0), z1 = std::min(last_plane[i], k1 - 1);
          if (z0 > z1) continue;
          const Vec3& x = particles[i];
          int x0, x1, y0, y1;
          range(x.x, 0, x0, x1);
          range(x.y, 1, y0, y1);
          for (int k = z0; k <= z1; ++k) {
            const double dz = g.lo.z + k * g.cell.z - x.z;
            for (int j = y0; j <= y1; ++j) {
              const double dy = g.lo.y + j * g.cell.y - x.y;
              double* row = &acc[(std::size_t(k - k0) * ny + j) * nx];
              const double yz2 = dy * dy + dz * dz;
              if (yz2 >= support2) continue;
              for (int ii = x0; ii <= x1; ++ii) {
                const double dx = g.lo.x + ii * g.cell.x - x.x;
                const double r2 = dx * dx + yz2;
                if (r2 >= support2) continue;
                row[ii] += mass * cubic_spline_kernel(std::sqrt(r2), h);
              }
            }
          }
        }
      float* out = &g.v[std::size_t(k0) * nx * ny];
      for (std::size_t m = 0; m < acc.size(); ++m) out[m] = float(acc[m]);
    }
  });
  return g;
}

}  // namespace raycast
