#include "io/height_image.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>

#include "io/image.h"

namespace raycast {

namespace {

std::string hf_lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void hf_check_size(const std::string& path, long w, long h) {
  if (w < 1 || h < 1 || w > kMaxHeightImageSide || h > kMaxHeightImageSide ||
      std::size_t(w) * std::size_t(h) > kMaxHeightImagePixels)
    throw ImageError(path + ": image size " + std::to_string(w) + " x " + std::to_string(h) +
                     " out of range for a height field (each side 1 to " +
                     std::to_string(kMaxHeightImageSide) + ", at most " +
                     std::to_string(kMaxHeightImagePixels) + " pixels)");
}

std::uint16_t hf_grey(unsigned v, unsigned maxval) {
  return static_cast<std::uint16_t>(std::uint64_t(v) * 65535u / maxval);
}

// What libpng's longjmp may leave: state held in memory, not in locals of the setjmp frame.
struct HfPngRead {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::vector<png_byte> bytes;
  std::vector<png_bytep> rows;
  png_uint_32 w = 0, h = 0;
  int depth = 0, type = 0;
  bool done = false;
  std::string message;
  ~HfPngRead() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (file) std::fclose(file);
  }
};

void on_hf_png_warning(png_structp, png_const_charp) {}
[[noreturn]] void on_hf_png_error(png_structp png, png_const_charp message) {
  static_cast<HfPngRead*>(png_get_error_ptr(png))->message = message;
  png_longjmp(png, 1);
}

// libpng reports errors by longjmp: everything after the setjmp lives in *s, none of it in locals
// of this frame.
bool hf_png_read(HfPngRead* s) {
  if (setjmp(png_jmpbuf(s->png))) return false;
  png_init_io(s->png, s->file);
  png_read_info(s->png, s->info);
  png_get_IHDR(s->png, s->info, &s->w, &s->h, &s->depth, &s->type, nullptr, nullptr, nullptr);
  if (s->w < 1 || s->h < 1 || s->w > png_uint_32(kMaxHeightImageSide) ||
      s->h > png_uint_32(kMaxHeightImageSide) || std::size_t(s->w) * s->h > kMaxHeightImagePixels)
    return true;  // the caller reports the size
  // One sample per byte below 8 bits (palette indices as they are, greys scaled to 0..255: the
  // same fraction of the maximum), alpha dropped, 16-bit samples kept big-endian.
  if (s->depth < 8) {
    if (s->type == PNG_COLOR_TYPE_GRAY) png_set_expand_gray_1_2_4_to_8(s->png);
    png_set_packing(s->png);
  }
  if (s->type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(s->png);
  png_read_update_info(s->png, s->info);
  const std::size_t stride = png_get_rowbytes(s->png, s->info);
  s->bytes.resize(stride * s->h);
  s->rows.resize(s->h);
  for (png_uint_32 y = 0; y < s->h; ++y) s->rows[y] = s->bytes.data() + y * stride;
  png_read_image(s->png, s->rows.data());
  s->done = true;
  return true;
}

HeightImage read_png_heights(const std::string& path) {
  auto r = std::make_unique<HfPngRead>();
  r->file = std::fopen(path.c_str(), "rb");
  if (!r->file) throw ImageError(path + ": cannot open the height field's image");
  r->png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, r.get(), on_hf_png_error, on_hf_png_warning);
  if (r->png) r->info = png_create_info_struct(r->png);
  if (!r->png || !r->info) throw ImageError(path + ": cannot read PNG: out of memory");
  if (!hf_png_read(r.get())) throw ImageError(path + ": cannot read PNG: " + r->message);
  const png_uint_32 w = r->w, h = r->h;
  hf_check_size(path, long(w), long(h));
  if (!r->done) throw ImageError(path + ": cannot read PNG: corrupt file");
  const int type = r->type;
  HeightImage img{int(w), int(h), std::vector<std::uint16_t>(std::size_t(w) * h)};
  const bool wide = r->depth == 16;
  const int channels = type == PNG_COLOR_TYPE_PALETTE || !(type & PNG_COLOR_MASK_COLOR) ? 1 : 3;
  for (png_uint_32 y = 0; y < h; ++y)
    for (png_uint_32 x = 0; x < w; ++x) {
      const png_byte* p = r->rows[y] + std::size_t(x) * std::size_t(channels) * (wide ? 2 : 1);
      auto sample = [&](int c) -> unsigned {
        return wide ? (unsigned(p[2 * c]) << 8 | p[2 * c + 1]) : p[c];
      };
      std::uint16_t v;
      if (type == PNG_COLOR_TYPE_PALETTE)
        v = static_cast<std::uint16_t>(sample(0) * 256u);
      else if (channels == 1)
        v = hf_grey(sample(0), wide ? 65535u : 255u);
      else if (wide)
        v = height_of_deep_colour(sample(0) / 65535.0, sample(1) / 65535.0, sample(2) / 65535.0);
      else
        v = height_of_colour8(int(sample(0)), int(sample(1)));
      img.values[std::size_t(y) * w + x] = v;
    }
  return img;
}

std::vector<unsigned char> hf_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageError(path + ": cannot open the height field's image");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Netpbm: P2/P5 (grey) and P3/P6 (colour), plain or raw, maxval up to 65535.
HeightImage read_pnm_heights(const std::string& path, bool colour) {
  const std::vector<unsigned char> b = hf_file_bytes(path);
  std::size_t at = 0;
  auto fail = [&](const std::string& m) -> ImageError {
    return ImageError(path + ": cannot read " + (colour ? "PPM" : "PGM") + ": " + m);
  };
  auto skip_space = [&] {
    while (at < b.size()) {
      if (b[at] == '#')
        while (at < b.size() && b[at] != '\n') ++at;
      else if (std::isspace(b[at]))
        ++at;
      else
        break;
    }
  };
  auto number = [&]() -> long {
    skip_space();
    long v = 0;
    std::size_t digits = 0;
    while (at < b.size() && std::isdigit(b[at]) && digits < 9)
      v = v * 10 + (b[at++] - '0'), ++digits;
    if (digits == 0) throw fail("expected a number at byte " + std::to_string(at));
    return v;
  };
  if (b.size() < 2 || b[0] != 'P') throw fail("not a Netpbm file");
  const char kind = static_cast<char>(b[1]);
  const bool raw = kind == '5' || kind == '6';
  if ((colour && kind != '3' && kind != '6') || (!colour && kind != '2' && kind != '5'))
    throw fail(std::string("unexpected magic number P") + kind);
  at = 2;
  const long w = number(), h = number(), maxval = number();
  hf_check_size(path, w, h);
  if (maxval < 1 || maxval > 65535) throw fail("maxval must be in [1, 65535]");
  ++at;  // the one whitespace byte before raw samples
  const int channels = colour ? 3 : 1;
  const std::size_t count = std::size_t(w) * std::size_t(h) * std::size_t(channels);
  const int bytes_per = maxval > 255 ? 2 : 1;
  if (raw && b.size() < at + count * std::size_t(bytes_per)) throw fail("the file is truncated");
  std::vector<unsigned> samples(count);
  for (std::size_t i = 0; i < count; ++i) {
    unsigned v;
    if (raw)
      v = bytes_per == 2 ? (unsigned(b[at + 2 * i]) << 8 | b[at + 2 * i + 1]) : b[at + i];
    else
      v = unsigned(number());
    if (v > unsigned(maxval)) throw fail("a sample exceeds maxval");
    samples[i] = v;
  }
  HeightImage img{int(w), int(h), std::vector<std::uint16_t>(std::size_t(w) * std::size_t(h))};
  const double m = double(maxval);
  for (std::size_t i = 0; i < img.values.size(); ++i) {
    if (!colour)
      img.values[i] = hf_grey(samples[i], unsigned(maxval));
    else if (maxval > 255)
      img.values[i] =
          height_of_deep_colour(samples[3 * i] / m, samples[3 * i + 1] / m, samples[3 * i + 2] / m);
    else  // POV-Ray's 8-bit rule on the samples as fractions of maxval
      img.values[i] = static_cast<std::uint16_t>(
          std::min(65535.0, std::floor((samples[3 * i] / m * 255 + samples[3 * i + 1] / m) * 255)));
  }
  return img;
}

// Truevision TGA: colour-mapped (1, 9), true colour (2, 10) and grey (3, 11), run-length or not.
HeightImage read_tga_heights(const std::string& path) {
  const std::vector<unsigned char> b = hf_file_bytes(path);
  auto fail = [&](const std::string& m) { return ImageError(path + ": cannot read TGA: " + m); };
  if (b.size() < 18) throw fail("the file is truncated");
  const int id_len = b[0], map_type = b[1], type = b[2];
  const int map_len = b[5] | b[6] << 8, map_bits = b[7];
  const int w = b[12] | b[13] << 8, h = b[14] | b[15] << 8, bits = b[16], desc = b[17];
  hf_check_size(path, w, h);
  const int base = type & 7;
  if (base != 1 && base != 2 && base != 3) throw fail("image type " + std::to_string(type));
  const bool rle = type & 8;
  const int bpp = (bits + 7) / 8;
  if ((base == 1 && bits != 8) || (base == 3 && bits != 8) ||
      (base == 2 && bits != 15 && bits != 16 && bits != 24 && bits != 32))
    throw fail(std::to_string(bits) + " bits per pixel in image type " + std::to_string(type));
  std::size_t at =
      18 + std::size_t(id_len) + (map_type ? std::size_t(map_len) * ((map_bits + 7) / 8) : 0);
  const std::size_t n = std::size_t(w) * std::size_t(h);
  std::vector<unsigned char> px(n * std::size_t(bpp));
  for (std::size_t i = 0; i < n;) {  // every step writes at least one pixel: at most n steps
    std::size_t run = 1;
    bool repeat = false;
    if (rle) {
      if (at >= b.size()) throw fail("the file is truncated");
      repeat = b[at] & 0x80;
      run = (b[at] & 0x7f) + 1u;
      ++at;
    }
    if (i + run > n) throw fail("a run passes the end of the image");
    for (std::size_t k = 0; k < run; ++k, ++i) {
      const std::size_t src = repeat ? at : at + k * std::size_t(bpp);
      if (src + std::size_t(bpp) > b.size()) throw fail("the file is truncated");
      std::copy_n(b.begin() + std::ptrdiff_t(src), bpp, px.begin() + std::ptrdiff_t(i) * bpp);
    }
    at += (repeat ? 1 : run) * std::size_t(bpp);
  }
  HeightImage img{w, h, std::vector<std::uint16_t>(n)};
  const bool top_first = desc & 0x20;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p =
          &px[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * std::size_t(bpp)];
      std::uint16_t v;
      if (base == 1) {
        v = static_cast<std::uint16_t>(p[0] * 256u);
      } else if (base == 3) {
        v = hf_grey(p[0], 255);
      } else if (bpp == 2) {  // 5 bits per channel: x rrrrr ggggg bbbbb, little-endian
        const unsigned c = p[0] | unsigned(p[1]) << 8;
        v = static_cast<std::uint16_t>(
            std::floor(((c >> 10 & 31) / 31.0 * 255 + (c >> 5 & 31) / 31.0) * 255));
      } else {  // b, g, r(, a)
        v = height_of_colour8(p[2], p[1]);
      }
      const int row = top_first ? y : h - 1 - y;
      img.values[std::size_t(row) * std::size_t(w) + std::size_t(x)] = v;
    }
  return img;
}

}  // namespace

