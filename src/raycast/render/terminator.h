#pragma once
// The shadow terminator of smooth-shaded meshes (docs/rendering.md "Smooth meshes"): a shadow
// ray leaving the flat triangle where the interpolated normal already faces the light re-enters
// the neighbouring facets and draws their staircase. Hanika 2021, "Hacking the Shadow
// Terminator" (Ray Tracing Gems II, ch. 4): start shadow rays from the point the vertex normals'
// tangent planes describe instead.
#include "objects/object.h"

namespace raycast {

/// The surface record to spawn shadow rays from for a hit on o: for a top-level smooth mesh, si
/// with p moved to p' = p - sum_i b_i min(0, (p - v_i) . n_i) n_i (object space: b the
/// barycentrics, v_i the vertices, n_i their unit normals turned to the shading normal's side),
/// carried to world space, and p_error widened by the rounding of the move; otherwise si itself.
/// Use it only for rays leaving on the side the shading normal si.shading_n points to. When the
/// move would go against the geometric normal's side, si is returned unchanged.
SurfaceInfo terminator_origin(const Object& o, const LocalHit& hit, const SurfaceInfo& si);

/// Whether terminator_origin may move a hit on o (o is a smooth mesh); for every other object it
/// returns si itself, so callers may skip it.
bool has_terminator_origin(const Object& o);

}  // namespace raycast
