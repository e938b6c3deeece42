#include "load/read_atmosphere.h"

#include <algorithm>

#include "load/read_textures.h"

namespace raycast {

namespace {

// {pigments: [PIGMENT, ...] (bottom first) or pigment: PIGMENT, emission, transform}.
SkySphere read_sky(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "render.sky_sphere");
  SkySphere sky;
  if (f.has("pigment") == f.has("pigments"))
    fail_at(ctx, node, "render.sky_sphere needs one of pigment or pigments");
  if (f.has("pigment")) {
    sky.layers.push_back(read_pigment(ctx, f.required("pigment")));
  } else {
    const YamlNode list = f.required("pigments");
    if (!list.IsSequence() || list.size() == 0)
      fail_at(ctx, list, "render.sky_sphere.pigments must be a list of pigments, bottom first");
    for (const YamlNode& p : list) sky.layers.push_back(read_pigment(ctx, p));
  }
  sky.emission = f.vec3("emission", sky.emission);
  if (f.has("transform")) sky.to_sky = read_transform(ctx, f.required("transform")).inverse();
  f.finish();
  return sky;
}

// {type: constant | ground, color: [r, g, b, filter?, transmit?], distance, offset, alt, up,
// turbulence, turb_depth, octaves, omega, lambda, transform}.
Fog read_fog(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "render.fog");
  Fog fog;
  const std::string type = f.string("type", "constant");
  if (type == "ground")
    fog.kind = Fog::Kind::kGround;
  else if (type != "constant")
    f.fail("type", "render.fog.type must be constant or ground, got " + type);
  const YamlNode c = f.required("color");
  const std::vector<double> v = read_numbers(ctx, c, f.name("color"));
  if (v.size() < 3 || v.size() > 5)
    fail_at(ctx, c,
            "render.fog.color must be [r, g, b], [r, g, b, filter] or [r, g, b, filter, transmit]");
  fog.color = {v[0], v[1], v[2]};
  fog.filter = v.size() > 3 ? v[3] : 0;
  fog.transmit = v.size() > 4 ? v[4] : 0;
  fog.distance = f.positive("distance");
  fog.offset = f.number("offset", fog.offset);
  fog.alt = f.non_negative("alt", fog.alt);
  fog.up = normalize(f.direction("up", fog.up));
  if (f.has("turbulence")) {
    const YamlNode t = f.required("turbulence");
    fog.turbulence.amount = t.IsSequence()
                                ? read_vec3(ctx, t, f.name("turbulence"))
                                : Vec3{1, 1, 1} * read_number(ctx, t, f.name("turbulence"));
  }
  fog.turb_depth = f.number("turb_depth", fog.turb_depth);
  fog.turbulence.octaves = f.integer("octaves", fog.turbulence.octaves, 1, 10);
  fog.turbulence.omega = f.number("omega", fog.turbulence.omega);
  fog.turbulence.lambda = f.number("lambda", fog.turbulence.lambda);
  if (f.has("transform")) fog.to_fog = read_transform(ctx, f.required("transform")).inverse();
  f.finish();
  return fog;
}

// [r, g, b, filter?, transmit?].
texture::Rgbft read_colour(const SourceContext& ctx, const YamlNode& node,
                           const std::string& what) {
  const std::vector<double> v = read_numbers(ctx, node, what);
  if (v.size() < 3 || v.size() > 5)
    fail_at(ctx, node,
            what + " must be [r, g, b], [r, g, b, filter] or [r, g, b, filter, transmit]");
  return {{v[0], v[1], v[2]}, v.size() > 3 ? v[3] : 0, v.size() > 4 ? v[4] : 0};
}

// {direction, angle, width, distance, colors: [[v, colour], ...], jitter, up, arc_angle,
// falloff_angle}.
Rainbow read_rainbow(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "render.rainbow");
  Rainbow r;
  r.direction = normalize(f.direction("direction"));
  r.angle = f.number("angle");
  r.width = f.positive("width");
  r.distance = f.positive("distance", r.distance);
  r.jitter = f.non_negative("jitter", r.jitter);
  r.up = f.direction("up", r.up);
  r.arc_angle = f.positive("arc_angle", r.arc_angle);
  r.falloff_angle = std::min(r.arc_angle, f.non_negative("falloff_angle", r.arc_angle));
  const YamlNode colors = f.required("colors");
  if (!colors.IsSequence() || colors.size() == 0 || colors.size() > texture::kMaxMapEntries)
    fail_at(ctx, colors,
            "render.rainbow.colors must be a list of 1 to 256 [value, colour] entries");
  for (const YamlNode& e : colors) {
    if (!e.IsSequence() || e.size() != 2)
      fail_at(ctx, e, "render.rainbow.colors entries are [value, [r, g, b, filter?, transmit?]]");
    const double at = read_number(ctx, e[0], "render.rainbow.colors");
    if (!r.colors.empty() && at < r.colors.back().at)
      fail_at(ctx, e, "render.rainbow.colors must be sorted by value");
    r.colors.push_back({at, read_colour(ctx, e[1], "render.rainbow.colors")});
  }
  f.finish();
  return r;
}

}  // namespace

std::shared_ptr<const Atmosphere> read_atmosphere(Fields& render) {
  if (!render.has("sky_sphere") && !render.has("fog") && !render.has("rainbow")) return nullptr;
  const SourceContext& ctx = render.ctx();
  auto a = std::make_shared<Atmosphere>();
  if (render.has("sky_sphere")) a->sky = read_sky(ctx, render.required("sky_sphere"));
  if (render.has("fog")) {
    // One fog as a mapping, several as a list of them.
    const YamlNode fogs = render.required("fog");
    if (fogs.IsSequence())
      for (const YamlNode& one : fogs) a->fogs.push_back(read_fog(ctx, one));
    else
      a->fogs.push_back(read_fog(ctx, fogs));
  }
  if (render.has("rainbow")) {
    const YamlNode rainbows = render.required("rainbow");
    if (rainbows.IsSequence())
      for (const YamlNode& one : rainbows) a->rainbows.push_back(read_rainbow(ctx, one));
    else
      a->rainbows.push_back(read_rainbow(ctx, rainbows));
  }
  return a;
}

}  // namespace raycast
