#include "geometry/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <stdexcept>

#include "geometry/shape_checks.h"
#include "load/text_shape.h"

namespace raycast {
namespace {

// POV-Ray's own Times Roman, from Debian's povray-includes (never copied into the project).
const char* const kFont = "/usr/share/povray-3.7/include/timrom.ttf";

bool have_font() { return std::filesystem::exists(kFont); }

// FreeType's control box of one character, in em units, and its advance.
Aabb freetype_box(unsigned long ch, double& advance) {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  Aabb box;
  if (FT_Init_FreeType(&lib) != 0) return box;
  if (FT_New_Face(lib, kFont, 0, &face) == 0) {
    FT_Load_Glyph(face, FT_Get_Char_Index(face, ch), FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING);
    FT_BBox b;
    FT_Outline_Get_CBox(&face->glyph->outline, &b);
    const double s = 1.0 / face->units_per_EM;
    box = {{s * static_cast<double>(b.xMin), s * static_cast<double>(b.yMin), 0},
           {s * static_cast<double>(b.xMax), s * static_cast<double>(b.yMax), 0}};
    advance = s * static_cast<double>(face->glyph->advance.x);
    FT_Done_Face(face);
  }
  FT_Done_FreeType(lib);
  return box;
}

TEST(Text, LetterI_BoundsAreFreeTypesGlyphBox) {
  if (!have_font()) GTEST_SKIP() << kFont << " is not installed";
  double advance = 0;
  const Aabb ft = freetype_box('I', advance);
  const Text t = make_text_shape(kFont, "I", 0.5, {});
  ASSERT_EQ(t.letters.size(), 1u);
  const Aabb b = bounds(t);
  EXPECT_NEAR(b.lo.x, ft.lo.x, 1e-12);
  EXPECT_NEAR(b.hi.x, ft.hi.x, 1e-12);
  EXPECT_NEAR(b.lo.y, ft.lo.y, 1e-12);
  EXPECT_NEAR(b.hi.y, ft.hi.y, 1e-12);
  EXPECT_EQ(b.lo.z, 0);
  EXPECT_EQ(b.hi.z, 0.5);
  // A capital of Times is about two thirds of the em tall.
  EXPECT_GT(b.hi.y - b.lo.y, 0.5);
  EXPECT_LT(b.hi.y - b.lo.y, 0.8);
}

TEST(Text, RayThroughTheStemHitsTheFrontAtZ0) {
  if (!have_font()) GTEST_SKIP() << kFont << " is not installed";
  const Text t = make_text_shape(kFont, "I", 0.5, {});
  const Aabb b = bounds(t);
  const Vec3 mid = 0.5 * (b.lo + b.hi);
  const Ray r{{mid.x, mid.y, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(t, r, h));
  EXPECT_NEAR(h.t, 5, 1e-12);
  const SurfaceInfo si = surface(t, r, h);
  EXPECT_NEAR(si.p.z, 0, 1e-12);
  EXPECT_NEAR(si.n.z, -1, 1e-12);
  SpanList sl;
  spans(t, r, sl);
  ASSERT_EQ(sl.size(), 1u);
  EXPECT_NEAR(sl[0].out.t, 5.5, 1e-12);
  EXPECT_TRUE(contains(t, {mid.x, mid.y, 0.25}));
}

TEST(Text, RayBetweenLettersMisses_OffsetMovesTheNextLetter) {
  if (!have_font()) GTEST_SKIP() << kFont << " is not installed";
  double advance = 0;
  const Aabb ft = freetype_box('I', advance);
  const Text t = make_text_shape(kFont, "II", 0.5, {});
  ASSERT_EQ(t.letters.size(), 2u);
  // The second letter starts one advance on (Times has no kerning for "II").
  EXPECT_NEAR(bounds(t.letters[1]).lo.x, ft.lo.x + advance, 1e-12);
  const double gap = 0.5 * (ft.hi.x + ft.lo.x + advance);  // between the two stems
  const double y = 0.5 * (ft.lo.y + ft.hi.y);
  LocalHit h;
  EXPECT_FALSE(intersect(t, Ray{{gap, y, -5}, {0, 0, 1}}, h));
  EXPECT_TRUE(intersect(t, Ray{{gap - 0.5 * advance, y, -5}, {0, 0, 1}}, h));
  EXPECT_EQ(h.prim, 0);
  ASSERT_TRUE(intersect(t, Ray{{gap + 0.5 * advance, y, -5}, {0, 0, 1}}, h));
  EXPECT_EQ(h.prim, 1);
  // A spacing of 0.25 along x moves the second letter by that much; z staggers it in depth.
  const Text spaced = make_text_shape(kFont, "II", 0.5, {0.25, 0, 1});
  EXPECT_NEAR(bounds(spaced.letters[1]).lo.x, ft.lo.x + advance + 0.25, 1e-12);
  EXPECT_EQ(bounds(spaced.letters[1]).lo.z, 1);
  // Flipped for a mirrored frame: z in [-0.5, 0].
  const Text flipped = make_text_shape(kFont, "I", 0.5, {}, true);
  EXPECT_EQ(bounds(flipped).lo.z, -0.5);
  EXPECT_EQ(bounds(flipped).hi.z, 0);
}

TEST(Text, RandomRays_SpansMatchContainsAndNormalsPointOut) {
  if (!have_font()) GTEST_SKIP() << kFont << " is not installed";
  // Letters with holes (B, o, 8, A) and curves: the even-odd rule on the font's contours.
  const Text t = make_text_shape(kFont, "Bo8A", 0.3, {});
  const auto inside = [&](const Vec3& p) { return contains(t, p); };
  const Aabb b = bounds(t);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    SCOPED_TRACE(i);
    const auto point = [&] {
      return Vec3{b.lo.x + u(rng) * (b.hi.x - b.lo.x), b.lo.y + u(rng) * (b.hi.y - b.lo.y),
                  -1 + 2.3 * u(rng)};
    };
    const Vec3 a = point(), c = point();
    const Ray r{a, c - a};
    testing::check_spans_against_oracle(t, r, inside, -1, 2, 300);
    LocalHit h;
    if (!intersect(t, r, h)) continue;
    ++hits;
    EXPECT_NEAR(h.t, testing::first_span_end(t, r), 1e-9);
    EXPECT_EQ(occluded(t, r), true);
    testing::expect_outward_normal(t, r, h, inside, 1e-7);
  }
  EXPECT_GT(hits, 100);
  // The hole of the o: a ray down its middle misses.
  const Aabb o = bounds(t.letters[1]);
  LocalHit h;
  EXPECT_FALSE(
      intersect(t, Ray{{0.5 * (o.lo.x + o.hi.x), 0.5 * (o.lo.y + o.hi.y), -5}, {0, 0, 1}}, h));
}

TEST(Text, MissingFontAndBlankStringAreErrors) {
  EXPECT_THROW(make_text_shape("/nonexistent/font.ttf", "A", 1, {}), std::runtime_error);
  if (!have_font()) return;
  EXPECT_THROW(make_text_shape(kFont, "   ", 1, {}), std::invalid_argument);
}

}  // namespace
}  // namespace raycast
