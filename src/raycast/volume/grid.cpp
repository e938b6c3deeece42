#include "volume/grid.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace raycast {

std::uint64_t grid_bytes(const std::array<std::uint64_t, 3>& n) {
  std::uint64_t count = 1;
  for (std::uint64_t k : n) {
    if (k == 0) return 0;
    if (count > UINT64_MAX / k) return 0;
    count *= k;
  }
  // float values, plus at most 2 floats per cell of range tables (cells and macro-cells).
  if (count > UINT64_MAX / 16) return 0;
  return count * 4 + (count / 512 + 1) * 8;
}

std::string format_bytes(double bytes) {
  char buf[64];
  if (bytes >= 1024.0 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / (1024.0 * 1024));
  return buf;
}

void check_grid_fits(const std::array<std::uint64_t, 3>& n) {
  const std::uint64_t bytes = grid_bytes(n);
  const std::string dims =
      std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]);
  if (bytes == 0 && n[0] && n[1] && n[2])
    throw std::length_error("a grid of " + dims + " nodes needs more than 2^64 bytes");
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  const double available = pages > 0 && page > 0 ? double(pages) * double(page) : 0;
  if (available > 0 && double(bytes) > available)
    throw std::length_error("a grid of " + dims + " nodes needs " + std::to_string(bytes) +
                            " bytes (" + format_bytes(double(bytes)) + "), more than the " +
                            format_bytes(available) + " of memory available");
}

double sample(const ScalarGrid& g, const Vec3& p) {
  if (!g.box().contains(p)) return 0;
  int c[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double x = (p[a] - g.lo[a]) / g.cell[a];
    c[a] = std::clamp(static_cast<int>(std::floor(x)), 0, g.n[a] - 2);
    f[a] = x - c[a];
  }
  double r = 0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        r += (i ? f[0] : 1 - f[0]) * (j ? f[1] : 1 - f[1]) * (k ? f[2] : 1 - f[2]) *
             g.at(c[0] + i, c[1] + j, c[2] + k);
  return r;
}

}  // namespace raycast
