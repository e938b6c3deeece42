#pragma once
// The outlines of a string's letters in a TrueType or OpenType font file, through FreeType.
#include <string>
#include <vector>

#include "math/contour.h"

namespace raycast {

/// One letter of a laid-out string: its closed contours in the string's coordinates (x along the
/// baseline, y up; one unit is the font's em), and its place in the string.
struct LetterOutline {
  std::vector<Contour> contours;  // empty for a space
  int index = 0;                  // the letter's place in the string, from 0
};

/// The letters of `text` (UTF-8; bytes that are not UTF-8 are read as Latin-1) in the font file,
/// as POV-Ray's `text` lays them out: the first letter's origin at (0, 0), each next one moved by
/// the previous one's advance, the font's kerning for the pair, and `spacing` (x, y). Outlines
/// are the font's own, unhinted: lines and quadratic (TrueType) or cubic (CFF) Bezier pieces,
/// scaled by 1 / units per em. Characters the font lacks draw as its missing-glyph shape. Throws
/// std::runtime_error naming the file when FreeType cannot read it.
std::vector<LetterOutline> text_outline(const std::string& font_file, const std::string& text,
                                        double spacing_x, double spacing_y);

}  // namespace raycast
