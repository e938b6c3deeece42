#pragma once
// Images read as heights, pixel by pixel as POV-Ray's height_field reads them: one 16-bit value
// per pixel from the file's own samples (no gamma, no colour conversion).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace raycast {

/// A width x height grid of heights in 0..65535, row-major, the file's top row first.
struct HeightImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> values;

  std::uint16_t at(int x, int y) const {
    return values[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
};

/// Files wider or taller than this, or of more pixels than kMaxHeightImagePixels, are an
/// ImageError (a height field makes two triangles per pixel).
inline constexpr int kMaxHeightImageSide = 16384;
inline constexpr std::size_t kMaxHeightImagePixels = std::size_t(1) << 22;

/// The formats read as heights.
enum class HeightImageFormat { kPng, kPgm, kPpm, kTga };

/// The format of POV-Ray's keyword (`png`, `pgm`, `ppm`, `tga`) or, for an empty keyword, of the
/// file's extension (case-insensitive; .png .pgm .ppm .tga). Throws ImageError naming the
/// formats raycast reads for any other (gif, jpeg, tiff, iff, sys, pot, bmp, exr, hdr).
HeightImageFormat height_image_format(const std::string& keyword, const std::string& path);

/// Reads the file. Heights follow POV-Ray 3.7: a palette image gives its index times 256; a grey
/// image its value scaled to 65535 (8 bits: v * 257); a colour image of more than 8 bits per
/// channel its grey 0.297 r + 0.589 g + 0.114 b scaled to 65535; an 8-bit colour image
/// 255 r + g (red the high part, green the low). Throws ImageError (unreadable, malformed, too
/// large).
HeightImage read_height_image(const std::string& path, HeightImageFormat format);

/// The value of a colour of more than 8 bits per channel (r, g, b in [0, 1]), and of an 8-bit
/// one (r, g, b in 0..255), as read_height_image gives them.
std::uint16_t height_of_deep_colour(double r, double g, double b);
std::uint16_t height_of_colour8(int r, int g);

}  // namespace raycast
