#include "io/image.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>

namespace raycast {

float linear_to_srgb(float linear) {
  if (!(linear > 0.f)) return 0.f;  // also maps NaN to 0
  if (linear >= 1.f) return 1.f;
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.f / 2.4f) - 0.055f;
}

float srgb_to_linear(float encoded) {
  if (!(encoded > 0.f)) return 0.f;
  if (encoded >= 1.f) return 1.f;
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

namespace {

std::uint8_t reference_srgb8(float linear) {
  return static_cast<std::uint8_t>(std::lround(255.f * linear_to_srgb(linear)));
}

}  // namespace

// thresholds[k - 1] = the smallest non-negative float whose code is >= k (k = 1..255). The code is
// non-decreasing in the value (linear_to_srgb is, and so is rounding), and the order of
// non-negative floats is the order of their bit patterns, so each threshold is a binary search
// over bit patterns.
Srgb8Table::Srgb8Table() {
  for (int k = 1; k <= 255; ++k) {
    std::uint32_t lo = 0, hi = kOne;  // code(lo) < k <= code(hi)
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (reference_srgb8(std::bit_cast<float>(mid)) >= k)
        hi = mid;
      else
        lo = mid;
    }
    thresholds[k - 1] = std::bit_cast<float>(hi);
  }
  int n = 0;
  for (std::uint32_t b = 0; b < (kOne >> kShift); ++b) {
    const float first = std::bit_cast<float>(b << kShift);
    while (n < 255 && thresholds[n] <= first) ++n;
    bucket_code[b] = static_cast<std::uint8_t>(n);
  }
}

const Srgb8Table kSrgb8;

ImageFormat image_format_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".png") return ImageFormat::kPng;
  if (ext == ".pfm") return ImageFormat::kPfm;
  if (ext == ".exr") {
    if (!have_exr())
      throw ImageError(path + ": this build has no OpenEXR support; write .png or .pfm");
    return ImageFormat::kExr;
  }
  throw ImageError(path + ": unknown image extension '" + ext + "'; expected .png, .pfm or .exr");
}

void save_image(const Image& image, const std::string& path) {
  switch (image_format_for(path)) {
    case ImageFormat::kPng:
      return save_png(image, path);
    case ImageFormat::kPfm:
      return save_pfm(image, path);
    case ImageFormat::kExr:
      return save_exr(image, path);
  }
}

std::shared_ptr<const ImageTexture> load_image_texture(const std::string& path) {
  auto texture = std::make_shared<ImageTexture>();
  const std::string ext = std::filesystem::path(path).extension().string();
  std::string lower;
  for (const char c : ext) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == ".png")
    texture->image = load_png(path);
  else if (lower == ".pfm")
    texture->image = load_pfm(path);
  else
    throw ImageError(path + ": image textures must be .png or .pfm, got '" + ext + "'");
  return texture;
}

}  // namespace raycast