std::uint16_t height_of_deep_colour(double r, double g, double b) {
  const double grey = 0.297 * r + 0.589 * g + 0.114 * b;
  return static_cast<std::uint16_t>(std::clamp(grey * 65535.0, 0.0, 65535.0));
}

std::uint16_t height_of_colour8(int r, int g) { return static_cast<std::uint16_t>(255 * r + g); }

HeightImageFormat height_image_format(const std::string& keyword, const std::string& path) {
  std::string k = hf_lower(keyword);
  if (k.empty()) {
    const std::size_t dot = path.find_last_of('.');
    k = dot == std::string::npos ? "" : hf_lower(path.substr(dot + 1));
    if (k == "jpg") k = "jpeg";
  }
  if (k == "png") return HeightImageFormat::kPng;
  if (k == "pgm") return HeightImageFormat::kPgm;
  if (k == "ppm") return HeightImageFormat::kPpm;
  if (k == "tga") return HeightImageFormat::kTga;
  throw ImageError(path + ": raycast reads height fields from png, pgm, ppm and tga images, not " +
                   (k.empty() ? std::string("a file without an extension") : k));
}

HeightImage read_height_image(const std::string& path, HeightImageFormat format) {
  switch (format) {
    case HeightImageFormat::kPng:
      return read_png_heights(path);
    case HeightImageFormat::kPgm:
      return read_pnm_heights(path, false);
    case HeightImageFormat::kPpm:
      return read_pnm_heights(path, true);
    case HeightImageFormat::kTga:
      break;
  }
  return read_tga_heights(path);
}

}  // namespace raycast
