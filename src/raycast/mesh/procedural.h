#pragma once
// Procedural triangle meshes for benchmarks and tests, made in memory at any size.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/triangle_soup.h"
#include "math/vec3.h"

namespace raycast {

/// A closed sphere of radius about 1 around the origin: the octahedron with each face split into
/// n^2 triangles (8 n^2 in all), vertices pushed to the sphere and displaced radially by
/// `displacement` times a smooth deterministic bump function. Vertices are shared (indexed), the
/// winding is counter-clockwise seen from outside.
TriangleSoup make_octa_sphere(int n, double displacement = 0.05, const Vec3& centre = {0, 0, 0},
                              double radius = 1);

/// `sphere`: a displaced octa-sphere of about `triangles` triangles. `forest`: a height-field
/// terrain (about a tenth of the triangles) with displaced spheres ("trees") standing on it, the
/// rest of the triangles, all in one open mesh. Throws std::invalid_argument for another name or a
/// count below 8 or above 2^31.
TriangleSoup make_procedural_mesh(const std::string& name, std::size_t triangles);

}  // namespace raycast
