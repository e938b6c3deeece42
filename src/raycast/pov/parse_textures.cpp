// Textures, pigments, finishes, interiors, materials, colour maps and transforms. What raycast's
// material cannot show yet (patterns other than checker, normals, layered textures ...) is read
// whole and warned about once per kind.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "pov/interpreter.h"
#include "pov/pov_transform.h"

namespace raycast::pov {

namespace {
const char* const kPatterns[] = {"agate",       "average",
                                 "boxed",       "bozo",
                                 "brick",       "bumps",
                                 "cells",       "crackle",
                                 "cylindrical", "density_file",
                                 "dents",       "facets",
                                 "function",    "gradient",
                                 "granite",     "hexagon",
                                 "leopard",     "marble",
                                 "object",      "onion",
                                 "pavement",    "pigment_pattern",
                                 "planar",      "quilted",
                                 "radial",      "ripples",
                                 "spherical",   "spiral1",
                                 "spiral2",     "spotted",
                                 "square",      "tiling",
                                 "triangular",  "waves",
                                 "wood",        "wrinkles",
                                 "mandel",      "julia",
                                 "magnet",      "image_pattern",
                                 "slope",       "aoi",
                                 "cubic",       "checker",
                                 "image_map",   "pattern",
                                 "tiles",       "hexagon",
                                 "brick"};
const char* const kPatternModifiers[] = {"turbulence",
                                         "octaves",
                                         "omega",
                                         "lambda",
                                         "frequency",
                                         "phase",
                                         "ramp_wave",
                                         "triangle_wave",
                                         "sine_wave",
                                         "scallop_wave",
                                         "cubic_wave",
                                         "poly_wave",
                                         "noise_generator",
                                         "metric",
                                         "form",
                                         "offset",
                                         "solid",
                                         "exponent",
                                         "accuracy",
                                         "interpolate",
                                         "once",
                                         "map_type",
                                         "use_color",
                                         "use_colour",
                                         "use_index",
                                         "color_space",
                                         "orientation",
                                         "mortar",
                                         "coords",
                                         "max_iteration",
                                         "precision",
                                         "repeat",
                                         "agate_turb",
                                         "brick_size",
                                         "control0",
                                         "control1",
                                         "fractal_interior_type",
                                         "fractal_exterior_type",
                                         "interior",
                                         "exterior"};
// Whether `w` is one of the two keyword lists (sets made once: asked for many words).
bool in(const char* const* list, std::size_t n, const std::string& w) {
  static const std::unordered_set<std::string_view> patterns(std::begin(kPatterns),
                                                             std::end(kPatterns));
  static const std::unordered_set<std::string_view> modifiers(std::begin(kPatternModifiers),
                                                              std::end(kPatternModifiers));
  (void)n;
  return (list == kPatterns ? patterns : modifiers).count(w) > 0;
}
Colour to_colour(const Value& v) {
  if (v.kind == Value::Float) return {v.v[0], v.v[0], v.v[0], 0, 0};
  return {v.v[0], v.v[1], v.dims > 2 ? v.v[2] : 0, v.dims > 3 ? v.v[3] : 0,
          v.dims > 4 ? v.v[4] : 0};
}
}  // namespace

namespace {

// An array of numbers (colours, vectors): its elements start a colour, not a pigment.
bool holds_numbers(const Value& v) {
  if (v.kind != Value::Array || !v.array) return false;
  for (const std::optional<Value>& e : v.array->elements)
    if (e) return e->is_numeric();
  return false;
}

}  // namespace

std::optional<Value> Interpreter::declared(Value::Kind kind) {
  if (tok().kind != Token::Word) return std::nullopt;
  const Value* v = lookup(tok().text);
  if (!v) return std::nullopt;
  if (v->kind == kind || (kind == Value::Texture && v->kind == Value::Material)) {
    Value copy = *v;
    next();
    return copy;
  }
  if (v->kind != Value::Array || holds_numbers(*v)) return std::nullopt;
  const Pos at = tok().pos;
  Value e = expression();  // an element: Textures[I]
  if (e.kind != kind && !(kind == Value::Texture && e.kind == Value::Material))
    fail_at(at, std::string("expected ") + (kind == Value::Texture ? "a texture" : "a pigment") +
                    ", got " + kind_name(e));
  return e;
}

void Interpreter::pattern_arguments(const Token& t, bool colours) {
  const std::string& w = t.text;
  if (w == "function" || w == "pigment_pattern" || w == "object" || w == "image_pattern" ||
      w == "image_map" || w == "tiles" || w == "slope") {
    if (w == "slope" && !is_symbol("{")) {
      expression();
      return;
    }
    if (w == "function" && !is_symbol("{")) {  // function F: a declared function's name
      if (tok().kind == Token::Word) next();
      return;
    }
    skip_block(w);
  } else if (w == "density_file") {
    tok();
    next();  // df3
    string_value("density_file");
  } else if (colours && (w == "brick" || w == "hexagon" || w == "checker")) {
    while (starts_colour()) {
      colour("the pattern");
      skip_comma();
    }
  } else {
    // The pattern's own values: a number, a vector, or (julia) a vector and a number.
    for (int k = 0; k < 3 && numeric_ahead(); ++k) {
      expression();
      skip_comma();
    }
  }
}

bool Interpreter::numeric_ahead() {
  const Token& t = peek_operator();
  if (pending_) return false;
  if (t.kind == Token::Number || pov::is_symbol(t, "<") || pov::is_symbol(t, "(") ||
      pov::is_symbol(t, "-"))
    return true;
  if (t.kind != Token::Word) return false;
  if (t.text == "x" || t.text == "y" || t.text == "z") return true;
  const Value* v = lookup(t.text);
  return v && v->is_numeric();
}

bool Interpreter::starts_colour() {
  const Token& t = tok();
  if (t.kind == Token::Number || pov::is_symbol(t, "<") || pov::is_symbol(t, "(")) return true;
  if (t.kind != Token::Word) return false;
  const std::string& w = t.text;
  if (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit") return true;
  if (w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" ||
      w == "srgb" || w == "srgbf" || w == "srgbt" || w == "srgbft")
    return true;
  const Value* v = lookup(w);
  return v && (v->is_numeric() || holds_numbers(*v));
}

Colour Interpreter::colour(const char* what) {
  const Pos at = tok().pos;
  const Token& t = tok();
  const bool component_first =
      t.kind == Token::Word && (t.text == "red" || t.text == "green" || t.text == "blue" ||
                                t.text == "filter" || t.text == "transmit");
  const Value v = component_first ? colour_modifiers(Value::vector({0, 0, 0, 0, 0}))
                                  : colour_modifiers(expression());
  if (!v.is_numeric())
    fail_at(at, std::string("expected a colour for ") + what + ", got " + kind_name(v));
  return to_colour(v);
}

std::vector<MapEntry> Interpreter::colour_map_block() {
  expect_symbol("{", "after color_map");
  std::vector<MapEntry> map;
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::ColourMap) {
      map = *v->colour_map;
      next();
    }
  }
  while (!accept_symbol("}")) {
    if (!is_symbol("[")) unexpected("'[' to open a colour map entry");
    next();
    const double a = number("a colour map value");
    skip_comma();
    if (!is_symbol("]") && tok().kind == Token::Number) {
      // [a, b colour c0 colour c1]: POV-Ray's older two-colour form.
      const double b = number("a colour map value");
      skip_comma();
      const Colour c0 = colour("the colour map");
      skip_comma();
      const Colour c1 = colour("the colour map");
      map.push_back({a, c0});
      map.push_back({b, c1});
    } else {
      map.push_back({a, colour("the colour map")});
    }
    expect_symbol("]", "to close the colour map entry");
    if (map.size() > 256) fail_here("a colour map has at most 256 entries");
  }
  return map;
}

