// The camera, light sources, global_settings, background and the scene's top level.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

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

// POV-Ray's look_at: turn direction towards the target, right = sky x direction, keeping every
// vector's length and the frame's handedness.
void turn_towards(Camera& c, const Vec3& target) {
  const double dl = length(c.direction), ul = length(c.up), rl = length(c.right);
  const double handed = dot(cross(c.up, c.direction), c.right);
  const Vec3 d = target - c.location;
  Vec3 r = cross(c.sky, d);
  // Looking straight along the sky: right stays as it was, made perpendicular to d.
  if (length(r) == 0) r = c.right - d * (dot(c.right, d) / dot(d, d));
  if (length(r) == 0) r = cross(Vec3{0, 0, 1}, d);
  if (length(r) == 0) r = cross(Vec3{1, 0, 0}, d);
  c.direction = d / length(d) * dl;
  c.right = r / length(r) * (handed > 0 ? rl : -rl);
  c.up = cross(d / length(d), r / length(r)) * ul;
}

// The projection keywords; cylinder's kind (1 to 4) is read by the caller.
const std::map<std::string, Camera::Kind>& camera_kinds() {
  static const std::map<std::string, Camera::Kind> kinds = {
      {"perspective", Camera::Perspective}, {"orthographic", Camera::Orthographic},
      {"fisheye", Camera::Fisheye},         {"ultra_wide_angle", Camera::UltraWideAngle},
      {"omnimax", Camera::Omnimax},         {"panoramic", Camera::Panoramic},
      {"cylinder", Camera::Cylinder},       {"spherical", Camera::Spherical}};
  return kinds;
}
}  // namespace

// Whether an angle was given: POV-Ray reads `angle 0` as none (the view stays as direction, up
// and right make it).
bool Interpreter::camera_angle(Camera& c, const Pos& at) {
  const double angle = number("angle");
  if (angle == 0) {
    if (accept_symbol(",") || numeric_ahead()) number("the vertical angle");
    return false;
  }
  c.angle = angle;
  const bool lens = c.kind != Camera::Perspective && c.kind != Camera::Orthographic;
  if (!(c.angle > 0 && c.angle <= 360)) fail_at(at, "angle must be in (0, 360] degrees");
  if (!lens && c.angle >= 179) {
    unsupported_warning(at, "camera angles of 179 degrees or more", "179 is used");
    c.angle = 179;
  }
  accept_symbol(",");
  if (numeric_ahead()) {
    c.vertical_angle = number("the vertical angle");
    if (!(c.vertical_angle > 0 && c.vertical_angle <= 360))
      fail_at(at, "the vertical angle must be in (0, 360] degrees");
  }
  return true;
}

