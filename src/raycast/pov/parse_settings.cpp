// The camera, light sources, global_settings, background and the scene's top level.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pov/interpreter.h"

namespace raycast::pov {

namespace {
constexpr double kDegrees = 180 / std::numbers::pi;

// One transformation step applied to a point (is_point) or a direction, in POV-Ray's frame.
Vec3 apply(const XformOp& o, const Vec3& p, bool is_point) {
  switch (o.kind) {
    case XformOp::Translate:
      return is_point ? p + o.v : p;
    case XformOp::Scale:
      return {p.x * o.v.x, p.y * o.v.y, p.z * o.v.z};
    case XformOp::Rotate: {
      Vec3 q = p;
      const double a = o.v.x / kDegrees, b = o.v.y / kDegrees, c = o.v.z / kDegrees;
      q = {q.x, q.y * std::cos(a) - q.z * std::sin(a), q.y * std::sin(a) + q.z * std::cos(a)};
      q = {q.x * std::cos(b) + q.z * std::sin(b), q.y, -q.x * std::sin(b) + q.z * std::cos(b)};
      q = {q.x * std::cos(c) - q.y * std::sin(c), q.x * std::sin(c) + q.y * std::cos(c), q.z};
      return q;
    }
    case XformOp::Matrix: {
      const auto& m = o.m;
      Vec3 q{p.x * m[0] + p.y * m[3] + p.z * m[6], p.x * m[1] + p.y * m[4] + p.z * m[7],
             p.x * m[2] + p.y * m[5] + p.z * m[8]};
      if (is_point) q = q + Vec3{m[9], m[10], m[11]};
      return q;
    }
  }
  return p;
}
}  // namespace

Camera Interpreter::camera_block(const Camera& base) {
  Camera c = base;
  c.pos = tok().pos;
  c.given = true;
  expect_symbol("{", "after camera");
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::Camera) {
      c = *v->camera;
      next();
    }
  }
  double angle = 0;
  while (!accept_symbol("}")) {
    const Token t = tok();
    const std::string& w = t.text;
    if (w == "perspective")
      next(), c.orthographic = false;
    else if (w == "orthographic")
      next(), c.orthographic = true;
    else if (w == "fisheye" || w == "ultra_wide_angle" || w == "omnimax" || w == "panoramic" ||
             w == "spherical" || w == "cylinder") {
      next();
      if (w == "cylinder") number("the cylinder camera's type");
      unsupported_warning(t.pos, "the " + w + " camera", "a perspective camera is used");
    } else if (w == "location")
      next(), c.location = vector("location");
    else if (w == "direction")
      next(), c.direction = vector("direction");
    else if (w == "up")
      next(), c.up = vector("up");
    else if (w == "right")
      next(), c.right = vector("right");
    else if (w == "sky")
      next(), c.sky = vector("sky");
    else if (w == "angle") {
      next();
      angle = number("angle");
      if (!(angle > 0 && angle <= 360)) fail_at(t.pos, "angle must be in (0, 360] degrees");
      if (angle >= 179) {
        unsupported_warning(t.pos, "camera angles of 179 degrees or more", "179 is used");
        angle = 179;
      }
      accept_symbol(",");
      if (numeric_ahead()) number("the vertical angle");
    } else if (w == "look_at") {
      next();
      const Vec3 target = vector("look_at");
      // POV-Ray's look_at: turn direction towards the target, right = sky x direction, keeping
      // every vector's length and the frame's handedness.
      const double dl = length(c.direction), ul = length(c.up), rl = length(c.right);
      const double handed = dot(cross(c.up, c.direction), c.right);
      const Vec3 d = target - c.location;
      Vec3 r = cross(c.sky, d);
      if (length(d) == 0) fail_at(t.pos, "look_at is the camera's location");
      // Looking straight along the sky: right stays as it was, made perpendicular to d.
      if (length(r) == 0) r = c.right - d * (dot(c.right, d) / dot(d, d));
      if (length(r) == 0) r = cross(Vec3{0, 0, 1}, d);
      if (length(r) == 0) r = cross(Vec3{1, 0, 0}, d);
      c.direction = d / length(d) * dl;
      c.right = r / length(r) * (handed > 0 ? rl : -rl);
      c.up = cross(d / length(d), r / length(r)) * ul;
    } else if (w == "focal_point" || w == "aperture" || w == "blur_samples" || w == "confidence" ||
               w == "variance") {
      next();
      expression();
      if (accept_symbol(",")) expression();
      unsupported_warning(t.pos, "focal blur", "the camera is a pinhole");
    } else if (w == "normal") {
      next();
      skip_block("normal");
      unsupported_warning(t.pos, "camera normal perturbation");
    } else {
      std::vector<XformOp> ops;
      if (!transform_item(ops))
        unexpected("a camera item (location, look_at, angle, up, right, direction, sky ...)");
      for (const XformOp& o : ops) {
        c.location = apply(o, c.location, true);
        c.direction = apply(o, c.direction, false);
        c.up = apply(o, c.up, false);
        c.right = apply(o, c.right, false);
      }
    }
  }
  for (const Vec3& v : {c.direction, c.up, c.right})
    if (!(length(v) > 0)) fail_at(c.pos, "the camera's direction, up and right must be non-zero");
  if (angle > 0 && !c.orthographic)
    c.direction = c.direction / length(c.direction) *
                  (0.5 * length(c.right) / std::tan(angle / kDegrees / 2));
  c.angle = angle;
  return c;
}