bool Interpreter::transform_item(std::vector<XformOp>& ops) {
  const Pos at = tok().pos;
  if (is_word("translate") || is_word("scale") || is_word("rotate")) {
    XformOp op;
    op.kind = is_word("translate") ? XformOp::Translate
              : is_word("scale")   ? XformOp::Scale
                                   : XformOp::Rotate;
    next();
    op.v = vector("the transformation");
    if (op.kind == XformOp::Scale && (op.v.x == 0 || op.v.y == 0 || op.v.z == 0)) {
      unsupported_warning(at, "scale by 0", "taken as 1 on that axis");
      if (op.v.x == 0) op.v.x = 1;
      if (op.v.y == 0) op.v.y = 1;
      if (op.v.z == 0) op.v.z = 1;
    }
    ops.push_back(op);
  } else if (is_word("matrix")) {
    next();
    expect_symbol("<", "after matrix");
    XformOp op;
    op.kind = XformOp::Matrix;
    for (int i = 0; i < 12; ++i) {
      if (i) expect_symbol(",", "between the matrix's 12 values");
      op.m[static_cast<std::size_t>(i)] = number_in_vector("a matrix value");
    }
    expect_symbol(">", "after the matrix's 12 values");
    ops.push_back(op);
  } else if (is_word("transform")) {
    next();
    const Value* v = tok().kind == Token::Word ? lookup(tok().text) : nullptr;
    if (v && v->kind == Value::Transform) {
      const auto t = v->transform;
      next();
      ops.insert(ops.end(), t->begin(), t->end());
    } else {
      const auto t = transform_block();
      ops.insert(ops.end(), t.begin(), t.end());
    }
  } else {
    return false;
  }
  return true;
}

