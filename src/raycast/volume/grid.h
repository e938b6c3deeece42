#pragma once
// A scalar field sampled on the nodes of a regular grid, trilinear inside each cell (see
// docs/iso-surfaces.md): node (i, j, k) sits at lo + (i, j, k) * cell, values are float32 with x
// varying fastest.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/aabb.h"

namespace raycast {

struct ScalarGrid {
  std::array<int, 3> n{};  // nodes per axis, each >= 2
  Vec3 lo;                 // node (0, 0, 0)
  Vec3 cell;               // node spacing per axis, > 0
  std::vector<float> v;    // n[0] * n[1] * n[2] values

  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i;
  }
  float at(int i, int j, int k) const { return v[index(i, j, k)]; }
  /// The last node's position (lo + (n - 1) * cell).
  Vec3 hi() const {
    return {lo.x + (n[0] - 1) * cell.x, lo.y + (n[1] - 1) * cell.y, lo.z + (n[2] - 1) * cell.z};
  }
  Aabb box() const { return {lo, hi()}; }
};

/// The bytes a grid of these node counts needs (values plus the iso-surface's range tables), or
/// 0 when the count overflows 64 bits.
std::uint64_t grid_bytes(const std::array<std::uint64_t, 3>& n);

/// Throws std::length_error("... needs N bytes (X GiB), more than the Y GiB of memory available")
/// when a grid of these node counts would not fit, before anything is allocated.
void check_grid_fits(const std::array<std::uint64_t, 3>& n);

/// The field at p by trilinear interpolation in the cell holding p (clamped to the grid); 0
/// outside the grid's box.
double sample(const ScalarGrid& g, const Vec3& p);

/// "12.3 MiB", "4.0 GiB": a byte count for messages.
std::string format_bytes(double bytes);

}  // namespace raycast
