#include "load/read_materials.h"

#include <filesystem>

#include "io/image.h"
#include "load/read_settings.h"
#include "load/read_textures.h"

namespace raycast {

namespace {

double unit_fraction(Fields& f, const std::string& key, double fallback) {
  const double v = f.non_negative(key, fallback);
  if (v > 1) f.fail(key, f.name(key) + " must be in [0, 1], got " + std::to_string(v));
  return v;
}

Attenuation read_attenuation(Fields& f, Light& light) {
  const std::string a = f.string("attenuation", "none");
  if (a == "none") return Attenuation::kNone;
  if (a == "inverse_square") return Attenuation::kInverseSquare;
  if (a == "fade") {
    light.fade_distance = f.positive("fade_distance", light.fade_distance);
    light.fade_power = f.non_negative("fade_power", light.fade_power);
    return Attenuation::kFade;
  }
  f.fail("attenuation", "light.attenuation must be none, inverse_square or fade, got " + a);
}

// A spot cone's keys (spot lights, area lights with a direction).
void read_spot_cone(Fields& f, Light& light) {
  light.direction = normalize(f.direction("direction"));
  light.angle = f.number("angle", light.angle);
  if (!(light.angle > 0 && light.angle < 180)) f.fail("angle", "light.angle must be in (0, 180)");
  light.falloff = f.non_negative("falloff", light.falloff);
  light.tightness = f.non_negative("tightness", light.tightness);
  const std::string edge = f.string("edge", "angle");
  if (edge == "cosine")
    light.edge = SpotEdge::kCosine;
  else if (edge != "angle")
    f.fail("edge", "light.edge must be angle or cosine, got " + edge);
}

// An area light's grid (docs/scene-format.md "Lights").
void read_area(Fields& f, Light& light) {
  light.position = f.vec3("position");
  light.axis1 = f.vec3("axis1");
  light.axis2 = f.vec3("axis2");
  light.size1 = f.integer("size1", light.size1, 1, 64);
  light.size2 = f.integer("size2", light.size2, 1, 64);
  light.adaptive = f.integer("adaptive", light.adaptive, -1, 6);
  light.jitter = f.boolean("jitter", light.jitter);
  light.circular = f.boolean("circular", light.circular);
  light.orient = f.boolean("orient", light.orient);
  light.attenuation = read_attenuation(f, light);
  light.spot = f.has("direction");
  if (light.spot) read_spot_cone(f, light);
}

// A data file's path as written, relative to the scene file's folder unless absolute.
std::string resolve(const SourceContext& ctx, const std::string& path) {
  const std::filesystem::path p(path);
  return p.is_absolute() ? path : (std::filesystem::path(ctx.dir) / p).string();
}

}  // namespace

Material read_material(const SourceContext& ctx, const YamlNode& node, const std::string& name) {
  Fields f(ctx, node, "material");
  Material m;
  m.name = name;
  if (f.has("color") && f.has("texture")) f.fail("texture", "material has both color and texture");
  m.color = read_color(f, "color", m.color);
  const bool textured = wants_texture(node);
  if (f.has("texture") && !textured) {
    Fields t(ctx, f.required("texture"), "texture");
    if (t.has("checker")) {
      Fields c(ctx, t.required("checker"), "checker");
      const YamlNode colors = c.required("colors");
      if (!colors.IsSequence() || colors.size() != 2)
        fail_at(ctx, colors, "checker.colors must be a list of 2 colours");
      m.has_checker = true;
      m.checker.c0 = read_vec3(ctx, colors[0], "checker.colors[0]");
      m.checker.c1 = read_vec3(ctx, colors[1], "checker.colors[1]");
      m.checker.scale = c.positive("scale", 1.0);
      c.finish();
    } else if (t.has("image")) {
      Fields i(ctx, t.required("image"), "image");
      m.image_file = resolve(ctx, i.string("file"));
      if (ctx.files) ctx.files->push_back(m.image_file);
      // Read now, so that a missing or bad file is an error at its position in every command.
      try {
        m.image = load_image_texture(m.image_file);
      } catch (const ImageError& e) {
        fail_at(ctx, i.required("file"), std::string("texture image: ") + e.what());
      }
      i.finish();
    } else {
      fail_at(ctx, t.node(), "texture must be checker or image");
    }
    t.finish();
  }
  m.ambient = f.non_negative("ambient", m.ambient);
  m.diffuse = f.non_negative("diffuse", m.diffuse);
  m.specular = f.non_negative("specular", m.specular);
  m.shininess = f.non_negative("shininess", m.shininess);
  m.reflection = unit_fraction(f, "reflection", m.reflection);
  m.transmission = unit_fraction(f, "transmission", m.transmission);
  m.ior = f.positive("ior", m.ior);
  m.fresnel = f.boolean("fresnel", m.fresnel);
  m.dispersion = f.positive("dispersion", m.dispersion);
  m.dispersion_samples = f.integer("dispersion_samples", m.dispersion_samples, 2, 64);
  m.fade_distance = f.non_negative("fade_distance", m.fade_distance);
  m.fade_power = f.non_negative("fade_power", m.fade_power);
  m.fade_color = read_color(f, "fade_color", m.fade_color);
  if (textured) read_texture_keys(f, m);
  f.finish();
  return m;
}

Light read_light(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "light");
  Light light;
  const std::string type = f.string("type");
  light.color = read_color(f, "color", light.color);
  light.intensity = f.non_negative("intensity", light.intensity);
  light.shadows = f.boolean("shadows", light.shadows);
  if (type == "point" || type == "spot") {
    light.type = type == "point" ? LightType::kPoint : LightType::kSpot;
    light.position = f.vec3("position");
    light.attenuation = read_attenuation(f, light);
    if (type == "spot") read_spot_cone(f, light);
  } else if (type == "directional") {
    light.type = LightType::kDirectional;
    light.direction = normalize(f.direction("direction"));
    light.bounded = f.has("position");
    light.position = f.vec3("position", light.position);
    if (light.bounded) light.attenuation = read_attenuation(f, light);
  } else if (type == "sphere") {
    light.type = LightType::kSphere;
    light.position = f.vec3("center");
    light.radius = f.positive("radius");
    light.samples = f.integer("samples", light.samples, 1, 4096);
    light.attenuation = read_attenuation(f, light);
  } else if (type == "cylinder") {
    light.type = LightType::kCylinder;
    light.position = f.vec3("position");
    light.direction = normalize(f.direction("direction"));
    light.angle = f.positive("radius");
    light.falloff = f.non_negative("falloff", 0);
    if (light.falloff > light.angle) f.fail("falloff", "light.falloff must be at most radius");
    light.attenuation = read_attenuation(f, light);
  } else if (type == "area") {
    light.type = LightType::kArea;
    read_area(f, light);
  } else {
    f.fail("type",
           "light.type must be point, directional, spot, sphere, cylinder or area, got " + type);
  }
  f.finish();
  return light;
}

}  // namespace raycast
