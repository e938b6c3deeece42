#include "render/glyphs.h"

namespace raycast {

namespace {

/// One glyph: five rows of three bits, the high bit the left column.
struct Glyph {
  char c;
  unsigned char rows[5];
};

constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
    {'+', {0, 2, 7, 2, 0}}, {'e', {0, 7, 7, 4, 7}}, {'=', {0, 7, 0, 7, 0}}, {'d', {1, 1, 7, 5, 7}},
    {'p', {7, 5, 7, 4, 4}}, {'t', {2, 7, 2, 2, 3}}, {'h', {4, 4, 7, 5, 5}}, {':', {0, 2, 0, 2, 0}},
};

const Glyph* glyph_of(char c) {
  for (const Glyph& g : kGlyphs)
    if (g.c == c) return &g;
  return nullptr;
}

}  // namespace

void draw_text(Image& image, int x, int y, std::string_view text, int scale, const Vec3f& color) {
  for (std::size_t k = 0; k < text.size(); ++k) {
    const Glyph* g = glyph_of(text[k]);
    if (!g) continue;
    const int left = x + int(k) * 4 * scale;
    for (int row = 0; row < 5; ++row)
      for (int col = 0; col < 3; ++col) {
        if (!(g->rows[row] >> (2 - col) & 1)) continue;
        for (int dy = 0; dy < scale; ++dy)
          for (int dx = 0; dx < scale; ++dx) {
            const int px = left + col * scale + dx, py = y + row * scale + dy;
            if (px >= 0 && py >= 0 && px < image.width && py < image.height)
              image.set(px, py, color);
          }
      }
  }
}

}  // namespace raycast