std::vector<XformOp> Interpreter::transform_block() {
  expect_symbol("{", "after transform");
  std::vector<XformOp> ops;
  bool inverse = false;
  while (!accept_symbol("}")) {
    if (is_word("inverse")) {
      next();
      inverse = true;
      continue;
    }
    if (tok().kind == Token::Word) {
      const Value* v = lookup(tok().text);
      if (v && v->kind == Value::Transform) {
        ops.insert(ops.end(), v->transform->begin(), v->transform->end());
        next();
        continue;
      }
    }
    if (!transform_item(ops))
      unexpected("translate, rotate, scale, matrix or inverse in transform");
  }
  if (inverse) {
    // The inverse of a sequence: the inverted steps in reverse order.
    std::vector<XformOp> inv;
    for (auto it = ops.rbegin(); it != ops.rend(); ++it) {
      XformOp o = *it;
      if (o.kind == XformOp::Translate) o.v = o.v * -1.0;
      if (o.kind == XformOp::Scale) o.v = {1 / o.v.x, 1 / o.v.y, 1 / o.v.z};
      if (o.kind == XformOp::Rotate) {
        // Rotations about x, then y, then z undone: -z, then -y, then -x.
        for (int k = 2; k >= 0; --k) {
          XformOp r;
          r.kind = XformOp::Rotate;
          r.v = {k == 0 ? -o.v.x : 0, k == 1 ? -o.v.y : 0, k == 2 ? -o.v.z : 0};
          inv.push_back(r);
        }
        continue;
      }
      if (o.kind == XformOp::Matrix) {
        // Rows r0 r1 r2 (3x3, row-vector form) and translation t: p' = p A + t.
        const auto& m = o.m;
        const double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7],
                     i = m[8];
        const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
        if (det == 0) fail_here("transform { inverse } of a singular matrix");
        std::array<double, 9> r = {
            (e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det,
            (f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det,
            (d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det};
        XformOp q;
        q.kind = XformOp::Matrix;
        for (int k = 0; k < 9; ++k)
          q.m[static_cast<std::size_t>(k)] = r[static_cast<std::size_t>(k)];
        for (int col = 0; col < 3; ++col) {
          double s = 0;
          for (int row = 0; row < 3; ++row)
            s += m[static_cast<std::size_t>(9 + row)] * r[static_cast<std::size_t>(3 * row + col)];
          q.m[static_cast<std::size_t>(9 + col)] = -s;
        }
        inv.push_back(q);
        continue;
      }
      inv.push_back(o);
    }
    ops = inv;
  }
  return ops;
}

Pigment Interpreter::pigment_block(const Pigment& base) {
  expect_symbol("{", "after pigment");
  return pigment_body(base, "}");
}

Pigment Interpreter::pigment_body(const Pigment& base, const char* close) {
  Pigment p = base;
  // `uv_mapping` may come before the declared pigment it applies to (POV-Ray reads both orders;
  // raycast's patterns are evaluated in space either way).
  if (is_word("uv_mapping")) next();
  if (const std::optional<Value> v = declared(Value::Pigment)) p = *v->pigment;
  // The texture system's model of the pigment, built alongside the summary fields.
  texture::Pigment model = p.model ? *p.model : texture::Pigment{};
  bool modelled = p.model != nullptr;
  while (!accept_symbol(close)) {
    const Token t = tok();
    const std::string& w = t.text;
    if (t.kind == Token::Word && w == "checker") {
      next();
      p.checker = true;
      p.pattern.clear();
      p.c0 = {0, 0, 1, 0, 0};  // POV-Ray's defaults: blue and green
      p.c1 = {0, 1, 0, 0, 0};
      start_pattern(texture::PatternKind::kChecker, model.pattern);
      model.kind = texture::Pigment::Kind::kColorMap;
      model.color_map = {{0, {{0, 0, 1}, 0, 0}}, {1, {{0, 1, 0}, 0, 0}}};
      block_list(model.pattern, model, p);
      modelled = true;
    } else if (t.kind == Token::Word && texture::pattern_kind(w)) {
      next();
      const texture::PatternKind k = *texture::pattern_kind(w);
      p.checker = false;
      p.pattern = w;
      start_pattern(k, model.pattern);
      if (model.kind == texture::Pigment::Kind::kSolid) {
        model.kind = texture::Pigment::Kind::kColorMap;  // POV-Ray's default map: black to white
        model.color_map = {{0, {{0, 0, 0}, 0, 0}}, {1, {{1, 1, 1}, 0, 0}}};
      }
      if (texture::block_count(k) > 0) {
        // Brick: mortar white, brick red; hexagon: blue, green, red; the others like checker.
        model.color_map =
            k == texture::PatternKind::kBrick
                ? std::vector<texture::ColorMapEntry>{{0, {{1, 1, 1}, 0, 0}},
                                                      {1, {{0.5, 0, 0}, 0, 0}}}
                : std::vector<texture::ColorMapEntry>{
                      {0, {{0, 0, 1}, 0, 0}}, {1, {{0, 1, 0}, 0, 0}}, {2, {{1, 0, 0}, 0, 0}}};
        model.kind = texture::Pigment::Kind::kColorMap;
        block_list(model.pattern, model, p);
      }
      modelled = true;
    } else if (t.kind == Token::Word && w == "average") {
      next();
      p.checker = false;
      p.pattern = w;
      model.kind = texture::Pigment::Kind::kAverage;
      modelled = true;
    } else if (pigment_item(t, p, model, modelled)) {
    } else {
      unexpected("a colour or a pattern in pigment");
    }
  }
  p.model = modelled && model.kind != texture::Pigment::Kind::kSolid
                ? std::make_shared<const texture::Pigment>(std::move(model))
                : nullptr;
  return p;
}

bool Interpreter::pigment_item(const Token& t, Pigment& p, texture::Pigment& model,
                               bool& modelled) {
  const std::string& w = t.text;
  if (t.kind != Token::Word) {
    if (!starts_colour()) return false;
    p.checker = false;
    p.c0 = colour("pigment");
    model.kind = texture::Pigment::Kind::kSolid;
    return true;
  }
  if (w == "image_map") {
    next();
    p.checker = false;
    p.pattern = w;
    p.c0 = {0.5, 0.5, 0.5, 0, 0};
    if (auto image = image_map_block(w)) {
      // The image's colours through the pattern's transformations (set after it, as in POV-Ray).
      std::vector<texture::PatternStep> steps = std::move(model.pattern.steps);
      model.pattern = texture::make_pattern(texture::PatternKind::kImage);
      model.pattern.steps = std::move(steps);
      model.pattern.image = std::move(image);
      model.kind = texture::Pigment::Kind::kImage;
      modelled = true;
    } else {
      model.kind = texture::Pigment::Kind::kSolid;
    }
  } else if (in(kPatterns, std::size(kPatterns), w)) {
    next();
    unsupported_warning(t.pos, "the " + w + " pattern", "drawn in its colour map's middle colour");
    p.checker = false;
    p.pattern = w;
    pattern_arguments(t, true);
    model.kind = texture::Pigment::Kind::kSolid;
  } else if (w == "color_map" || w == "colour_map") {
    next();
    p.map = colour_map_block();
    if (!p.map.empty()) p.c0 = p.map[p.map.size() / 2].colour;
    model.color_map.clear();
    for (const MapEntry& e : p.map)
      model.color_map.push_back(
          {e.at, {{e.colour.r, e.colour.g, e.colour.b}, e.colour.filter, e.colour.transmit}});
    if (model.kind == texture::Pigment::Kind::kPigmentMap)
      model.kind = texture::Pigment::Kind::kColorMap;
  } else if (w == "pigment_map") {
    next();
    const bool average = model.kind == texture::Pigment::Kind::kAverage;
    model.pigment_map = pigment_map_block(average);
    if (model.kind != texture::Pigment::Kind::kSolid && !average)
      model.kind = texture::Pigment::Kind::kPigmentMap;
    if (!model.pigment_map.empty()) {
      // The middle entry's colour summarises the map for the YAML conversion.
      const texture::Rgbft& c = model.pigment_map[model.pigment_map.size() / 2].pigment->color;
      p.c0 = {c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit};
    }
  } else if (w == "slope_map") {
    next();
    unsupported_warning(t.pos, w);
    skip_block(w);
  } else if (pattern_modifier(w, model.pattern)) {
  } else if (in(kPatternModifiers, std::size(kPatternModifiers), w)) {
    next();
    skip_pattern_modifier(w);
  } else if (w == "quick_color" || w == "quick_colour") {
    next();
    colour("quick_color");
  } else if (w == "uv_mapping") {
    next();
  } else if (w == "scale" || w == "translate" || w == "rotate" || w == "matrix" ||
             w == "transform") {
    std::vector<XformOp> ops;
    transform_item(ops);
    const std::optional<Transform> x = pov_transform(ops);
    if (!x) fail_at(t.pos, "the pigment's matrix cannot be inverted");
    for (const XformOp& o : ops)
      if (o.kind == XformOp::Scale && o.v.x == o.v.y && o.v.y == o.v.z && o.v.x > 0)
        p.scale *= o.v.x;
      else
        p.checker_plain = false;
    texture::transform_pigment(model, *x);
    // A pattern not named yet still gets the move (pigment { scale 2 bozo }).
    if (model.kind == texture::Pigment::Kind::kSolid) texture::transform_pattern(model.pattern, *x);
  } else if (starts_colour()) {
    p.checker = false;
    p.pattern.clear();
    p.c0 = colour("pigment");
    model.kind = texture::Pigment::Kind::kSolid;
    modelled = false;
    model.pattern.steps.clear();
  } else {
    return false;
  }
  return true;
}

void Interpreter::skip_pattern_modifier(const std::string& w) {
  if (w == "fractal_interior_type" || w == "fractal_exterior_type" || w == "interior" ||
      w == "exterior") {
    expression();
    skip_comma();
    expression();
  } else if (w == "metric" || w == "offset" || w == "exponent" || w == "accuracy" ||
             w == "interpolate" || w == "map_type" || w == "color_space" || w == "max_iteration" ||
             w == "precision" || w == "form" || w == "orientation" || w == "coords" ||
             w == "repeat") {
    expression();
  }
}

bool is_pattern_word(const std::string& w) { return in(kPatterns, std::size(kPatterns), w); }
bool is_pattern_modifier_word(const std::string& w) {
  return in(kPatternModifiers, std::size(kPatternModifiers), w);
}

void Interpreter::reflection_block(Finish& f) {
  std::vector<double> values;
  while (!accept_symbol("}")) {
    if (is_word("fresnel")) {
      next();
      f.fresnel = boolean_option();
    } else if (is_word("falloff")) {
      next();
      f.reflection_falloff = number("reflection falloff");
    } else if (is_word("metallic")) {
      next();
      f.reflection_metallic = true;
      if (numeric_ahead()) number("reflection metallic");
    } else if (is_word("exponent")) {
      unsupported_warning(tok().pos, "reflection exponent");
      next();
      if (starts_colour()) number("a reflection setting");
    } else if (starts_colour()) {
      const Colour c = colour("reflection");
      values.push_back((c.r + c.g + c.b) / 3);
      skip_comma();
    } else {
      unexpected("a reflection value or fresnel");
    }
  }
  if (values.empty()) return;
  f.reflection_min = values.front();
  f.reflection_max = values.back();
  // { min, max fresnel on }: raycast's Fresnel split starts from the minimum; without fresnel,
  // POV-Ray's variable reflection is drawn at its mean.
  f.reflection = f.fresnel ? values.front() : 0.5 * (values.front() + values.back());
}

Finish Interpreter::finish_block(const Finish& base) {
  expect_symbol("{", "after finish");
  Finish f = base;
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::Finish) {
      f = *v->finish;
      next();
    }
  }
  auto grey = [&](const char* what) {
    const Colour c = colour(what);
    return (c.r + c.g + c.b) / 3;
  };
  while (!accept_symbol("}")) {
    const Token t = tok();
    const std::string& w = t.text;
    if (w == "ambient")
      next(), f.ambient = grey("ambient");
    else if (w == "emission")
      next(), f.ambient += grey("emission");
    else if (w == "diffuse") {
      next();
      if (is_word("albedo")) next();
      f.diffuse = number("diffuse");
      if (accept_symbol(",")) number("diffuse's back side");
    } else if (w == "phong") {
      next();
      if (is_word("albedo")) next();
      f.phong = number("phong");
    } else if (w == "phong_size")
      next(), f.phong_size = number("phong_size");
    else if (w == "specular") {
      next();
      if (is_word("albedo")) next();
      f.specular = number("specular");
    } else if (w == "roughness") {
      next();
      f.roughness = std::max(number("roughness"), 1e-6);
    } else if (w == "reflection") {
      next();
      if (accept_symbol("{"))
        reflection_block(f);
      else {
        f.fresnel = false;
        f.reflection = grey("reflection");
        f.reflection_min = f.reflection_max = f.reflection;
      }
    } else if (w == "conserve_energy") {
      next();
      f.conserve_energy = boolean_option();
    } else if (w == "brilliance") {
      next(), f.brilliance = number("brilliance");
    } else if (w == "crand") {
      next(), f.crand = number("crand");
    } else if (w == "metallic") {
      next();
      if (is_word("on") || is_word("off") || is_word("true") || is_word("false") ||
          is_word("yes") || is_word("no"))
        f.metallic = boolean_option() ? 1 : 0;
      else
        f.metallic = numeric_ahead() ? number("metallic") : 1;
    } else if (w == "ior" || w == "refraction" || w == "caustics" || w == "fade_distance" ||
               w == "fade_power") {
      // POV-Ray 3.1's finish items, an interior's since 3.5: POV-Ray still reads them with a
      // warning; `ior` and the fade are kept (refraction in raycast follows the material's
      // transmission).
      next();
      const double x = number(w.c_str());
      if (w == "ior")
        f.ior = x;
      else if (w == "fade_distance")
        f.fade_distance = x;
      else if (w == "fade_power")
        f.fade_power = x;
      else
        unsupported_warning(t.pos, "finish " + w + " (an interior item since POV-Ray 3.5)");
    } else if (w == "irid" || w == "subsurface" || w == "reflection_exponent") {
      next();
      if (w == "reflection_exponent")
        number(w.c_str());
      else
        skip_block(w);
      unsupported_warning(t.pos, "finish " + w);
    } else {
      unexpected("a finish item (ambient, diffuse, phong, specular, roughness, reflection ...)");
    }
  }
  return f;
}

