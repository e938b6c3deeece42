#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "io/image.h"

namespace raycast {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("raycast_io_test_" + name)).string();
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Srgb, KnownValues_MatchTheStandard) {
  EXPECT_FLOAT_EQ(linear_to_srgb(0.f), 0.f);
  EXPECT_FLOAT_EQ(linear_to_srgb(1.f), 1.f);
  EXPECT_NEAR(linear_to_srgb(0.5f), 0.735357f, 1e-5f);
  EXPECT_NEAR(linear_to_srgb(0.0031308f), 0.04045f, 1e-5f);
  EXPECT_NEAR(srgb_to_linear(0.735357f), 0.5f, 1e-5f);
  for (int i = 0; i <= 255; ++i) {
    const float e = float(i) / 255.f;
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(e)), e, 1e-5f) << i;
  }
}

TEST(Srgb, OutOfRangeAndNaN_AreClamped) {
  EXPECT_EQ(linear_to_srgb(-1.f), 0.f);
  EXPECT_EQ(linear_to_srgb(7.f), 1.f);
  EXPECT_EQ(linear_to_srgb(std::numeric_limits<float>::infinity()), 1.f);
  EXPECT_EQ(linear_to_srgb(std::nanf("")), 0.f);
}

std::uint8_t reference_srgb8(float v) {
  return static_cast<std::uint8_t>(std::lround(255.f * linear_to_srgb(v)));
}

TEST(Srgb8, EveryFloatNearEachCodeBoundaryAndSampled_MatchesTheDirectFormula) {
  // Around each boundary the table finds (where the direct formula's code changes), 64 floats each
  // side; then every 1021st float of [0, 1]; then the special values.
  for (std::uint32_t bits = 0; bits <= 0x3f800000u + 64; bits += 1021) {
    const float v = std::bit_cast<float>(bits);
    ASSERT_EQ(linear_to_srgb8(v), reference_srgb8(v)) << v;
  }
  int boundaries = 0;
  for (std::uint32_t bits = 1; bits <= 0x3f800000u; bits += 4093) {
    const float a = std::bit_cast<float>(bits - 1), b = std::bit_cast<float>(bits + 4092);
    if (reference_srgb8(a) == reference_srgb8(b)) continue;
    for (std::uint32_t k = bits - 1; k <= bits + 4092; ++k) {
      const float v = std::bit_cast<float>(k);
      ASSERT_EQ(linear_to_srgb8(v), reference_srgb8(v)) << v;
    }
    ++boundaries;
  }
  EXPECT_GE(boundaries, 200);  // most of the 255 boundaries were looked at
  for (const float v : {0.f, -0.f, -1.f, 1.f, 2.f, std::numeric_limits<float>::infinity(),
                        -std::numeric_limits<float>::infinity(), std::nanf(""),
                        std::numeric_limits<float>::denorm_min(), 0.0031308f, 0.5f})
    EXPECT_EQ(linear_to_srgb8(v), reference_srgb8(v)) << v;
}

TEST(Png, WriteThenRead_RoundTripsWithin8BitQuantisation) {
  Image image(7, 5);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      image.set(x, y, {float(x) / 6.f, float(y) / 4.f, float(x * y) / 24.f});
  const std::string path = temp_path("roundtrip.png");
  save_png(image, path);
  const Image back = load_png(path);
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const float written = image.at(x, y)[c];
        const float expected = srgb_to_linear(std::round(255.f * linear_to_srgb(written)) / 255.f);
        EXPECT_NEAR(back.at(x, y)[c], expected, 1e-6f) << x << ' ' << y << ' ' << c;
      }
    }
  }
  std::filesystem::remove(path);
}

TEST(Png, ValuesOutsideUnitRange_AreClampedWhenWritten) {
  Image image(2, 1);
  image.set(0, 0, {-3.f, 2.f, std::nanf("")});
  image.set(1, 0, {1.f, 0.f, 1e9f});
  const std::string path = temp_path("clamp.png");
  save_png(image, path);
  const Image back = load_png(path);
  EXPECT_EQ(back.at(0, 0), (Vec3f{0.f, 1.f, 0.f}));
  EXPECT_EQ(back.at(1, 0), (Vec3f{1.f, 0.f, 1.f}));
  std::filesystem::remove(path);
}

