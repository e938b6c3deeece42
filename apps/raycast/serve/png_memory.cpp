#include "serve/png_memory.h"

#include <png.h>

#include <algorithm>
#include <cmath>
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

void normalize_depth(Image& image) {
  std::vector<float> finite;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    if (std::isfinite(image.rgb[i])) finite.push_back(image.rgb[i]);
  float scale = 0;
  if (!finite.empty()) {
    auto middle = finite.begin() + std::ptrdiff_t(finite.size() / 2);
    std::nth_element(finite.begin(), middle, finite.end());
    scale = 2 * *middle;
  }
  for (float& d : image.rgb)
    d = std::isfinite(d) ? (scale > 0 ? std::min(1.f, d / scale) : 0.f) : 1.f;
}

}  // namespace raycast::serve
