#pragma once
// PNG bytes in memory for the page (io/ writes files only): 8-bit sRGB, the same codes as
// `raycast render -o x.png` (io/image.h linear_to_srgb8).
#include <string>

#include "io/image.h"

namespace raycast::serve {

/// The image as a PNG file's bytes. Throws std::runtime_error if libpng fails.
std::string encode_png(const Image& image);

}  // namespace raycast::serve
