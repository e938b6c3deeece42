#pragma once
// An explained pixel drawn as the lecture slides draw it: the plane through the camera ray and
// the first hit's normal (so the first reflected and refracted rays lie in it), the scene's
// cross-section in that plane shaded per object, and the ray tree as arrows over it.
#include <string>

#include "render/explain.h"

namespace raycast {

/// The drawing as a standalone SVG document. Solids are found by sampling the plane on a grid
/// with their inside test (open surfaces have no inside and are not drawn); rays that leave the
/// plane are drawn projected onto it, dotted. Shadow rays are dashed, those blocked end in a
/// cross at the blocker.
std::string explain_svg(const Scene& scene, const Explanation& e);

}  // namespace raycast
