#pragma once
// Images in linear light: float RGB, row-major from the top-left pixel, and the files they go to.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/vec3.h"

namespace raycast {

/// A width x height image of linear RGB floats; pixel (0, 0) is the top-left one.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // 3 * width * height values, row-major, top row first

  Image() = default;
  /// A black image; width and height must be >= 0.
  Image(int w, int h)
      : width(w), height(h), rgb(std::size_t(3) * std::size_t(w) * std::size_t(h), 0.f) {}

  Vec3f at(int x, int y) const {
    const std::size_t i = index(x, y);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  void set(int x, int y, const Vec3f& c) {
    const std::size_t i = index(x, y);
    rgb[i] = c.x;
    rgb[i + 1] = c.y;
    rgb[i + 2] = c.z;
  }

 private:
  std::size_t index(int x, int y) const {
    return 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  }
};

/// Anything that goes wrong reading or writing an image file: an unknown extension, a file that
/// cannot be opened, a corrupt file, a format this build lacks. The message names the file.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The sRGB transfer function (IEC 61966-2-1) and its inverse, on [0, 1].
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);
/// The tables behind linear_to_srgb8 (built once, in image.cpp).
struct Srgb8Table {
  static constexpr int kShift = 15;                   // buckets of 2^15 consecutive floats
  static constexpr std::uint32_t kOne = 0x3f800000u;  // the bits of 1.f
  float thresholds[255];
  std::uint8_t bucket_code[kOne >> kShift];  // the code of each bucket's first float
  Srgb8Table();
};
extern const Srgb8Table kSrgb8;
/// The 8-bit sRGB code of a linear value: exactly lround(255 * linear_to_srgb(linear)) (NaN and
/// values <= 0 give 0, values >= 1 give 255), from tables of the 255 smallest floats reaching
/// each code and of the code of every 2^15th float (built once from linear_to_srgb itself).
/// Inline: the antialiasing pass encodes three values per pixel.
inline std::uint8_t linear_to_srgb8(float linear) {
  if (!(linear > 0.f)) return 0;  // also NaN
  if (linear >= 1.f) return 255;
  // The number of thresholds <= linear: start from the bucket's first float (a bucket spans at
  // most a code or two), then step over the thresholds inside the bucket.
  int n = kSrgb8.bucket_code[std::bit_cast<std::uint32_t>(linear) >> Srgb8Table::kShift];
  while (n < 255 && kSrgb8.thresholds[n] <= linear) ++n;
  return static_cast<std::uint8_t>(n);
}

/// 8-bit sRGB PNG: each value clamped to [0, 1], sRGB-encoded, rounded to the nearest of 0..255.
void save_png(const Image& image, const std::string& path);
/// The same PNG to an open stream (standard output for `-o -`); `name` is used in messages. The
/// stream is neither flushed nor closed.
void write_png(const Image& image, std::FILE* file, const std::string& name);
/// Reads an 8- or 16-bit PNG (grey, grey+alpha, RGB, RGBA, palette) into linear RGB: the sRGB
/// encoding is undone, alpha is dropped. Throws ImageError.
Image load_png(const std::string& path);
/// A PNG's pixels as stored, for image maps that need more than the colour: RGBA with the sRGB
/// encoding kept (values in [0, 1]; a file's own gAMA is converted to sRGB), top row first, and
/// for palette images each pixel's palette index. Throws ImageError.
struct PngPixels {
  int width = 0, height = 0;
  std::vector<float> rgba;          // 4 * width * height
  std::vector<std::uint8_t> index;  // palette images: width * height, else empty
  int palette_size = 0;
};
PngPixels load_png_pixels(const std::string& path);
/// Portable float map ("PF", 3 channels, little-endian, bottom row first as the format demands),
/// linear values written as they are.
void save_pfm(const Image& image, const std::string& path);
/// Reads a colour ("PF") or grey ("Pf") PFM of either endianness. Throws ImageError.
Image load_pfm(const std::string& path);
/// OpenEXR, 32-bit float RGB channels, linear, ZIP-compressed. Throws ImageError when this build
/// has no OpenEXR.
void save_exr(const Image& image, const std::string& path);
/// Whether this build can write OpenEXR files.
bool have_exr();

/// An image texture in linear RGB (PNG files are decoded from sRGB).
struct ImageTexture {
  Image image;
};

/// Loads an image texture from a .png or .pfm file; throws ImageError (missing, unreadable,
/// malformed, or another format).
std::shared_ptr<const ImageTexture> load_image_texture(const std::string& path);

/// The formats save_image knows, by lower-case extension.
enum class ImageFormat { kPng, kPfm, kExr };
/// The format for a path from its extension (case-insensitive); throws ImageError for any other
/// extension, or for .exr when this build lacks OpenEXR.
ImageFormat image_format_for(const std::string& path);
/// Writes the image in the format its extension names (.png, .pfm, .exr). Throws ImageError.
void save_image(const Image& image, const std::string& path);

}  // namespace raycast