Node Interpreter::light_block() {
  Light l;
  l.pos = tok().pos;
  next();
  expect_symbol("{", "after light_source");
  bool declared_light = false;
  if (tok().kind == Token::Word) {
    const Value* v = lookup(tok().text);
    if (v && v->kind == Value::Object && v->object && v->object->light) {
      l = *v->object->light;
      next();
      declared_light = true;
    }
  }
  if (!declared_light && !is_symbol("}")) {
    l.position = vector("the light's position");
    skip_comma();
  }
  if (starts_colour()) l.colour = colour("the light");
  while (!accept_symbol("}")) {
    const Token t = tok();
    const std::string& w = t.text;
    if (w == "spotlight")
      next(), l.kind = Light::Spot;
    else if (w == "point_at")
      next(), l.point_at = vector("point_at");
    else if (w == "radius")
      next(), l.radius = number("radius");
    else if (w == "falloff")
      next(), l.falloff = number("falloff");
    else if (w == "color" || w == "colour" || w == "rgb")
      l.colour = colour("the light");
    else if (w == "tightness") {
      next();
      if (number("tightness") != 0) unsupported_warning(t.pos, "spotlight tightness");
    } else if (w == "area_light") {
      next();
      l.area = true;
      l.axis1 = vector("area_light");
      skip_comma();
      l.axis2 = vector("area_light");
      skip_comma();
      const double n1 = number("area_light");
      skip_comma();
      const double n2 = number("area_light");
      l.size1 = static_cast<int>(std::clamp(n1, 1.0, 64.0));
      l.size2 = static_cast<int>(std::clamp(n2, 1.0, 64.0));
    } else if (w == "adaptive" || w == "fade_distance" || w == "fade_power") {
      next();
      number(w.c_str());
      if (w != "adaptive") unsupported_warning(t.pos, "light " + w);
    } else if (w == "jitter" || w == "circular" || w == "orient" || w == "shadowless" ||
               w == "media_interaction" || w == "media_attenuation" || w == "parallel" ||
               w == "cylinder") {
      next();
      if (w == "media_interaction" || w == "media_attenuation") boolean_option();
      if (w == "shadowless" || w == "parallel" || w == "cylinder")
        unsupported_warning(t.pos, "the " + w + " light", "a point light is used");
    } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
      next();
      unsupported_warning(t.pos, "light " + w);
      skip_block(w);
    } else {
      std::vector<XformOp> ops;
      if (!transform_item(ops)) unexpected("a light_source item");
      for (const XformOp& o : ops) {
        l.position = apply(o, l.position, true);
        l.point_at = apply(o, l.point_at, true);
      }
    }
  }
  if (l.kind == Light::Spot) {
    l.falloff = std::clamp(l.falloff, 1e-3, 179.0);
    l.radius = std::clamp(l.radius, 0.0, l.falloff);
  }
  Node n;
  n.kind = Node::LightSource;
  n.pos = l.pos;
  n.light = l;
  return n;
}

