#include "render/contact_sheet.h"

#include <algorithm>
#include <stdexcept>

#include "render/glyphs.h"

namespace raycast {

Image make_contact_sheet(const std::vector<Image>& images, const std::vector<std::string>& captions,
                         int gap) {
  if (images.empty() || captions.size() != images.size())
    throw std::invalid_argument("contact sheet: one caption per image, at least one image");
  const int w = images[0].width, h = images[0].height;
  for (const Image& image : images)
    if (image.width != w || image.height != h)
      throw std::invalid_argument("contact sheet: the images must have one size");
  const int scale = std::max(1, h / 80);
  const int caption_height = 7 * scale + gap;
  const int count = int(images.size());
  Image sheet(count * w + (count + 1) * gap, h + 2 * gap + caption_height);
  std::fill(sheet.rgb.begin(), sheet.rgb.end(), 1.f);
  for (int k = 0; k < count; ++k) {
    const int left = gap + k * (w + gap);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) sheet.set(left + x, gap + y, images[std::size_t(k)].at(x, y));
    const std::string& caption = captions[std::size_t(k)];
    draw_text(sheet, left + (w - text_width(caption, scale)) / 2, gap + h + gap, caption, scale,
              Vec3f{0, 0, 0});
  }
  return sheet;
}

}  // namespace raycast
