#include "io/image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
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

}  // namespace raycast
