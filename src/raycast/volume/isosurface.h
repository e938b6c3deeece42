#pragma once
// The iso-surface of a scalar grid as a closed solid: inside where the trilinear field exceeds
// `iso` (see docs/iso-surfaces.md). Rays walk a min/max macro-grid and then the cells with a
// 3D-DDA; in each cell the field along the ray is a cubic whose crossings are found exactly.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/shape.h"
#include "volume/grid.h"

namespace raycast {

/// Cells per macro-cell per axis: a macro-cell whose node range excludes iso is crossed in one
/// step.
inline constexpr int kMacroCell = 4;

/// The shared, immutable data of an iso-surface: the grid, the level and the macro-grid ranges.
struct IsoData {
  ScalarGrid grid;
  double iso = 0;
  std::array<int, 3> macro_n{};  // macro-cells per axis
  std::vector<float> macro_min;  // per macro-cell: the least node value of its cells
  std::vector<float> macro_max;  // and the greatest
  Aabb inside_bounds;            // the macro-cells that may hold points inside the solid
};

/// The solid {field > iso} of a trilinearly interpolated grid; the field is 0 outside the grid,
/// so where the grid's boundary nodes exceed iso the solid is closed by the grid box's faces.
/// LocalHit: part 0 the iso-surface (a = the root's error bound in t, b = the linear cell index),
/// part 1 + face a grid box face (0..5 = -x, +x, -y, +y, -z, +z). (u, v) = (0, 0).
struct Isosurface {
  static constexpr const char* kName = "isosurface";
  std::shared_ptr<const IsoData> data;
};

/// Builds the macro-grid. Throws std::invalid_argument for iso < 0 or not finite, a grid with
/// fewer than 2 nodes on an axis, a non-positive or non-finite spacing, or a non-finite value.
Isosurface make_isosurface(ScalarGrid grid, double iso);

Aabb bounds(const Isosurface& s);
bool intersect(const Isosurface& s, const Ray& ray, LocalHit& hit);
bool occluded(const Isosurface& s, const Ray& ray);
void spans(const Isosurface& s, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Isosurface& s, const Ray& ray, const LocalHit& hit);
bool contains(const Isosurface& s, const Vec3& p);
inline bool is_closed(const Isosurface&) { return true; }

/// One crossing of the line with the solid's boundary, for tests and `spans`.
struct IsoCrossing {
  LocalHit hit;
  bool entering = false;
};

/// Every crossing of the line o + t d with t in [ta, tb], in order (entering and leaving
/// alternate). With skip_empty = false every cell is solved (the brute-force reference for the
/// macro-grid and the cell-range skipping); the crossings are the same.
std::vector<IsoCrossing> iso_crossings(const IsoData& d, const Ray& ray, double ta, double tb,
                                       bool skip_empty = true);

}  // namespace raycast
