#pragma once
// A 3x5 pixel font for the numbers and short labels drawn into images (heatmap scales, contact
// sheet captions): digits, the signs of a number and a few letters.
#include <string_view>

#include "io/image.h"

namespace raycast {

/// Draws `text` with its top-left corner at (x, y), each font pixel a `scale` x `scale` square
/// of `color`; characters without a glyph are spaces. Pixels outside the image are skipped.
void draw_text(Image& image, int x, int y, std::string_view text, int scale, const Vec3f& color);

/// The width in image pixels of draw_text's text (4 font pixels a character, less the last gap).
inline int text_width(std::string_view text, int scale) {
  return text.empty() ? 0 : (4 * int(text.size()) - 1) * scale;
}

}  // namespace raycast
