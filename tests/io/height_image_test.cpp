// The height-field image readers: each format's samples become POV-Ray 3.7's 16-bit heights,
// rows as the file shows them (top first), and unsupported or broken files are ImageErrors.
#include "io/height_image.h"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/image.h"

namespace raycast {
namespace {

std::string temp_file(const std::string& name, const std::string& bytes) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("raycast_height_image_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

HeightImage read(const std::string& path) {
  return read_height_image(path, height_image_format("", path));
}

TEST(HeightImage, PlainAndRawPgmScaleGreyTo65535) {
  const HeightImage a = read(temp_file("a.pgm", "P2\n# comment\n3 2\n255\n0 1 2\n255 128 7\n"));
  ASSERT_EQ(a.width, 3);
  ASSERT_EQ(a.height, 2);
  EXPECT_EQ(a.at(0, 0), 0);
  EXPECT_EQ(a.at(1, 0), 257);
  EXPECT_EQ(a.at(0, 1), 65535);
  EXPECT_EQ(a.at(1, 1), 128 * 257);
  const std::string raw16 = std::string("P5 2 1 65535\n") + '\x12' + '\x34' + '\xff' + '\xfe';
  const HeightImage b = read(temp_file("b.pgm", raw16));
  EXPECT_EQ(b.at(0, 0), 0x1234);
  EXPECT_EQ(b.at(1, 0), 0xfffe);
}

TEST(HeightImage, EightBitColourIsRedHighGreenLow) {
  const std::string raw =
      std::string("P6 2 1 255\n") + '\x02' + '\x05' + '\x63' + '\xff' + '\x00' + '\x00';
  const HeightImage a = read(temp_file("c.ppm", raw));
  EXPECT_EQ(a.at(0, 0), 255 * 2 + 5);
  EXPECT_EQ(a.at(1, 0), 255 * 255);
  // More than 8 bits a channel: the grey 0.297 r + 0.589 g + 0.114 b.
  const HeightImage b = read(temp_file("d.ppm", "P3 1 1 65535\n65535 0 0\n"));
  EXPECT_EQ(b.at(0, 0), static_cast<std::uint16_t>(0.297 * 65535));
}

TEST(HeightImage, TgaRowsFollowTheOriginBit) {
  // Uncompressed grey (type 3), 1 x 2, bottom row first (descriptor 0): the file's first pixel is
  // the image's bottom row.
  std::string h(18, '\0');
  h[2] = 3;
  h[12] = 1;
  h[14] = 2;
  h[16] = 8;
  const HeightImage a = read(temp_file("e.tga", h + '\x0a' + '\x14'));
  EXPECT_EQ(a.at(0, 1), 10 * 257);
  EXPECT_EQ(a.at(0, 0), 20 * 257);
  // Run-length colour-mapped (type 9), top row first: a run of two index-3 pixels.
  std::string m(18, '\0');
  m[1] = 1;
  m[2] = 9;
  m[5] = 4;  // four map entries of 24 bits
  m[7] = 24;
  m[12] = 2;
  m[14] = 1;
  m[16] = 8;
  m[17] = 0x20;
  const HeightImage b = read(temp_file("f.tga", m + std::string(12, '\x01') + '\x81' + '\x03'));
  EXPECT_EQ(b.at(0, 0), 3 * 256);
  EXPECT_EQ(b.at(1, 0), 3 * 256);
}

TEST(HeightImage, PngGreyAndPaletteFollowPovRay) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string grey =
      (dir / ("raycast_hf_grey_" + std::to_string(::getpid()) + ".png")).string();
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  img.width = 2;
  img.height = 1;
  img.format = PNG_FORMAT_GRAY;
  const unsigned char px[2] = {3, 200};
  ASSERT_TRUE(png_image_write_to_file(&img, grey.c_str(), 0, px, 0, nullptr));
  const HeightImage a = read(grey);
  EXPECT_EQ(a.at(0, 0), 3 * 257);
  EXPECT_EQ(a.at(1, 0), 200 * 257);
  std::filesystem::remove(grey);
  // A palette image: its indices times 256, whatever the palette's colours.
  const std::string pal =
      (dir / ("raycast_hf_pal_" + std::to_string(::getpid()) + ".png")).string();
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  img.width = 3;
  img.height = 1;
  img.format = PNG_FORMAT_RGB_COLORMAP;
  img.colormap_entries = 3;
  const unsigned char map[9] = {255, 255, 255, 0, 0, 0, 10, 20, 30};
  const unsigned char idx[3] = {0, 1, 2};
  ASSERT_TRUE(png_image_write_to_file(&img, pal.c_str(), 0, idx, 0, map));
  const HeightImage b = read(pal);
  EXPECT_EQ(b.at(0, 0), 0);
  EXPECT_EQ(b.at(1, 0), 256);
  EXPECT_EQ(b.at(2, 0), 512);
  std::filesystem::remove(pal);
}

TEST(HeightImage, UnsupportedAndBrokenFilesAreErrors) {
  EXPECT_THROW(height_image_format("gif", "x.gif"), ImageError);
  EXPECT_THROW(height_image_format("", "x.jpg"), ImageError);
  EXPECT_EQ(height_image_format("", "X.PNG"), HeightImageFormat::kPng);
  EXPECT_THROW(read(temp_file("g.pgm", "P5 2 2 255\n\x01")), ImageError);      // truncated
  EXPECT_THROW(read(temp_file("h.pgm", "P2 0 2 255\n")), ImageError);          // empty
  EXPECT_THROW(read(temp_file("i.pgm", "P2 99999 99999 255\n")), ImageError);  // too large
  EXPECT_THROW(read(temp_file("j.png", "not a png")), ImageError);
  EXPECT_THROW(read_height_image("/no/such/file.png", HeightImageFormat::kPng), ImageError);
}

}  // namespace
}  // namespace raycast
