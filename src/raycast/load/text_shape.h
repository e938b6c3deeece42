#pragma once
// Text shapes from font files: the letters' outlines (io/font_outline.h) swept into prisms.
#include <string>

#include "geometry/text.h"

namespace raycast {

/// The letters of `text` in the font file as solids: letter i swept along z from i * offset.z to
/// i * offset.z + thickness (negated when `flip_z`, for a mirrored frame), laid out with the
/// spacing (offset.x, offset.y) added after each letter. Letters without area (spaces) are left
/// out. Throws std::runtime_error when the font cannot be read, std::invalid_argument when no
/// letter has area.
Text make_text_shape(const std::string& font_file, const std::string& text, double thickness,
                     const Vec3& offset, bool flip_z = false);

}  // namespace raycast
