#pragma once
// The camera the page asks for (orbit, pan, zoom): read from a JSON body and checked as strictly
// as the scene loader checks a `camera` block, plus a bound on coordinates; NaN is refused.
#include <string>

#include "scene/render_settings.h"

namespace raycast::serve {

/// Coordinates beyond this magnitude are refused (they could only come from a broken client).
inline constexpr double kMaxCoordinate = 1e9;

/// Reads {"type", "position", "look_at", "up", "fov", "height"}: absent fields keep `current`'s
/// values. Throws SceneError (file "request") naming the field at fault.
CameraDesc parse_camera_request(const std::string& body, const CameraDesc& current);

/// The camera as JSON, with the same field names.
std::string camera_json(const CameraDesc& camera);

}  // namespace raycast::serve
