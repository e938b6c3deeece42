#include "load/text_shape.h"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/font_outline.h"

namespace raycast {

Text make_text_shape(const std::string& font_file, const std::string& text, double thickness,
                     const Vec3& offset, bool flip_z) {
  if (!(thickness != 0) || !std::isfinite(thickness))
    throw std::invalid_argument("the thickness must be finite and not 0");
  std::vector<Prism> letters;
  for (const LetterOutline& l : text_outline(font_file, text, offset.x, offset.y)) {
    if (l.contours.empty()) continue;
    double z0 = l.index * offset.z, z1 = z0 + thickness;
    if (flip_z) z0 = -z0, z1 = -z1;
    try {
      letters.push_back(make_prism(l.contours, z0, z1));
    } catch (const std::invalid_argument&) {
      // An outline without area (a font's blank glyph drawn as a line) draws nothing.
    }
  }
  return make_text(std::move(letters));
}

}  // namespace raycast
