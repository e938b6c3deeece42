#pragma once
// Several renders of one scene side by side in one picture (the `--max-depth` sweep), each
// captioned.
#include <string>
#include <vector>

#include "io/image.h"

namespace raycast {

/// The images (all the same size) in one row, `gap` pixels apart on a white sheet, each with
/// its caption (digits and the few letters of render/glyphs.h) drawn below it.
Image make_contact_sheet(const std::vector<Image>& images, const std::vector<std::string>& captions,
                         int gap = 4);

}  // namespace raycast