Interior Interpreter::interior_block() {
  expect_symbol("{", "after interior");
  Interior in;
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::Interior) {
      if (v->interior) in = *v->interior;
      next();
    }
  }
  while (!accept_symbol("}")) {
    const Token t = tok();
    if (t.text == "ior") {
      next();
      in.ior = number("ior");
      if (*in.ior <= 0) fail_at(t.pos, "ior must be > 0");
    } else if (t.text == "media") {
      next();
      unsupported_warning(t.pos, "media");
      skip_block("media");
    } else if (t.text == "fade_distance") {
      next();
      in.fade_distance = number("fade_distance");
    } else if (t.text == "fade_power") {
      next();
      in.fade_power = number("fade_power");
    } else if (t.text == "fade_color" || t.text == "fade_colour") {
      next();
      in.fade_color = colour("fade_color");
    } else if (t.text == "dispersion") {
      next();
      in.dispersion = number("dispersion");
      if (!(in.dispersion > 0)) fail_at(t.pos, "dispersion must be > 0");
    } else if (t.text == "dispersion_samples") {
      next();
      const double n = number("dispersion_samples");
      if (!(n >= 2 && n <= 64)) fail_at(t.pos, "dispersion_samples must be 2 to 64");
      in.dispersion_samples = static_cast<int>(n);
    } else if (t.text == "caustics") {
      next();
      number(t.text.c_str());
      unsupported_warning(t.pos, "interior " + t.text);
    } else {
      unexpected("ior, media, caustics, dispersion or fade settings in interior");
    }
  }
  return in;
}

