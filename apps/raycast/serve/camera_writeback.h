#pragma once
// "Save camera" on the page: the camera written back into the scene file, replacing only its
// top-level `camera:` block (or adding one), every other line kept byte for byte. When that
// cannot be done safely (a JSON scene, a layout we do not recognise), the camera goes to a
// sidecar file SCENE.camera.yaml instead, for the user to paste.
#include <string>

#include "scene/render_settings.h"

namespace raycast::serve {

/// The camera as one YAML line, numbers in their shortest exact form:
/// `camera: {type: perspective, position: [..], look_at: [..], up: [..], fov: ..}`.
std::string camera_yaml(const CameraDesc& camera);

/// The scene text with its camera block replaced by `camera_yaml(camera)`; false when the text
/// has no recognisable top-level block layout (JSON, or `camera` not at column 1).
bool replace_camera_block(const std::string& text, const CameraDesc& camera, std::string& out);

struct WriteResult {
  std::string path;      // the file written
  bool sidecar = false;  // the camera went to SCENE.camera.yaml (why: `reason`)
  std::string reason;
};

/// Writes the camera into the scene file (atomically: a temporary file renamed over it) after
/// checking that the new text loads and gives exactly this camera; else writes the sidecar.
/// Throws std::runtime_error when no file could be written.
WriteResult write_camera(const std::string& scene_path, const CameraDesc& camera);

}  // namespace raycast::serve