void Interpreter::global_settings_block() {
  next();
  expect_symbol("{", "after global_settings");
  while (!accept_symbol("}")) {
    const Token t = tok();
    const std::string& w = t.text;
    if (w == "max_trace_level") {
      next();
      const double n = number("max_trace_level");
      scene_.max_trace_level = static_cast<int>(std::clamp(n, 1.0, 256.0));
    } else if (w == "assumed_gamma") {
      next();
      scene_.settings.gamma_given = true;
      if (is_word("srgb")) {
        next();
        scene_.settings.assumed_gamma = 0;
      } else {
        scene_.settings.assumed_gamma = number("assumed_gamma");
      }
    } else if (w == "ambient_light") {
      next();
      scene_.ambient_light = colour("ambient_light");
    } else if (w == "adc_bailout") {
      next();
      scene_.adc_bailout = std::clamp(number("adc_bailout"), 0.0, 1.0);
    } else if (w == "charset") {
      next();
      tok();
      next();
    } else if (w == "number_of_waves" || w == "noise_generator" || w == "max_intersections" ||
               w == "irid_wavelength" || w == "hf_gray_16") {
      next();
      if (w == "irid_wavelength")
        colour("irid_wavelength");
      else if (w != "hf_gray_16" || starts_colour())
        number(w.c_str());
    } else if (w == "radiosity" || w == "photons" || w == "subsurface" || w == "mm_per_unit") {
      next();
      unsupported_warning(t.pos, w);
      if (w == "mm_per_unit")
        number(w.c_str());
      else
        skip_block(w);
    } else {
      unexpected(
          "a global setting (assumed_gamma, max_trace_level, ambient_light, adc_bailout ...)");
    }
  }
}

PovScene Interpreter::run() {
  default_texture_.pigment.c0 = {0, 0, 0, 0, 0};  // POV-Ray's default: black
  for (;;) {
    const Token t = tok();
    if (t.kind == Token::End) break;
    const std::string& w = t.text;
    if (t.kind == Token::Word && w == "camera") {
      next();
      scene_.camera = camera_block(scene_.camera);
    } else if (t.kind == Token::Word && w == "light_source") {
      scene_.objects.push_back(light_block());
    } else if (t.kind == Token::Word && w == "global_settings") {
      global_settings_block();
    } else if (t.kind == Token::Word && w == "background") {
      next();
      expect_symbol("{", "after background");
      scene_.background = colour("background");
      expect_symbol("}", "to close background");
    } else if (t.kind == Token::Word && (w == "fog" || w == "rainbow" || w == "sky_sphere" ||
                                         w == "media" || w == "photons" || w == "radiosity")) {
      next();
      unsupported_warning(t.pos, w);
      skip_block(w);
    } else if (t.kind == Token::Word && (is_object_keyword() || is_declared_object())) {
      std::optional<Node> n = is_object_keyword() ? object(0) : bare_declared_object();
      if (n) {
        if (!n->texture && n->kind != Node::LightSource) n->texture = default_texture_;
        scene_.objects.push_back(std::move(*n));
      }
    } else if (pov::is_symbol(t, ";")) {
      next();
    } else {
      unexpected(
          "a scene item (camera, light_source, an object, global_settings, background, a "
          "directive)");
    }
  }
  return std::move(scene_);
}

PovScene interpret_pov(const std::string& text, const std::string& name, const std::string& dir,
                       const Options& options) {
  Interpreter in(text, name, dir, options);
  return in.run();
}

}  // namespace raycast::pov
