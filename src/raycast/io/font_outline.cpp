#include "io/font_outline.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <memory>
#include <stdexcept>

namespace raycast {

namespace {

// The code points of UTF-8 text; a byte that does not start a valid sequence is Latin-1.
std::vector<unsigned long> code_points(const std::string& text) {
  std::vector<unsigned long> out;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = byte(i);
    const int extra = c >= 0xF0 && c < 0xF8 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    bool valid = c >= 0xC0 && c < 0xF8 && i + static_cast<std::size_t>(extra) < text.size();
    for (int k = 1; valid && k <= extra; ++k)
      valid = (byte(i + static_cast<std::size_t>(k)) & 0xC0) == 0x80;
    if (!valid) {
      out.push_back(c);
      ++i;
      continue;
    }
    unsigned long cp = c & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k)
      cp = (cp << 6) | (byte(i + static_cast<std::size_t>(k)) & 0x3F);
    out.push_back(cp);
    i += static_cast<std::size_t>(extra) + 1;
  }
  return out;
}

// Collects FreeType's outline pieces into contours, in em units placed at the pen.
struct OutlineSink {
  double scale = 1, x0 = 0, y0 = 0;
  std::vector<Contour> contours;
  std::array<double, 2> at{};

  std::array<double, 2> point(const FT_Vector* v) const {
    return {x0 + scale * static_cast<double>(v->x), y0 + scale * static_cast<double>(v->y)};
  }
  void add(int degree, std::initializer_list<const FT_Vector*> pts) {
    ContourPiece p;
    p.degree = degree;
    p.p[0] = at;
    bool moves = false;
    std::size_t k = 1;
    for (const FT_Vector* v : pts) {
      p.p[k] = point(v);
      moves = moves || p.p[k] != at;
      ++k;
    }
    if (!moves || contours.empty()) return;  // a piece of no length
    contours.back().push_back(p);
    at = p.p[static_cast<std::size_t>(degree)];
  }
};

OutlineSink& sink(void* user) { return *static_cast<OutlineSink*>(user); }

int move_to(const FT_Vector* to, void* user) {
  OutlineSink& s = sink(user);
  s.contours.emplace_back();
  s.at = s.point(to);
  return 0;
}
int line_to(const FT_Vector* to, void* user) {
  sink(user).add(1, {to});
  return 0;
}
int conic_to(const FT_Vector* c, const FT_Vector* to, void* user) {
  sink(user).add(2, {c, to});
  return 0;
}
int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  sink(user).add(3, {c1, c2, to});
  return 0;
}

// Contours as the prism needs them: closed, at least two pieces.
std::vector<Contour> closed_contours(std::vector<Contour> in) {
  std::vector<Contour> out;
  for (Contour& c : in) {
    if (c.empty()) continue;
    const auto& end = c.back().p[static_cast<std::size_t>(c.back().degree)];
    if (end != c.front().p[0]) {
      ContourPiece p;
      p.p[0] = end;
      p.p[1] = c.front().p[0];
      c.push_back(p);
    }
    if (c.size() >= 2) out.push_back(std::move(c));
  }
  return out;
}

struct LibraryDeleter {
  void operator()(FT_Library l) const { FT_Done_FreeType(l); }
};
struct FaceDeleter {
  void operator()(FT_Face f) const { FT_Done_Face(f); }
};

}  // namespace

std::vector<LetterOutline> text_outline(const std::string& font_file, const std::string& text,
                                        double spacing_x, double spacing_y) {
  FT_Library lib_raw = nullptr;
  if (FT_Init_FreeType(&lib_raw) != 0) throw std::runtime_error("FreeType cannot start");
  const std::unique_ptr<FT_LibraryRec_, LibraryDeleter> lib(lib_raw);
  FT_Face face_raw = nullptr;
  if (FT_New_Face(lib.get(), font_file.c_str(), 0, &face_raw) != 0)
    throw std::runtime_error("cannot read the font file '" + font_file + "'");
  const std::unique_ptr<FT_FaceRec_, FaceDeleter> face(face_raw);
  if (!FT_IS_SCALABLE(face.get()) || face->units_per_EM == 0)
    throw std::runtime_error("the font file '" + font_file + "' has no outlines");
  const double scale = 1.0 / face->units_per_EM;
  const FT_Outline_Funcs funcs{move_to, line_to, conic_to, cubic_to, 0, 0};
  std::vector<LetterOutline> out;
  double pen_x = 0, pen_y = 0;
  FT_UInt previous = 0;
  int index = 0;
  for (const unsigned long cp : code_points(text)) {
    const FT_UInt glyph = FT_Get_Char_Index(face.get(), cp);
    if (previous != 0 && FT_HAS_KERNING(face.get())) {
      FT_Vector kern{0, 0};
      if (FT_Get_Kerning(face.get(), previous, glyph, FT_KERNING_UNSCALED, &kern) == 0)
        pen_x += scale * static_cast<double>(kern.x);
    }
    if (FT_Load_Glyph(face.get(), glyph,
                      FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0)
      throw std::runtime_error("cannot read a letter of the font file '" + font_file + "'");
    const FT_GlyphSlot slot = face->glyph;
    LetterOutline letter;
    letter.index = index++;
    if (slot->format == FT_GLYPH_FORMAT_OUTLINE) {
      OutlineSink s;
      s.scale = scale;
      s.x0 = pen_x;
      s.y0 = pen_y;
      FT_Outline_Decompose(&slot->outline, &funcs, &s);
      letter.contours = closed_contours(std::move(s.contours));
    }
    out.push_back(std::move(letter));
    pen_x += scale * static_cast<double>(slot->advance.x) + spacing_x;
    pen_y += scale * static_cast<double>(slot->advance.y) + spacing_y;
    previous = glyph;
  }
  return out;
}

}  // namespace raycast
