#pragma once
// How far apart two images are, in the 8-bit sRGB codes a viewer sees: `raycast compare`
// (docs/cli.md) and the POV-Ray corpus's closeness figures (bench/pov-corpus/run.py).
#include <string>

#include "io/image.h"

namespace raycast {

/// The differences of two equal-sized images, over every pixel's three channels as 8-bit sRGB
/// codes (0..255).
struct ImageDiff {
  int block = 4;            // the side of the blocks averaged before block_mean
  double block_mean = 0;    // mean |a - b| of the blocks' mean codes (blocks cut at the edges)
  double mean = 0;          // mean |a - b| over every pixel and channel
  int max = 0;              // largest |a - b| of one channel of one pixel
  long long pixels = 0;     // width * height
  long long differing = 0;  // pixels with any channel's codes apart
};

/// Compares a and b (the same width and height: else std::invalid_argument) with blocks of
/// block x block pixels (block >= 1). A block mean forgives what moves by a pixel or two (edges,
/// sampling) and keeps what changes a region's colour (light, shading, a missing object).
ImageDiff compare_images(const Image& a, const Image& b, int block);

/// The per-pixel difference: each channel is |a - b| of the codes, stored so that save_png writes
/// that very code (black where equal).
Image difference_image(const Image& a, const Image& b);

/// Reads a PNG or PFM image by its extension (any case). Throws ImageError.
Image load_image(const std::string& path);

}  // namespace raycast
