#pragma once
// "What is under this pixel?": one primary ray through the pixel's centre, answered as JSON.
#include <string>

#include "scene/scene.h"

namespace raycast::serve {

/// The JSON answer for raster position (x, y) of a width x height image seen through `camera`:
/// {"hit": false} or {"hit": true, "t", "point", "normal", "object": {"index", "entry", "shape",
/// "line", "column"}, "material"}. x and y must lie in [0, width) x [0, height).
std::string pick_json(const Scene& scene, const CameraDesc& camera, int width, int height, double x,
                      double y);

}  // namespace raycast::serve
