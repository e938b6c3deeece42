#pragma once
// POV-Ray's height field as a triangle mesh: a grid of heights over the unit square in x and z,
// two triangles per cell, cut at a water level.
#include <memory>
#include <vector>

#include "io/height_image.h"
#include "io/triangle_soup.h"
#include "mesh/mesh.h"

namespace raycast {

/// Heights y[z * width + x] at x = i / (width - 1), z = j / (depth - 1) (both at least 2).
struct HeightGrid {
  int width = 0;
  int depth = 0;
  std::vector<double> y;
};

/// The grid of an image as POV-Ray lays it out: the image's bottom row at z = 0, its top row at
/// z = 1, its left column at x = 0, each 16-bit value v at height v / 65536.
HeightGrid height_grid_of(const HeightImage& image);

struct HeightFieldOptions {
  bool smooth = false;     // vertex normals (each the mean of its four neighbouring faces')
  double water_level = 0;  // the surface below this height is cut away
  bool mirror_z = false;   // z negated (and the winding kept facing up)
};

/// Cell (i, j) spans [x_i, x_i+1] x [z_j, z_j+1]; its two triangles meet on the diagonal from
/// (x_i+1, z_j) to (x_i, z_j+1), each wound so that its normal has y > 0. Parts below the water
/// level are clipped off at y = water_level. The normals (smooth only) are one per position.
/// Throws std::invalid_argument for a grid under 2 x 2 or with non-finite heights.
struct HeightFieldTriangles {
  TriangleSoup soup;
  std::vector<Vec3f> normals;
};
HeightFieldTriangles height_field_triangles(const HeightGrid& grid,
                                            const HeightFieldOptions& options);

/// The mesh of height_field_triangles (a mesh of no triangles when all lies below the water).
std::shared_ptr<const Mesh> make_height_field(const HeightGrid& grid,
                                              const HeightFieldOptions& options);

}  // namespace raycast