TEST(Png, UnwritablePath_ThrowsImageError) {
  const Image image(2, 2);
  EXPECT_THROW(save_png(image, temp_path("no_such_dir/x.png")), ImageError);
}

TEST(Png, WrittenFile_HasSignatureIhdrSrgbAndIend) {
  Image image(3, 2);
  image.set(2, 1, {0.25f, 0.5f, 0.75f});
  const std::string path = temp_path("chunks.png");
  save_png(image, path);
  const std::string bytes = read_bytes(path);
  ASSERT_GE(bytes.size(), 8u + 25u + 13u + 12u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(bytes.substr(8 + 25 + 4, 4), "sRGB");
  EXPECT_EQ(bytes.substr(bytes.size() - 8, 4), "IEND");
  std::filesystem::remove(path);
}

TEST(Png, MissingOrCorruptFile_ThrowsImageError) {
  EXPECT_THROW(load_png(temp_path("does_not_exist.png")), ImageError);
  const std::string path = temp_path("corrupt.png");
  std::ofstream(path) << "not a png at all";
  EXPECT_THROW(load_png(path), ImageError);
  std::filesystem::remove(path);
}

TEST(Pfm, Contents_HeaderThenLittleEndianFloatsBottomRowFirst) {
  Image image(2, 2);
  image.set(0, 0, {1.f, 2.f, 3.f});       // top-left
  image.set(1, 0, {4.f, 5.f, 6.f});       // top-right
  image.set(0, 1, {-7.f, 0.25f, 1e20f});  // bottom-left
  image.set(1, 1, {10.f, 11.f, 12.5f});   // bottom-right
  const std::string path = temp_path("contents.pfm");
  save_pfm(image, path);
  const std::string bytes = read_bytes(path);
  const std::string header = "PF\n2 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 12 * sizeof(float));
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  const float expected[12] = {-7.f, 0.25f, 1e20f, 10.f, 11.f, 12.5f, 1.f, 2.f, 3.f, 4.f, 5.f, 6.f};
  for (int i = 0; i < 12; ++i) {
    std::uint32_t bits = 0;
    for (int b = 3; b >= 0; --b)  // little-endian, whatever the host
      bits = (bits << 8) | std::uint8_t(bytes[header.size() + 4 * i + b]);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    EXPECT_EQ(value, expected[i]) << i;
  }
  const Image back = load_pfm(path);
  EXPECT_EQ(back.rgb, image.rgb);
  std::filesystem::remove(path);
}

TEST(Pfm, InfinityAndNegativeValues_AreKeptExactly) {
  Image image(1, 1);
  image.set(0, 0, {std::numeric_limits<float>::infinity(), -0.5f, 0.f});
  const std::string path = temp_path("inf.pfm");
  save_image(image, path);
  EXPECT_EQ(load_pfm(path).rgb, image.rgb);
  std::filesystem::remove(path);
}

TEST(SaveImage, UnknownExtension_ThrowsNamingTheFile) {
  const Image image(1, 1);
  try {
    save_image(image, temp_path("picture.bmp"));
    FAIL() << "no exception";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("picture.bmp"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(".bmp"), std::string::npos) << e.what();
  }
  EXPECT_THROW(save_image(image, temp_path("no_extension")), ImageError);
}

TEST(SaveImage, ExtensionIsCaseInsensitive) {
  EXPECT_EQ(image_format_for("a/b/OUT.PNG"), ImageFormat::kPng);
  EXPECT_EQ(image_format_for("x.Pfm"), ImageFormat::kPfm);
}

TEST(SaveImage, Exr_WritesAnOpenExrFileOrSaysWhyNot) {
  Image image(3, 2);
  image.set(1, 1, {0.5f, 2.f, 100.f});
  const std::string path = temp_path("out.exr");
  if (!have_exr()) {
    EXPECT_THROW(save_image(image, path), ImageError);
    return;
  }
  save_image(image, path);
  const std::string bytes = read_bytes(path);
  ASSERT_GE(bytes.size(), 4u);
  EXPECT_EQ(bytes.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));  // the OpenEXR magic number
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace raycast
