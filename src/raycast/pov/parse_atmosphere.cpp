// The atmosphere's blocks: sky_sphere and fog (docs/pov-import.md). Each is read into the scene
// description as written; pov_loader builds the engine's atmosphere from it.
#include "pov/interpreter.h"
#include "pov/pov_transform.h"

namespace raycast::pov {

namespace {

// A pigment as the texture system's model: its own when it has a pattern, else a solid colour.
texture::Pigment pigment_model(const Pigment& p) {
  if (p.model) return *p.model;
  texture::Pigment solid;
  solid.color = {{p.c0.r, p.c0.g, p.c0.b}, p.c0.filter, p.c0.transmit};
  return solid;
}

}  // namespace

SkySphere Interpreter::sky_sphere_block() {
  const Pos at = tok().pos;
  expect_symbol("{", "after sky_sphere");
  SkySphere sky;
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::SkySphere) {
      sky = *v->sky_sphere;
      next();
    }
  }
  Pigment black;
  black.c0 = {0, 0, 0, 0, 0};
  while (!accept_symbol("}")) {
    if (is_word("pigment")) {
      next();
      sky.pigments.push_back(pigment_model(pigment_block(black)));
    } else if (is_word("emission")) {
      next();
      sky.emission = colour("the sky_sphere's emission");
    } else if (!transform_item(sky.xforms)) {
      unexpected("pigment, emission or a transformation in sky_sphere");
    }
  }
  if (!pov_transform(sky.xforms)) fail_at(at, "the sky_sphere's matrix cannot be inverted");
  return sky;
}

Fog Interpreter::fog_block() {
  const Pos start = tok().pos;
  expect_symbol("{", "after fog");
  Fog fog;
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::Fog) {
      fog = *v->fog;
      next();
    }
  }
  // turbulence, octaves, omega and lambda as a pattern reads them.
  texture::Pattern turbulence;
  turbulence.turbulence = fog.turbulence;
  while (!accept_symbol("}")) {
    const Pos at = tok().pos;
    if (is_word("fog_type")) {
      next();
      const double type = number("fog_type");
      if (type != 1 && type != 2) fail_at(at, "fog_type is 1 (constant) or 2 (ground fog)");
      fog.type = int(type);
    } else if (is_word("distance")) {
      next();
      fog.distance = number("the fog's distance");
      if (fog.distance < 0) fail_at(at, "the fog's distance must be at least 0");
    } else if (is_word("fog_offset")) {
      next(), fog.offset = number("fog_offset");
    } else if (is_word("fog_alt")) {
      next(), fog.alt = number("fog_alt");
    } else if (is_word("turb_depth")) {
      next(), fog.turb_depth = number("turb_depth");
    } else if (is_word("up")) {
      next();
      fog.up = vector("the fog's up");
      if (!(length(fog.up) > 0)) fail_at(at, "the fog's up vector has length 0");
    } else if (is_word("turbulence") || is_word("octaves") || is_word("omega") ||
               is_word("lambda")) {
      const std::string w = tok().text;  // the token changes under pattern_modifier
      pattern_modifier(w, turbulence);
    } else if (transform_item(fog.xforms)) {
    } else if (starts_colour()) {
      fog.colour = colour("fog");
    } else {
      unexpected("a fog item (fog_type, distance, a colour, fog_offset, fog_alt, turbulence ...)");
    }
  }
  fog.turbulence = turbulence.turbulence;
  if (!pov_transform(fog.xforms)) fail_at(start, "the fog's matrix cannot be inverted");
  return fog;
}

Rainbow Interpreter::rainbow_block() {
  const Pos start = tok().pos;
  expect_symbol("{", "after rainbow");
  Rainbow r;
  bool falloff_given = false;
  while (!accept_symbol("}")) {
    const Pos at = tok().pos;
    if (is_word("direction")) {
      next();
      r.direction = vector("the rainbow's direction");
      if (!(length(r.direction) > 0)) fail_at(at, "the rainbow's direction has length 0");
    } else if (is_word("up")) {
      next();
      r.up = vector("the rainbow's up");
      if (!(length(r.up) > 0)) fail_at(at, "the rainbow's up vector has length 0");
    } else if (is_word("angle")) {
      next(), r.angle = number("the rainbow's angle");
    } else if (is_word("width")) {
      next(), r.width = number("the rainbow's width");
    } else if (is_word("distance")) {
      next(), r.distance = number("the rainbow's distance");
    } else if (is_word("jitter")) {
      next(), r.jitter = number("the rainbow's jitter");
    } else if (is_word("arc_angle")) {
      next(), r.arc_angle = number("arc_angle");
    } else if (is_word("falloff_angle")) {
      next(), r.falloff_angle = number("falloff_angle");
      falloff_given = true;
    } else if (is_word("color_map") || is_word("colour_map")) {
      next();
      r.map = colour_map_block();
    } else {
      unexpected("a rainbow item (direction, angle, width, distance, color_map, jitter, up ...)");
    }
  }
  if (!(r.width > 0)) fail_at(start, "the rainbow needs a width above 0");
  if (!(r.distance > 0)) fail_at(start, "the rainbow's distance must be above 0");
  if (!falloff_given || r.falloff_angle > r.arc_angle) r.falloff_angle = r.arc_angle;
  return r;
}

}  // namespace raycast::pov
