// Portable float map: a text header "PF\n<w> <h>\n<scale>\n" (a negative scale means
// little-endian), then float32 RGB triples, bottom row first.
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/image.h"

namespace raycast {

namespace {

std::uint32_t byte_swap(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

}  // namespace

void save_pfm(const Image& image, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw ImageError(path + ": cannot open for writing");
  out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
  std::vector<float> row(std::size_t(3) * std::size_t(image.width));
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      const Vec3f c = image.at(x, y);
      row[3 * std::size_t(x)] = c.x;
      row[3 * std::size_t(x) + 1] = c.y;
      row[3 * std::size_t(x) + 2] = c.z;
    }
    if constexpr (std::endian::native == std::endian::big)
      for (float& f : row) f = std::bit_cast<float>(byte_swap(std::bit_cast<std::uint32_t>(f)));
    out.write(reinterpret_cast<const char*>(row.data()),
              std::streamsize(row.size() * sizeof(float)));
  }
  if (!out) throw ImageError(path + ": write failed");
}

Image load_pfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageError(path + ": cannot open");
  std::string magic;
  long long w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  if (!in || (magic != "PF" && magic != "Pf") || w <= 0 || h <= 0 || w > (1 << 16) ||
      h > (1 << 16) || scale == 0)
    throw ImageError(path + ": not a PFM file (bad header)");
  in.get();  // the single whitespace character after the scale
  const int channels = magic == "PF" ? 3 : 1;
  const bool swap = (scale < 0) != (std::endian::native == std::endian::little);
  Image image(static_cast<int>(w), static_cast<int>(h));
  std::vector<float> row(std::size_t(channels) * std::size_t(w));
  for (long long y = h - 1; y >= 0; --y) {
    in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    if (!in) throw ImageError(path + ": truncated PFM data");
    if (swap)
      for (float& f : row) f = std::bit_cast<float>(byte_swap(std::bit_cast<std::uint32_t>(f)));
    for (long long x = 0; x < w; ++x) {
      const float* p = &row[std::size_t(channels) * std::size_t(x)];
      image.set(int(x), int(y), channels == 3 ? Vec3f{p[0], p[1], p[2]} : Vec3f{p[0], p[0], p[0]});
    }
  }
  return image;
}

}  // namespace raycast
