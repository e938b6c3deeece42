#include "serve/png_memory.h"

#include <png.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace raycast::serve {

std::string encode_png(const Image& image) {
  std::vector<std::uint8_t> codes(image.rgb.size());
  for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = linear_to_srgb8(image.rgb[i]);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // First call: the size; second: the bytes.
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, codes.data(), 0, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, codes.data(), 0, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
  bytes.resize(size);
  return bytes;
}

}  // namespace raycast::serve
