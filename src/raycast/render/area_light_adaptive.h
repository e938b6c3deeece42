#pragma once
// POV-Ray's `adaptive N` sampling of an area light's grid: the corners of a coarse grid of
// (2^N + 1) x (2^N + 1) points first, a cell split in four (at the grid points nearest its
// middle) only where its corners' samples differ, down to single grid steps.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/light_falloff.h"

namespace raycast {

namespace detail {

// One adaptive pass over a size1 x size2 grid. Each grid point belongs to one cell: the cell's
// lower rows and columns, and its upper ones too on the grid's last row or column, so the
// cells' points tile the grid. A cell whose corners agree stands for all its points with the
// corners' value; a cell split down to single steps has sampled every point it holds, so a
// grid split everywhere gives the full grid's sum exactly.
template <class Sample>
class AdaptiveAreaGrid {
 public:
  AdaptiveAreaGrid(const Light& light, const Vec3& p, Rng& rng, Sample& sample)
      : grid_(light, p), rng_(rng), sample_(sample), n1_(light.size1), n2_(light.size2) {
    // Reused by the thread's later calls: the grid holds at most 64 x 64 points.
    thread_local std::vector<Color> values;
    thread_local std::vector<std::uint8_t> known;
    values.resize(std::size_t(n1_) * n2_);
    known.assign(std::size_t(n1_) * n2_, 0);
    values_ = values.data();
    known_ = known.data();
  }

  Color sum(int level) {
    const std::vector<int> rows = coarse(n1_, level), columns = coarse(n2_, level);
    for (std::size_t a = 0; a + 1 < rows.size(); ++a)
      for (std::size_t b = 0; b + 1 < columns.size(); ++b)
        cell(rows[a], rows[a + 1], columns[b], columns[b + 1]);
    return total_;
  }

 private:
  // The coarse grid's indices along a side of n points: 2^level equal steps, rounded to grid
  // points (fewer where the side has fewer); a side of 1 point is one cell [0, 0].
  static std::vector<int> coarse(int n, int level) {
    if (n == 1) return {0, 0};
    const int steps = 1 << level;
    std::vector<int> at;
    for (int k = 0; k <= steps; ++k) {
      const int i = int((long(k) * (n - 1) * 2 + steps) / (2 * steps));  // nearest, halves up
      if (at.empty() || at.back() != i) at.push_back(i);
    }
    return at;
  }

  const Color& value(int i, int j) {
    const std::size_t k = std::size_t(i) * n2_ + j;
    if (!known_[k]) {
      values_[k] = sample_(grid_.point(i, j, rng_));
      known_[k] = 1;
    }
    return values_[k];
  }

  // The points of a cell's side [lo, hi] that the cell holds.
  static int held(int lo, int hi, int n) { return hi - lo + (hi == n - 1 ? 1 : 0); }

  void cell(int i0, int i1, int j0, int j1) {
    const Color c = value(i0, j0);
    const bool agree = same(c, value(i1, j0)) && same(c, value(i0, j1)) && same(c, value(i1, j1));
    if (agree) {
      total_ += double(held(i0, i1, n1_) * held(j0, j1, n2_)) * c;
      return;
    }
    const bool split1 = i1 - i0 >= 2, split2 = j1 - j0 >= 2;
    if (!split1 && !split2) {  // every point the cell holds is one of its corners
      for (int i = i0; i < i0 + held(i0, i1, n1_); ++i)
        for (int j = j0; j < j0 + held(j0, j1, n2_); ++j) total_ += value(i, j);
      return;
    }
    const int mi = split1 ? (i0 + i1) / 2 : i0, mj = split2 ? (j0 + j1) / 2 : j0;
    cell(i0, split1 ? mi : i1, j0, split2 ? mj : j1);
    if (split1) cell(mi, i1, j0, split2 ? mj : j1);
    if (split2) cell(i0, split1 ? mi : i1, mj, j1);
    if (split1 && split2) cell(mi, i1, mj, j1);
  }

  static bool same(const Color& a, const Color& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }

  const AreaLightGrid grid_;
  Rng& rng_;
  Sample& sample_;
  const int n1_, n2_;
  Color* values_ = nullptr;
  std::uint8_t* known_ = nullptr;
  Color total_{0, 0, 0};
};

}  // namespace detail

/// The sum over the area light's grid, seen from p, of sample(target) (a Color: one grid point's
/// share of the light through its shadow ray), sampled adaptively at light.adaptive >= 0: cells
/// whose corners agree count their unsampled points at the corners' value.
/// Not inlined: kept out of the shading code of the lights sampled in full.
template <class Sample>
[[gnu::noinline]] Color adaptive_area_light_sum(const Light& light, const Vec3& p, Rng& rng,
                                                Sample&& sample) {
  detail::AdaptiveAreaGrid<Sample> grid(light, p, rng, sample);
  return grid.sum(std::max(light.adaptive, 0));
}

}  // namespace raycast
