#pragma once
// Early split clipping (Ernst and Greiner 2007): before the SAH build, the references of
// triangles whose box is much larger than the triangle are cut into pieces with tighter boxes,
// so that the tree's boxes fit long thin and diagonal triangles better. A triangle then sits in
// several leaves (the every-hit query removes the repeats: MeshBvh::split).
#include <array>
#include <cstdint>
#include <span>

#include "accel/bvh.h"
#include "math/vec3.h"

namespace raycast {

/// Splits the references `refs` (one per triangle: refs[i] the float box of triangles[i], index
/// i) and appends at most budget * triangles.size() extra references. The piece of largest
/// wasted area (its box's half area minus the area of the triangle inside it) is split first,
/// and only pieces whose box's half area exceeds min_ratio times that area are split at all:
/// its box is halved at the float midpoint of its longest axis, the triangle clipped (in double)
/// to each half, and each piece gets the clipped polygon's box rounded outwards to float and
/// intersected with its half. So every point of a triangle lies in one of its pieces' boxes (a
/// point on the split plane in both). Serial and deterministic (the same for any thread count).
void split_triangle_refs(std::span<const Vec3f> positions,
                         std::span<const std::array<std::uint32_t, 3>> triangles, double budget,
                         double min_ratio, BvhBuildRefs& refs);

}  // namespace raycast
