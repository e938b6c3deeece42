#pragma once
// `raycast render SCENE --frames A-B -o out_{frame:04d}.png`: one image per frame, `{frame}`
// patterns in the scene's data paths and in the output expanded (docs/iso-surfaces.md).
#include <string>

#include "render/renderer.h"

namespace raycast::cli {

/// Prints "raycast render: MESSAGE" to stderr and returns 2, the exit code of bad usage.
int usage_error(const std::string& message);

/// Renders frames A..B (inclusive; "A" alone is one frame). A frame whose scene fails to load or
/// whose image cannot be written is reported on stderr by frame number and file, and the others
/// still render. Returns 0 when every frame rendered, 2 for bad usage or any failed frame.
int render_frames(const std::string& scene, const std::string& output, const std::string& frames,
                  const RenderOptions& options);

/// One frame: loads the scene for `frame`, renders it and writes the output pattern expanded for
/// it (returned in `written`). Throws SceneError or ImageError.
RenderStats render_frame(const std::string& scene, const std::string& output, int frame,
                         const RenderOptions& options, std::string& written);

}  // namespace raycast::cli
