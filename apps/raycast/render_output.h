#pragma once
// Writing what `raycast render` produced: the image (depth normalised for 8-bit files) and the
// AOV files beside it. Shared by the single-process and the distributed (MPI) renders.
#include <string>

#include "io/image.h"

namespace raycast::cli {

/// Depth for an 8-bit image: distances divided by twice the median finite distance and clamped
/// to [0, 1] (robust against a ground plane running to the horizon), misses white. Also used by
/// `raycast serve` for its depth passes.
void normalize_depth(Image& image);

/// "out.png" + "depth" -> "out.depth.pfm" (next to the output).
std::string aov_path(const std::string& output, const std::string& aov);

/// Saves the image in the format of the path's extension, or as PNG on standard output for `-`;
/// `depth`: the image holds distances (normalised for an 8-bit file). Throws ImageError.
void save_render(Image image, const std::string& path, bool depth);

}  // namespace raycast::cli