Texture Interpreter::texture_block(const Texture& base, int depth) {
  if (depth > kMaxPovNesting) fail_here("textures are nested too deeply");
  const NestingLevel level(*this);  // a texture's depth restarts in a value declared inside it
  expect_symbol("{", "after texture");
  return texture_body(base, depth, "}");
}

Texture Interpreter::texture_body(const Texture& base, int depth, const char* close) {
  Texture t = base;
  t.name.clear();
  if (const std::optional<Value> v = declared(Value::Texture)) {
    const std::optional<Interior> interior = t.interior;
    t = *v->texture;
    if (!t.interior) t.interior = interior;
  } else if (const Value* p = tok().kind == Token::Word ? lookup(tok().text) : nullptr;
             p && p->kind == Value::Pigment && p->pigment) {
    t.pigment = *p->pigment;  // POV-Ray reads a pigment's name alone as the texture's pigment
    next();
  }
  std::optional<TextureMap> map;  // a patterned texture being read
  while (!accept_symbol(close)) {
    const Token k = tok();
    if (is_word("texture") && map) {  // the textures of a block pattern, in order
      next();
      map->at.push_back(double(map->textures.size()));
      map->textures.push_back(texture_block(base, depth + 1));
      skip_comma();
    } else if (is_word("texture")) {  // a texture written whole inside a map entry
      next();
      t = texture_block(t, depth + 1);
    } else if (is_word("pigment")) {
      next();
      t.pigment = pigment_block(t.pigment);
    } else if (is_word("finish")) {
      next();
      t.finish = finish_block(t.finish);
    } else if (is_word("normal")) {
      next();
      t.normal = normal_block(t.normal);
    } else if (is_word("no_bump_scale")) {
      next();
      unsupported_warning(k.pos, "no_bump_scale", "bumps scale with the texture");
    } else if (is_word("material_map")) {
      next();
      unsupported_warning(k.pos, k.text, "the first texture is used");
      if (std::optional<Texture> first = first_texture_in_block(base, depth, k.text)) t = *first;
    } else if (is_word("texture_map")) {
      next();
      if (!map) {
        unsupported_warning(k.pos, "texture_map without a pattern", "the first texture is used");
        map.emplace();
      }
      texture_map_block(base, depth, *map);
    } else if (k.kind == Token::Word && texture::pattern_kind(k.text)) {
      // a patterned texture (texture { gradient x texture_map { ... } })
      next();
      if (!map) map.emplace();
      start_pattern(*texture::pattern_kind(k.text), map->pattern);
    } else if (is_word("average")) {
      next();
      if (!map) map.emplace();
      map->average = true;
    } else if (k.kind == Token::Word && in(kPatterns, std::size(kPatterns), k.text)) {
      next();
      unsupported_warning(k.pos, "textures patterned by " + k.text, "the first texture is used");
      if (!map) map.emplace();
      pattern_arguments(k, false);
    } else if (k.kind == Token::Word && map && pattern_modifier(k.text, map->pattern)) {
    } else if (k.kind == Token::Word &&
               in(kPatternModifiers, std::size(kPatternModifiers), k.text)) {
      next();
      if (starts_colour()) expression();
    } else if (is_word("warp")) {
      next();
      skip_block("warp");
    } else if (is_word("uv_mapping")) {
      next();
    } else if (k.kind == Token::Word &&
               (k.text == "scale" || k.text == "translate" || k.text == "rotate" ||
                k.text == "matrix" || k.text == "transform")) {
      std::vector<XformOp> ops;
      transform_item(ops);
      if (map) {
        if (const std::optional<Transform> x = pov_transform(ops))
          texture::transform_pattern(map->pattern, *x);
        for (Texture& e : map->textures) move_texture(e, ops);
      } else {
        move_texture(t, ops);
      }
    } else {
      unexpected("pigment, finish, normal or a transformation in texture");
    }
  }
  if (map && !map->textures.empty()) {
    const std::optional<Interior> interior = t.interior;
    t = Texture{};
    t.interior = interior;
    t.pigment = map->textures.front().pigment;  // what the YAML conversion shows
    t.finish = map->textures.front().finish;
    t.map = std::make_shared<const TextureMap>(std::move(*map));
  }
  return t;
}

