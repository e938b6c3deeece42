#include "load/pov_textures.h"

#include <algorithm>

namespace raycast {

namespace {

bool plain_checker(const pov::Pigment& p) {
  return p.checker && p.checker_plain && p.model &&
         p.model->kind == texture::Pigment::Kind::kColorMap;
}

bool plain_finish(const pov::Finish& f) {
  return f.brilliance == 1 && f.metallic == 0 && f.crand == 0 && !f.reflection_metallic &&
         f.reflection_min == f.reflection_max;
}

}  // namespace

bool needs_texture_system(const pov::Texture& t) {
  // A clear pigment with Fresnel reflection is the plain path's Fresnel split between the
  // mirror and the refracted ray.
  const bool clear = !t.pigment.model && t.pigment.c0.filter + t.pigment.c0.transmit > 0;
  const bool fresnel_glass = clear && t.finish.fresnel;
  return t.map || (t.pigment.model && !plain_checker(t.pigment)) ||
         (t.normal && t.normal->bump_size != 0) || !t.under.empty() ||
         (!plain_finish(t.finish) && !fresnel_glass);
}

texture::Rgbft PovTextureBuilder::colour(const texture::Rgbft& c) const {
  return {{linear_(c.rgb.x), linear_(c.rgb.y), linear_(c.rgb.z)}, c.filter, c.transmit};
}

std::shared_ptr<const texture::Pigment> PovTextureBuilder::pigment(const texture::Pigment& p,
                                                                   int depth) {
  const auto found = pigments_.find(&p);
  if (found != pigments_.end()) return found->second;
  auto out = std::make_shared<texture::Pigment>(p);
  out->color = colour(p.color);
  for (texture::ColorMapEntry& e : out->color_map) e.color = colour(e.color);
  // Maps hold finished pigments, so the nesting is as deep as the scene wrote it; the bound
  // keeps a pathological scene from exhausting the stack.
  for (texture::PigmentMapEntry& e : out->pigment_map)
    if (e.pigment && depth < 64) e.pigment = pigment(*e.pigment, depth + 1);
  pigments_[&p] = out;
  return out;
}

texture::TextureLayer PovTextureBuilder::layer(const pov::Texture& t) {
  texture::TextureLayer l;
  if (t.pigment.model)
    l.pigment = *pigment(*t.pigment.model, 0);
  else
    l.pigment.color = colour({{t.pigment.c0.r, t.pigment.c0.g, t.pigment.c0.b},
                              t.pigment.c0.filter,
                              t.pigment.c0.transmit});
  if (t.normal && t.normal->bump_size != 0) l.normal = t.normal;
  const pov::Finish& f = t.finish;
  texture::Finish& o = l.finish;
  o.ambient = f.ambient;
  o.diffuse = f.diffuse;
  o.brilliance = f.brilliance;
  o.phong = f.phong;
  o.phong_size = f.phong_size;
  o.specular = f.specular;
  o.roughness = std::max(f.roughness, 1e-6);
  o.metallic = f.metallic;
  o.reflection_min = std::min(1.0, f.reflection_min);
  o.reflection_max = std::min(1.0, f.reflection_max);
  o.reflection_fresnel = f.fresnel;
  o.reflection_falloff = f.reflection_falloff;
  o.reflection_metallic = f.reflection_metallic;
  o.crand = f.crand;
  return l;
}

std::shared_ptr<const texture::TextureStack> PovTextureBuilder::stack(const pov::Texture& t,
                                                                      int depth) {
  auto s = std::make_shared<texture::TextureStack>();
  // A patterned texture is the map under the layers when it is the bottom one (or alone); a
  // patterned layer higher up is drawn as its first texture (the nesting bound of the
  // interpreter also bounds `depth`; the check keeps a hand-built description safe).
  auto add = [&](const pov::Texture& u, bool bottom) {
    if (u.map && bottom && depth < 64) {
      s->map_pattern = u.map->pattern;
      s->average = u.map->average;
      for (std::size_t i = 0; i < u.map->textures.size(); ++i)
        s->map.push_back({u.map->at[i], stack(u.map->textures[i], depth + 1)});
    } else {
      s->layers.push_back(layer(u));
    }
  };
  for (std::size_t i = 0; i < t.under.size(); ++i) add(t.under[i], i == 0);
  add(t, t.under.empty());
  return s;
}

}  // namespace raycast
