// Patterns in pigments and normals as the texture system models them (texture/): the pattern
// keyword and its own values, its modifiers (turbulence, waves, frequency, warps ...), block
// patterns' lists, pigment maps, normals, texture transformations and layered textures.
#include <algorithm>
#include <cmath>

#include "pov/interpreter.h"
#include "pov/pov_transform.h"

namespace raycast::pov {

namespace {

texture::Rgbft rgbft(const Colour& c) { return {{c.r, c.g, c.b}, c.filter, c.transmit}; }

Vec3 as_vector(const Value& v) {
  if (v.kind == Value::Float) return {v.v[0], v.v[0], v.v[0]};
  return {v.v[0], v.v[1], v.dims > 2 ? v.v[2] : 0};
}

}  // namespace

Texture layer_on_top(Texture below, Texture top) {
  top.under = std::move(below.under);
  below.under.clear();
  if (!top.interior) top.interior = below.interior;
  top.under.push_back(std::move(below));
  return top;
}

void Interpreter::start_pattern(texture::PatternKind kind, texture::Pattern& p) {
  // A pattern named after transformations keeps them (pigment { scale 2 bozo }).
  std::vector<texture::PatternStep> steps = std::move(p.steps);
  const texture::Turbulence turbulence = p.turbulence;
  p = texture::make_pattern(kind);
  p.steps = std::move(steps);
  p.turbulence = turbulence;
  if (kind == texture::PatternKind::kGradient && numeric_ahead()) {
    p.vector = vector("the gradient's direction");
  } else if ((kind == texture::PatternKind::kSpiral1 || kind == texture::PatternKind::kSpiral2) &&
             numeric_ahead()) {
    p.amount = number("the spiral's arms");
  } else if (kind == texture::PatternKind::kFunction) {
    p.function = pattern_function_argument();
  } else if (kind == texture::PatternKind::kImage) {
    // Without an image it reads 0 everywhere.
    p.image = image_map_block("image_pattern");
  }
  skip_comma();
}

std::shared_ptr<const texture::PatternFunction> Interpreter::pattern_function_argument() {
  const Pos at = tok().pos;
  std::shared_ptr<const FunctionValue> f;
  if (is_symbol("{")) {
    f = function_block(at).function;
  } else if (const Value* v = tok().kind == Token::Word ? lookup(tok().text) : nullptr;
             v && v->kind == Value::Function) {
    f = v->function;
    next();
  } else {
    unexpected("a function's block or name after function");
  }
  if (!f->opaque.empty()) {
    unsupported_warning(at, "the function pattern of a " + f->opaque, "its value is 0");
    return nullptr;
  }
  return pattern_function(f);
}

bool Interpreter::pattern_modifier(const std::string& w, texture::Pattern& p) {
  using texture::WaveForm;
  static const std::pair<const char*, WaveForm> waves[] = {
      {"ramp_wave", WaveForm::kRamp},   {"triangle_wave", WaveForm::kTriangle},
      {"sine_wave", WaveForm::kSine},   {"scallop_wave", WaveForm::kScallop},
      {"cubic_wave", WaveForm::kCubic}, {"poly_wave", WaveForm::kPoly}};
  for (const auto& [name, wave] : waves)
    if (w == name) {
      next();
      p.wave = wave;
      p.wave_given = true;
      if (wave == WaveForm::kPoly && numeric_ahead()) p.exponent = number("poly_wave");
      return true;
    }
  if (w == "turbulence") {
    next();
    p.turbulence.amount = as_vector(expression());
  } else if (w == "octaves") {
    next();
    p.turbulence.octaves = std::clamp(int(number("octaves")), 1, 10);
  } else if (w == "omega") {
    next(), p.turbulence.omega = number("omega");
  } else if (w == "lambda") {
    next(), p.turbulence.lambda = number("lambda");
  } else if (w == "frequency") {
    next(), p.frequency = number("frequency");
  } else if (w == "phase") {
    next(), p.phase = number("phase");
  } else if (w == "noise_generator") {
    next(), p.noise_generator = std::clamp(int(number("noise_generator")), 1, 3);
  } else if (w == "agate_turb") {
    next(), p.amount = number("agate_turb");
  } else if (w == "brick_size") {
    next(), p.vector = as_vector(expression());
  } else if (w == "mortar") {
    next(), p.amount = number("mortar");
  } else if (w == "control0") {
    next(), p.amount = number("control0");
  } else if (w == "control1") {
    next(), p.amount2 = number("control1");
  } else if (w == "warp") {
    next();
    warp_block(p);
  } else {
    return false;
  }
  return true;
}

void Interpreter::warp_block(texture::Pattern& p) {
  const Pos at = tok().pos;
  expect_symbol("{", "after warp");
  texture::PatternStep step;
  bool turbulence = false;
  for (int guard = 0; !accept_symbol("}"); ++guard) {
    if (tok().kind == Token::End || guard > 100000) fail_here("warp { is never closed");
    if (is_word("turbulence")) {
      next();
      step.warp.amount = as_vector(expression());
      turbulence = true;
    } else if (is_word("octaves")) {
      next();
      step.warp.octaves = std::clamp(int(number("octaves")), 1, 10);
    } else if (is_word("omega")) {
      next(), step.warp.omega = number("omega");
    } else if (is_word("lambda")) {
      next(), step.warp.lambda = number("lambda");
    } else {
      // repeat, black_hole, spherical, cylindrical, toroidal, planar, cubic warps
      unsupported_warning(at, "warp " + tok().text);
      skip_warp_rest();
      return;
    }
  }
  if (turbulence) p.steps.push_back(step);
}

void Interpreter::skip_warp_rest() {
  int depth = 1;
  for (int guard = 0; depth > 0; ++guard) {
    if (tok().kind == Token::End || guard > 1000000) fail_here("a block is never closed");
    if (is_symbol("{")) ++depth;
    if (is_symbol("}")) --depth;
    next();
  }
}

void Interpreter::skip_entry_rest() {
  int depth = 0;
  for (int guard = 0; depth > 0 || !is_symbol("]"); ++guard) {
    if (tok().kind == Token::End || guard > 1000000) fail_here("a map entry is never closed");
    if (is_symbol("{")) ++depth;
    if (is_symbol("}")) --depth;
    next();
  }
  next();
}

void Interpreter::block_list(texture::Pattern& pattern, texture::Pigment& model, Pigment& p) {
  const int n = texture::block_count(pattern.kind);
  std::vector<texture::Rgbft> colours;
  std::vector<std::shared_ptr<const texture::Pigment>> pigments;
  for (int k = 0; k < n; ++k) {
    if (starts_colour()) {
      const Colour c = colour("the pattern");
      colours.push_back(rgbft(c));
      pigments.push_back(std::make_shared<texture::Pigment>(
          texture::Pigment{texture::Pigment::Kind::kSolid, rgbft(c), {}, {}, {}}));
      if (k == 0) p.c0 = c;
      if (k == 1) p.c1 = c;
    } else if (is_word("pigment")) {
      next();
      const Pigment sub = pigment_block(Pigment{});
      pigments.push_back(sub.model
                             ? sub.model
                             : std::make_shared<texture::Pigment>(texture::Pigment{
                                   texture::Pigment::Kind::kSolid, rgbft(sub.c0), {}, {}, {}}));
      colours.push_back(rgbft(sub.c0));
      if (k == 0) p.c0 = sub.c0;
      if (k == 1) p.c1 = sub.c0;
      if (sub.model) p.checker_plain = false;
    } else {
      break;
    }
    skip_comma();
  }
  if (pigments.empty()) return;  // the defaults set by the caller stay
  if (std::all_of(pigments.begin(), pigments.end(),
                  [](const auto& q) { return q->kind == texture::Pigment::Kind::kSolid; })) {
    model.kind = texture::Pigment::Kind::kColorMap;
    model.color_map.clear();
    for (std::size_t k = 0; k < colours.size(); ++k)
      model.color_map.push_back({double(k), pigments[k]->color});
  } else {
    model.kind = texture::Pigment::Kind::kPigmentMap;
    model.pigment_map.clear();
    for (std::size_t k = 0; k < pigments.size(); ++k)
      model.pigment_map.push_back({double(k), pigments[k]});
  }
}

std::vector<texture::PigmentMapEntry> Interpreter::pigment_map_block(bool weights) {
  expect_symbol("{", "after pigment_map");
  std::vector<texture::PigmentMapEntry> map;
  while (!accept_symbol("}")) {
    if (!is_symbol("[")) unexpected("'[' to open a pigment map entry");
    next();
    // The value may be left out (the entries of an `average` map are weights, 1 by default).
    const double at = numeric_ahead() ? number("a pigment map value")
                      : weights       ? 1
                      : map.empty()   ? 0
                                      : map.back().at + 1;
    skip_comma();
    const Pigment sub = pigment_body(Pigment{}, "]");
    map.push_back({at, sub.model
                           ? sub.model
                           : std::make_shared<texture::Pigment>(texture::Pigment{
                                 texture::Pigment::Kind::kSolid, rgbft(sub.c0), {}, {}, {}})});
    if (map.size() > texture::kMaxMapEntries) fail_here("a pigment map has at most 256 entries");
  }
  std::stable_sort(map.begin(), map.end(),
                   [](const auto& a, const auto& b) { return a.at < b.at; });
  return map;
}

texture::Normal Interpreter::normal_block(const std::optional<texture::Normal>& base) {
  expect_symbol("{", "after normal");
  return normal_body(base, "}");
}

std::vector<texture::NormalMapEntry> Interpreter::normal_map_block() {
  expect_symbol("{", "after normal_map");
  std::vector<texture::NormalMapEntry> map;
  while (!accept_symbol("}")) {
    if (!is_symbol("[")) unexpected("'[' to open a normal map entry");
    next();
    const double weight = numeric_ahead() ? number("a normal map value") : 1;
    skip_comma();
    map.push_back(
        {weight, std::make_shared<const texture::Normal>(normal_body(std::nullopt, "]"))});
    if (map.size() > texture::kMaxMapEntries) fail_here("a normal map has at most 256 entries");
  }
  return map;
}

texture::Normal Interpreter::normal_body(const std::optional<texture::Normal>& base,
                                         const char* close) {
  texture::Normal n = base ? *base : texture::Normal{texture::Pattern{}, 0, {}, {}};
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::Normal) {
      n = *v->normal;
      next();
    }
  }
  bool average = false;
  while (!accept_symbol(close)) {
    if (accept_symbol(",")) continue;  // pattern_name { ... }, BUMP_SIZE
    const Token t = tok();
    const std::string& w = t.text;
    const std::optional<texture::PatternKind> k =
        t.kind == Token::Word ? texture::pattern_kind(w) : std::nullopt;
    if (k) {
      next();
      start_pattern(*k, n.pattern);
      n.bump_size = numeric_ahead() ? number("the bump size") : 0.5;
      skip_comma();
      // A block pattern's normals, one per block in order (checker normal { } normal { }).
      for (int i = 0;
           texture::block_count(*k) > 0 && i < texture::block_count(*k) && is_word("normal"); ++i) {
        next();
        n.map.push_back(
            {double(i), std::make_shared<const texture::Normal>(normal_block(std::nullopt))});
        n.bump_size = 1;
        skip_comma();
      }
    } else if (t.kind == Token::Word && w == "bump_map") {
      // The image's grey (or palette index) as a height field over the pattern's space.
      next();
      std::vector<texture::PatternStep> steps = std::move(n.pattern.steps);
      n.pattern = texture::make_pattern(texture::PatternKind::kImage);
      n.pattern.steps = std::move(steps);
      n.pattern.image = image_map_block(w, &n.bump_size);
    } else if (t.kind == Token::Word && w == "average") {
      next();
      average = true;
      n.bump_size = 1;
    } else if (t.kind == Token::Word && w == "normal_map" && average) {
      next();
      n.average = normal_map_block();
    } else if (t.kind == Token::Word && w == "normal_map") {
      next();
      n.map = normal_map_block();
      n.bump_size = 1;
      std::stable_sort(n.map.begin(), n.map.end(),
                       [](const auto& a, const auto& b) { return a.weight < b.weight; });
    } else if (t.kind == Token::Word && w == "bump_size") {
      next();
      n.bump_size = number("bump_size");
    } else if (t.kind == Token::Word && pattern_modifier(w, n.pattern)) {
    } else if (t.kind == Token::Word && (w == "scale" || w == "translate" || w == "rotate" ||
                                         w == "matrix" || w == "transform")) {
      std::vector<XformOp> ops;
      transform_item(ops);
      if (const std::optional<Transform> x = pov_transform(ops)) texture::transform_normal(n, *x);
    } else if (t.kind == Token::Word && w == "accuracy") {
      next();
      number("accuracy");
    } else {
      // What the texture system does not model (slope_map, normal_map, bump_map, average,
      // pigment_pattern, facets ...): the normal is left flat and the rest of the block read.
      unsupported_warning(t.pos, "normal " + (t.kind == Token::Word ? w : std::string("items")),
                          "the normal is left flat");
      n.bump_size = 0;
      n.average.clear();
      n.map.clear();
      if (std::string_view(close) == "]") {
        skip_entry_rest();
      } else {
        skip_warp_rest();
      }
      return n;
    }
  }
  return n;
}

void Interpreter::move_texture(Texture& t, const std::vector<XformOp>& ops) {
  const std::optional<Transform> x = pov_transform(ops);
  if (!x) fail_here("the texture's matrix cannot be inverted");
  if (t.map) {
    auto moved = std::make_shared<TextureMap>(*t.map);
    texture::transform_pattern(moved->pattern, *x);
    for (Texture& e : moved->textures) move_texture(e, ops);
    t.map = std::move(moved);
  }
  move_pigment(t.pigment, ops, *x);
  if (t.normal) texture::transform_normal(*t.normal, *x);
  for (Texture& u : t.under) move_texture(u, ops);
}

void Interpreter::move_pigment(Pigment& p, const std::vector<XformOp>& ops, const Transform& x) {
  for (const XformOp& o : ops) {
    if (o.kind == XformOp::Scale && o.v.x == o.v.y && o.v.y == o.v.z && o.v.x > 0)
      p.scale *= o.v.x;
    else
      p.checker_plain = false;
  }
  if (!p.model) return;
  auto moved = std::make_shared<texture::Pigment>(*p.model);
  texture::transform_pigment(*moved, x);
  p.model = std::move(moved);
}

}  // namespace raycast::pov
