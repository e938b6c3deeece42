#pragma once
// `{frame}` patterns in file names (docs/iso-surfaces.md): `fluid_{frame:04d}.ply` with frame 7
// is `fluid_0007.ply`; `{frame}` alone prints the number as is.
#include <string>

namespace raycast {

/// Whether the text holds a `{frame` pattern.
bool has_frame_pattern(const std::string& text);

/// Replaces every `{frame}` and `{frame:0Nd}` / `{frame:Nd}` (N = 1..9: zero- or space-padded
/// to N digits) with the frame number. Throws std::invalid_argument for any other `{frame...}`.
std::string expand_frame_pattern(const std::string& text, int frame);

}  // namespace raycast
