#include "io/image_diff.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace raycast {

namespace {

// The image's channels as 8-bit sRGB codes, row-major as in Image::rgb.
std::vector<std::uint8_t> codes(const Image& image) {
  std::vector<std::uint8_t> out(image.rgb.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = linear_to_srgb8(image.rgb[i]);
  return out;
}

// The mean code of each channel over the pixels [x0, x1) x [y0, y1).
void block_means(const std::vector<std::uint8_t>& c, int width, int x0, int x1, int y0, int y1,
                 double mean[3]) {
  long long sum[3] = {0, 0, 0};
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 3; ++k)
        sum[k] += c[3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)) + std::size_t(k)];
  const double n = double(x1 - x0) * double(y1 - y0);
  for (int k = 0; k < 3; ++k) mean[k] = double(sum[k]) / n;
}

}  // namespace

ImageDiff compare_images(const Image& a, const Image& b, int block) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("the images' sizes differ: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
  if (block < 1) throw std::invalid_argument("the block size must be >= 1");
  ImageDiff d;
  d.block = block;
  d.pixels = static_cast<long long>(a.width) * a.height;
  if (d.pixels == 0) return d;
  const std::vector<std::uint8_t> ca = codes(a), cb = codes(b);
  long long total = 0;
  for (std::size_t p = 0; p < ca.size(); p += 3) {
    bool differs = false;
    for (std::size_t k = 0; k < 3; ++k) {
      const int e = std::abs(int(ca[p + k]) - int(cb[p + k]));
      total += e;
      d.max = std::max(d.max, e);
      differs |= e != 0;
    }
    d.differing += differs;
  }
  d.mean = double(total) / double(ca.size());
  double block_total = 0;
  long long blocks = 0;
  for (int y0 = 0; y0 < a.height; y0 += block) {
    for (int x0 = 0; x0 < a.width; x0 += block) {
      const int x1 = std::min(a.width, x0 + block), y1 = std::min(a.height, y0 + block);
      double ma[3], mb[3];
      block_means(ca, a.width, x0, x1, y0, y1, ma);
      block_means(cb, a.width, x0, x1, y0, y1, mb);
      for (int k = 0; k < 3; ++k) block_total += std::abs(ma[k] - mb[k]);
      ++blocks;
    }
  }
  d.block_mean = block_total / (3.0 * double(blocks));
  return d;
}

Image difference_image(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("the images' sizes differ");
  const std::vector<std::uint8_t> ca = codes(a), cb = codes(b);
  Image out(a.width, a.height);
  for (std::size_t i = 0; i < ca.size(); ++i)
    out.rgb[i] = srgb_to_linear(float(std::abs(int(ca[i]) - int(cb[i]))) / 255.f);
  return out;
}

Image load_image(const std::string& path) {
  std::string ext = path.substr(
      path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".png") return load_png(path);
  if (ext == ".pfm") return load_pfm(path);
  throw ImageError(path + ": cannot read the image: the extension is not .png or .pfm");
}

}  // namespace raycast