std::optional<Texture> Interpreter::first_texture_in_block(const Texture& base, int depth,
                                                           const std::string& what) {
  expect_symbol("{", ("after " + what).c_str());
  std::optional<Texture> first;
  int braces = 0;  // of the items between the textures (an image's file, its options)
  while (braces > 0 || !accept_symbol("}")) {
    if (is_symbol("{")) ++braces;
    if (is_symbol("}")) --braces;
    if (is_word("texture")) {
      next();
      Texture layer = texture_block(base, depth + 1);
      if (!first) first = std::move(layer);
      continue;
    }
    if (tok().kind == Token::End) fail_here(what + " { is never closed");
    if (tok().kind == Token::Word) {
      if (const std::optional<Value> v = declared(Value::Texture)) {
        if (!first) first = *v->texture;
        continue;
      }
    }
    next();
  }
  return first;
}

void Interpreter::texture_map_block(const Texture& base, int depth, TextureMap& map) {
  expect_symbol("{", "after texture_map");
  while (!accept_symbol("}")) {
    if (!is_symbol("[")) unexpected("'[' to open a texture map entry");
    next();
    const double at = numeric_ahead()  ? number("a texture map value")
                      : map.average    ? 1
                      : map.at.empty() ? 0
                                       : map.at.back() + 1;
    skip_comma();
    if (depth + 1 > kMaxPovNesting) fail_here("textures are nested too deeply");
    Texture entry = texture_body(base, depth + 1, "]");
    // Entries are kept sorted by value (a stable insertion: equal values keep their order).
    std::size_t i = map.at.size();
    while (i > 0 && map.at[i - 1] > at) --i;
    map.at.insert(map.at.begin() + std::ptrdiff_t(i), at);
    map.textures.insert(map.textures.begin() + std::ptrdiff_t(i), std::move(entry));
    if (map.at.size() > texture::kMaxMapEntries) fail_here("a texture map has at most 256 entries");
  }
}

Texture Interpreter::material_block(const Texture& base, int depth) {
  expect_symbol("{", "after material");
  Texture t = base;
  if (const std::optional<Value> v = declared(Value::Texture)) t = *v->texture;
  while (!accept_symbol("}")) {
    if (is_word("texture")) {
      next();
      const std::optional<Interior> interior = t.interior;
      t = texture_block(t, depth + 1);
      t.interior = interior;
    } else if (is_word("interior")) {
      next();
      t.interior = interior_block();
    } else if (is_word("interior_texture")) {
      unsupported_warning(tok().pos, "interior_texture");
      next();
      skip_block("interior_texture");
    } else {
      std::vector<XformOp> ops;
      if (!transform_item(ops)) unexpected("texture or interior in material");
    }
  }
  return t;
}

}  // namespace raycast::pov
