#pragma once
// POV-Ray's transformations as written (XformOp) composed into one transform in POV-Ray's own
// coordinates (no change of handedness), for textures, which are evaluated in those coordinates.
#include <optional>
#include <vector>

#include "math/transform.h"
#include "pov/pov_scene.h"

namespace raycast::pov {

/// The steps first to last as one transform (the later ones applied after); nullopt for a
/// singular matrix. An empty list is the identity.
std::optional<Transform> pov_transform(const std::vector<XformOp>& ops);

}  // namespace raycast::pov
