#pragma once
// An explained pixel written out (docs/explain.md): an indented text tree for people, JSON for
// programs (the keys are part of the contract), and an SVG drawing of the tree in the plane of
// the camera ray over the scene's cross-section.
#include <string>

#include "render/explain.h"

namespace raycast {

/// The tree as indented text, one ray per block, each hit's shading written as the sum it is.
std::string explain_text(const Scene& scene, const Explanation& e);

/// The tree as one JSON object: `pixel`, `sample`, `samples`, `color` (linear RGB) and `ray`; a
/// ray has `kind` (camera, shadow, reflection, refraction), `origin`, `direction`, `tmin`,
/// `tmax`, `depth`, `weight`, `hit` (null on a miss) and `children`; a hit has `object` (the
/// top-level entry, as `raycast cast` counts), `t`, `point`, `normal` and `shading` (the terms
/// by name, summing to the ray's `radiance`). Non-finite numbers are written as null.
std::string explain_json(const Scene& scene, const Explanation& e);

/// The shortest decimal text that reads back as the same double (%.17g at most); null for NaN
/// and infinities.
std::string json_double(double value);

}  // namespace raycast
