// PNG through libpng's simplified API (libpng 1.6), which handles every colour type, bit depth and
// gamma chunk and reports errors through png_image::message instead of longjmp.
#include <png.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "io/image.h"

namespace raycast {

namespace {

std::uint8_t encode_8bit(float linear) {
  return static_cast<std::uint8_t>(std::lround(255.f * linear_to_srgb(linear)));
}

}  // namespace

void save_png(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0)
    throw ImageError(path + ": cannot write an empty image");
  std::vector<std::uint8_t> bytes(image.rgb.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = encode_8bit(image.rgb[i]);
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&png, path.c_str(), 0, bytes.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw ImageError(path + ": cannot write PNG: " + message);
  }
}

Image load_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw ImageError(path + ": cannot read PNG: " + png.message);
  png.format = PNG_FORMAT_RGB;
  if (png.width == 0 || png.height == 0 || png.width > (1u << 16) || png.height > (1u << 16)) {
    png_image_free(&png);
    throw ImageError(path + ": PNG size out of range");
  }
  std::vector<std::uint8_t> bytes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw ImageError(path + ": cannot read PNG: " + message);
  }
  float table[256];
  for (int i = 0; i < 256; ++i) table[i] = srgb_to_linear(static_cast<float>(i) / 255.f);
  Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  for (std::size_t i = 0; i < bytes.size(); ++i) image.rgb[i] = table[bytes[i]];
  return image;
}

}  // namespace raycast
