// prism { ... } and text { ... }: the swept shapes, read into nodes.
#include <string>

#include "pov/interpreter.h"

namespace raycast::pov {

namespace {

// POV-Ray 3.8's built-in fonts, by number, as the files that ship with POV-Ray 3.7.
const char* internal_font(long n) {
  switch (n) {
    case 2:
      return "cyrvetic.ttf";
    case 3:
      return "crystal.ttf";
    case 4:
      return "povlogo.ttf";
    default:
      return "timrom.ttf";
  }
}

}  // namespace

// prism { [linear_sweep | conic_sweep] [SPLINE] H1, H2, N, <x, z>... }: the keywords may come in
// any order before the heights.
void Interpreter::prism_body(Node& n) {
  n.spline = "linear_spline";
  for (;;) {
    if (is_word("linear_sweep") || is_word("conic_sweep")) {
      n.conic_sweep = is_word("conic_sweep");
      next();
    } else if (is_word("linear_spline") || is_word("quadratic_spline") || is_word("cubic_spline") ||
               is_word("bezier_spline")) {
      n.spline = tok().text;
      next();
    } else {
      break;
    }
  }
  const double h1 = number("prism's first height");
  skip_comma();
  const double h2 = number("prism's second height");
  skip_comma();
  const Pos at = tok().pos;
  const long cnt = count("the number of points");
  if (cnt < 3) fail_at(at, "a prism needs at least 3 points");
  if (cnt > 100000) fail_at(at, "at most 100000 points");
  for (long i = 0; i < cnt; ++i) {
    skip_comma();
    const Pos v = tok().pos;
    const Value p = expression();
    if (p.dims != 2) fail_at(v, "expected a 2-vector <x, z>");
    n.points.push_back({p.v[0], p.v[1], 0});
  }
  n.values = {h1, h2};
}

// text { ttf "FONT" "STRING" THICKNESS, OFFSET } (or `internal N` for the font): a float offset
// is spacing along x.
void Interpreter::text_body(Node& n) {
  const Pos at = tok().pos;
  std::string font;
  if (is_word("ttf")) {
    next();
    font = string_value("the font file");
    skip_comma();
  } else if (is_word("internal")) {
    next();
    font = internal_font(static_cast<long>(number("the internal font's number")));
  } else {
    unexpected("ttf \"font.ttf\" or internal N");
  }
  skip_comma();
  n.text = string_value("the text");
  skip_comma();
  const double thickness = number("the text's thickness");
  skip_comma();
  const Pos o = tok().pos;
  const Value v = expression();
  Vec3 offset;
  if (v.kind == Value::Float)
    offset = {v.v[0], 0, 0};
  else if (v.kind == Value::Vector && v.dims >= 2)
    offset = {v.v[0], v.v[1], v.dims >= 3 ? v.v[2] : 0};
  else
    fail_at(o, "expected the offset between letters: a float or a vector");
  n.values = {thickness};
  n.points = {offset};
  // POV-Ray adds ".ttf" to a font name without an extension ("cyrvetic").
  std::optional<std::string> found = find_on_library_path(font);
  if (!found && font.find('.') == std::string::npos) found = find_on_library_path(font + ".ttf");
  if (!found) {
    unsupported_warning(at, "text in the font '" + font + "'",
                        "the font file is not on the library path: the text is left out");
    return;
  }
  n.font = *found;
}

}  // namespace raycast::pov
