#pragma once
// Where `render` writes its image (docs/cli.md): a file whose extension names the format, or `-`
// for PNG on standard output. Checked before any work, so a bad path fails in a moment, not
// after the render.
#include <string>

#include "io/image.h"

namespace raycast::cli {

/// Whether `path` is `-`, standard output.
inline bool is_stdout(const std::string& path) { return path == "-"; }

/// Why no file can be written at `path` (a missing folder, no permission, a directory), or an empty
/// string when one can. The file is opened for appending, so an existing file is not changed, and
/// a file created only by the check is removed again.
std::string output_problem(const std::string& path);

/// Writes the image to `path` in its extension's format, or as PNG to standard output for `-`.
/// Throws ImageError.
void write_output_image(const Image& image, const std::string& path);

}  // namespace raycast::cli