// After the camera's items: `angle` sets the perspective direction's length from right's (the
// orthographic camera's right and up: the perspective view's size at the look_at distance).
void Interpreter::camera_finish(Camera& c, double look_distance, bool angle_given,
                                bool frame_given) {
  for (const Vec3& v : {c.direction, c.up, c.right})
    if (!(length(v) > 0)) fail_at(c.pos, "the camera's direction, up and right must be non-zero");
  if (!(length(cross(c.right, c.up)) > 0)) fail_at(c.pos, "the camera's right and up are parallel");
  const double half = std::tan(c.angle / kDegrees / 2);
  if (angle_given && c.kind == Camera::Perspective)
    c.direction = c.direction / length(c.direction) * (0.5 * length(c.right) / half);
  // An orthographic camera without its own up and right, or with an angle, sees what the
  // perspective camera of that angle sees at the look_at distance.
  if (c.kind == Camera::Orthographic && (angle_given || !frame_given)) {
    const double k = angle_given ? 2 * look_distance * half / length(c.right)
                                 : look_distance / length(c.direction);
    c.right = c.right * k;
    c.up = c.up * k;
  }
  // The lenses' angle when none is given: 90 degrees (spherical: 360 by 180).
  if (c.angle == 0 && c.kind != Camera::Perspective && c.kind != Camera::Orthographic)
    c.angle = c.kind == Camera::Spherical ? 360 : 90;
  if (c.kind == Camera::Omnimax)
    unsupported_warning(c.pos, "the omnimax camera", "a fisheye of 180 degrees is used");
}

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
  bool angle_given = false, frame_given = false;
  double look_distance = length(c.direction);
  while (!accept_symbol("}")) {
    const Token t = tok();
    const std::string& w = t.text;
    const auto kind = camera_kinds().find(w);
    if (kind != camera_kinds().end()) {
      next();
      c.kind = kind->second;
      if (w == "cylinder") {
        const double n = number("the cylinder camera's type");
        if (!(n == 1 || n == 2 || n == 3 || n == 4))
          fail_at(t.pos, "the cylinder camera's type must be 1, 2, 3 or 4");
        c.cylinder = static_cast<int>(n);
      }
    } else if (w == "location")
      next(), c.location = vector("location");
    else if (w == "direction")
      next(), c.direction = vector("direction");
    else if (w == "up")
      next(), c.up = vector("up"), frame_given = true;
    else if (w == "right")
      next(), c.right = vector("right"), frame_given = true;
    else if (w == "sky")
      next(), c.sky = vector("sky");
    else if (w == "angle")
      next(), angle_given = camera_angle(c, t.pos) || angle_given;
    else if (w == "look_at") {
      next();
      const Vec3 target = vector("look_at");
      if (length(target - c.location) == 0) fail_at(t.pos, "look_at is the camera's location");
      turn_towards(c, target);
      look_distance = length(target - c.location);
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
  camera_finish(c, look_distance, angle_given, frame_given);
  return c;
}

namespace {
// One transformation of a light: its points and its area's axes.
void transform_light(Light& l, const std::vector<XformOp>& ops) {
  for (const XformOp& o : ops) {
    l.position = apply(o, l.position, true);
    l.point_at = apply(o, l.point_at, true);
    l.axis1 = apply(o, l.axis1, false);
    l.axis2 = apply(o, l.axis2, false);
  }
}
}  // namespace

// A light_source item that is a number after its keyword; false when `w` is not one.
bool Interpreter::light_number(Light& l, const std::string& w) {
  double* target = w == "radius"          ? &l.radius
                   : w == "falloff"       ? &l.falloff
                   : w == "tightness"     ? &l.tightness
                   : w == "fade_distance" ? &l.fade_distance
                   : w == "fade_power"    ? &l.fade_power
                                          : nullptr;
  if (!target && w != "adaptive") return false;
  next();
  const double v = number(w.c_str());
  if (target)
    *target = v;
  else  // levels above 6 split past any grid of at most 64 points a side
    l.adaptive = static_cast<int>(std::clamp(v, 0.0, 6.0));
  return true;
}

void Interpreter::area_light_item(Light& l) {
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
    if (w == "spotlight") {
      next(), l.kind = Light::Spot;
    } else if (w == "cylinder") {
      next(), l.kind = Light::Cylinder;
      l.radius = 0.75, l.falloff = 1;
    } else if (w == "point_at") {
      next(), l.point_at = vector("point_at");
    } else if (w == "color" || w == "colour" || w == "rgb") {
      l.colour = colour("the light");
    } else if (light_number(l, w)) {
    } else if (w == "area_light") {
      area_light_item(l);
    } else if (w == "jitter" || w == "circular" || w == "orient" || w == "shadowless" ||
               w == "parallel") {
      next();
      bool& flag = w == "jitter"       ? l.jitter
                   : w == "circular"   ? l.circular
                   : w == "orient"     ? l.orient
                   : w == "shadowless" ? l.shadowless
                                       : l.parallel;
      flag = true;
    } else if (w == "media_interaction" || w == "media_attenuation" || w == "area_illumination") {
      next();
      boolean_option();
    } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
      next();
      unsupported_warning(t.pos, "light " + w);
      skip_block(w);
    } else {
      std::vector<XformOp> ops;
      if (!transform_item(ops)) unexpected("a light_source item");
      transform_light(l, ops);
    }
  }
  if (l.kind == Light::Spot) {
    l.falloff = std::clamp(l.falloff, 1e-3, 179.0);
    l.radius = std::clamp(l.radius, 0.0, l.falloff);
  } else if (l.kind == Light::Cylinder) {
    l.falloff = std::max(l.falloff, 1e-9);
    l.radius = std::clamp(l.radius, 0.0, l.falloff);
  }
  if (l.parallel && l.kind != Light::Point)
    unsupported_warning(l.pos, "parallel spotlights and cylinder lights",
                        "a parallel light without the cone is used");
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
    } else if (t.kind == Token::Word && w == "sky_sphere") {
      next();
      scene_.sky_sphere = sky_sphere_block();
    } else if (t.kind == Token::Word && w == "fog") {
      next();
      Fog f = fog_block();
      if (f.distance != 0) scene_.fogs.push_back(std::move(f));  // POV-Ray's "fog is off"
    } else if (t.kind == Token::Word && w == "rainbow") {
      next();
      scene_.rainbows.push_back(rainbow_block());
    } else if (t.kind == Token::Word && (w == "media" || w == "photons" || w == "radiosity")) {
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
