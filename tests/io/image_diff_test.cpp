// compare_images: the block mean, the plain mean and the max in 8-bit sRGB codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "io/image_diff.h"

namespace raycast {
namespace {

// A linear value whose 8-bit sRGB code is `code`.
float from_code(int code) { return srgb_to_linear(float(code) / 255.f); }

Image filled(int w, int h, int code) {
  Image im(w, h);
  for (float& v : im.rgb) v = from_code(code);
  return im;
}

TEST(ImageDiff, CodesRoundTrip_EveryCodeIsItself) {
  for (int c = 0; c < 256; ++c) EXPECT_EQ(linear_to_srgb8(from_code(c)), c) << c;
}

TEST(ImageDiff, EqualImages_AreZeroApart) {
  const ImageDiff d = compare_images(filled(5, 3, 100), filled(5, 3, 100), 4);
  EXPECT_EQ(d.block_mean, 0);
  EXPECT_EQ(d.mean, 0);
  EXPECT_EQ(d.max, 0);
  EXPECT_EQ(d.differing, 0);
  EXPECT_EQ(d.pixels, 15);
}

TEST(ImageDiff, OnePixelOff_PlainMeanMaxAndBlockMean) {
  // 8x4 image, blocks of 4: two blocks. One pixel's red is 64 codes higher: the plain mean is
  // 64 / (32 * 3), the block mean (64 / 16) / (2 blocks * 3 channels).
  Image a = filled(8, 4, 10), b = filled(8, 4, 10);
  b.set(1, 2, Vec3f{from_code(74), from_code(10), from_code(10)});
  const ImageDiff d = compare_images(a, b, 4);
  EXPECT_DOUBLE_EQ(d.mean, 64.0 / 96.0);
  EXPECT_DOUBLE_EQ(d.block_mean, 4.0 / 6.0);
  EXPECT_EQ(d.max, 64);
  EXPECT_EQ(d.differing, 1);
}

TEST(ImageDiff, APixelMovedInsideItsBlock_HasNoBlockDifference) {
  Image a = filled(4, 4, 0), b = filled(4, 4, 0);
  a.set(0, 0, Vec3f{1, 1, 1});
  b.set(1, 1, Vec3f{1, 1, 1});
  const ImageDiff d = compare_images(a, b, 4);
  EXPECT_EQ(d.block_mean, 0);
  EXPECT_EQ(d.max, 255);
  EXPECT_DOUBLE_EQ(d.mean, 2 * 255.0 * 3 / 48);
  // With blocks of one pixel the block mean is the plain mean.
  EXPECT_DOUBLE_EQ(compare_images(a, b, 1).block_mean, d.mean);
}

TEST(ImageDiff, PartialBlocksAtTheEdges_AreAveragedOverTheirOwnPixels) {
  // 5x1 with blocks of 4: blocks of 4 and 1 pixels. The last pixel is 30 codes apart.
  Image a = filled(5, 1, 0), b = filled(5, 1, 0);
  b.set(4, 0, Vec3f{from_code(30), from_code(30), from_code(30)});
  EXPECT_DOUBLE_EQ(compare_images(a, b, 4).block_mean, 15.0);
}

TEST(ImageDiff, DifferentSizes_AreRefused) {
  EXPECT_THROW(compare_images(filled(4, 4, 0), filled(4, 5, 0), 4), std::invalid_argument);
  EXPECT_THROW(compare_images(filled(4, 4, 0), filled(4, 4, 0), 0), std::invalid_argument);
}

TEST(ImageDiff, DifferenceImage_HoldsTheCodeDifference) {
  Image a = filled(2, 1, 200), b = filled(2, 1, 150);
  const Image d = difference_image(a, b);
  EXPECT_EQ(linear_to_srgb8(d.at(0, 0).x), 50);
  EXPECT_EQ(linear_to_srgb8(difference_image(a, a).at(1, 0).y), 0);
}

TEST(ImageDiff, LoadImage_ReadsPngAndPfmAndRefusesOthers) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string png = (dir / "raycast_image_diff.PNG").string();
  const std::string pfm = (dir / "raycast_image_diff.pfm").string();
  const Image a = filled(3, 2, 77);
  save_png(a, png);
  save_pfm(a, pfm);
  EXPECT_EQ(compare_images(load_image(png), a, 4).max, 0);
  EXPECT_EQ(compare_images(load_image(pfm), a, 4).max, 0);
  EXPECT_THROW(load_image((dir / "x.jpg").string()), ImageError);
  std::filesystem::remove(png);
  std::filesystem::remove(pfm);
}

}  // namespace
}  // namespace raycast
