#include "texture/texture_stack.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace raycast::texture {

namespace {

double average(const Vec3& c) { return (c.x + c.y + c.z) / 3; }

// A value in [0, 1) that changes from point to point with no pattern (crand's grain).
double grain(const Vec3& p) {
  auto bits = [](double v) {
    std::uint64_t u = 0;
    static_assert(sizeof(u) == sizeof(v));
    __builtin_memcpy(&u, &v, sizeof(u));
    return u;
  };
  std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ULL ^ bits(p.y) * 0xC2B2AE3D27D4EB4FULL ^
                    bits(p.z) * 0x165667B19E3779F9ULL;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ULL;
  h ^= h >> 29;
  return double(h >> 11) * (1.0 / double(1ULL << 53));
}

// The highlight and reflection terms of a layer seen through `vis` of the layers above, added
// to the sums; the layer with the largest highlight gives the sizes.
void add_finish(const Finish& f, double vis, Finish& sum, double& strongest) {
  sum.phong += vis * f.phong;
  sum.specular += vis * f.specular;
  sum.reflection_min += vis * f.reflection_min;
  sum.reflection_max += vis * f.reflection_max;
  sum.crand += vis * f.crand;
  const double highlight = vis * (f.phong + f.specular + f.reflection_max);
  if (highlight > strongest || strongest < 0) {
    strongest = highlight;
    sum.phong_size = f.phong_size;
    sum.roughness = f.roughness;
    sum.metallic = f.metallic;
    sum.reflection_fresnel = f.reflection_fresnel;
    sum.reflection_falloff = f.reflection_falloff;
    sum.reflection_metallic = f.reflection_metallic;
  }
}

}  // namespace

void transform_normal(Normal& normal, const Transform& t) {
  transform_pattern(normal.pattern, t);
  for (std::vector<NormalMapEntry>* list : {&normal.average, &normal.map})
    for (NormalMapEntry& e : *list) {
      if (!e.normal) continue;
      auto moved = std::make_shared<Normal>(*e.normal);
      transform_normal(*moved, t);
      e.normal = std::move(moved);
    }
}

void transform_layer(TextureLayer& layer, const Transform& t) {
  transform_pigment(layer.pigment, t);
  if (layer.normal) transform_normal(*layer.normal, t);
}

bool TextureStack::may_transmit() const {
  // The stack lets light through only where every layer does (and the map under them).
  const bool layers_do = std::all_of(layers.begin(), layers.end(), [](const TextureLayer& l) {
    return texture::may_transmit(l.pigment);
  });
  if (map_pattern)
    return layers_do && std::any_of(map.begin(), map.end(), [](const TextureMapEntry& e) {
             return e.texture && e.texture->may_transmit();
           });
  return !layers.empty() && layers_do;
}

bool TextureStack::has_normal() const {
  return std::any_of(layers.begin(), layers.end(),
                     [](const TextureLayer& l) { return l.normal.has_value(); }) ||
         std::any_of(map.begin(), map.end(),
                     [](const TextureMapEntry& e) { return e.texture && e.texture->has_normal(); });
}

namespace {

// The map's entries around the pattern's value at p: a block pattern's entry k alone, else the
// two neighbours and the weight of the second (a colour map's rule). Null entries when none.
struct MapPick {
  const TextureStack* a = nullptr;
  const TextureStack* b = nullptr;
  double t = 0;
};
MapPick pick(const TextureStack& texture, const Vec3& p) {
  const std::vector<TextureMapEntry>& map = texture.map;
  if (map.empty()) return {};
  const double v = evaluate(*texture.map_pattern, p);
  const int blocks = block_count(texture.map_pattern->kind);
  if (blocks > 0) {
    const auto k =
        std::size_t(std::clamp(std::lround(v * double(blocks - 1)), 0L, long(map.size()) - 1));
    return {map[k].texture.get(), nullptr, 0};
  }
  if (!(v > map.front().at)) return {map.front().texture.get(), nullptr, 0};
  if (v >= map.back().at) return {map.back().texture.get(), nullptr, 0};
  std::size_t i = 1;
  while (map[i].at <= v) ++i;
  const double span = map[i].at - map[i - 1].at;
  if (!(span > 0)) return {map[i].texture.get(), nullptr, 0};
  return {map[i - 1].texture.get(), map[i].texture.get(), (v - map[i - 1].at) / span};
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + t * (b - a); }

SurfaceLook blend(const SurfaceLook& a, const SurfaceLook& b, double t) {
  SurfaceLook out = t < 0.5 ? a : b;  // sizes, flags: the nearer entry's
  out.ambient = lerp(a.ambient, b.ambient, t);
  out.diffuse = lerp(a.diffuse, b.diffuse, t);
  out.pigment = lerp(a.pigment, b.pigment, t);
  out.through = lerp(a.through, b.through, t);
  auto mix_value = [t](double x, double y) { return x + t * (y - x); };
  out.finish.phong = mix_value(a.finish.phong, b.finish.phong);
  out.finish.specular = mix_value(a.finish.specular, b.finish.specular);
  out.finish.brilliance = mix_value(a.finish.brilliance, b.finish.brilliance);
  out.finish.reflection_min = mix_value(a.finish.reflection_min, b.finish.reflection_min);
  out.finish.reflection_max = mix_value(a.finish.reflection_max, b.finish.reflection_max);
  const Vec3 n = lerp(a.normal, b.normal, t);
  const double l = length(n);
  if (l > 0) out.normal = n / l;
  return out;
}

}  // namespace

SurfaceLook mapped_look(const TextureStack& texture, const TextureContext& ctx) {
  if (texture.average) {
    // A running weighted mean: each entry blended in by its share of the weights so far.
    SurfaceLook sum;
    double total = 0;
    for (const TextureMapEntry& e : texture.map) {
      if (!e.texture || !(e.at > 0)) continue;
      total += e.at;
      const SurfaceLook look = evaluate(*e.texture, ctx);
      sum = total == e.at ? look : blend(sum, look, e.at / total);
    }
    return sum;
  }
  const MapPick m = pick(texture, ctx.p);
  if (!m.a) return {};
  const SurfaceLook a = evaluate(*m.a, ctx);
  return m.b ? blend(a, evaluate(*m.b, ctx), m.t) : a;
}

namespace {

// POV-Ray's wrinkles normal: vector noise summed over ten octaves, each half as strong and twice
// as fine (the gradient of the wrinkles value would weigh every octave alike), taken along the
// world axes.
Vec3 wrinkles_normal(const Pattern& pattern, const TextureContext& ctx) {
  const Vec3 q = pattern_point(pattern, ctx.p);
  Vec3 v{0, 0, 0};
  double f = 1;
  for (int i = 0; i < 10; ++i, f *= 2) v += vector_noise(f * q, pattern.noise_generator) / f;
  // Three times: raycast's vector noise is about a third as strong as POV-Ray's DNoise, whose
  // wrinkles these are compared with (docs/textures.md "Normals").
  const Vec3 t = pattern_vector(pattern, 3.0 * v);
  Vec3 g{0, 0, 0};
  for (std::size_t a = 0; a < 3; ++a) {
    const double l = length(ctx.axes[a]);
    if (l > 0) g[a] = dot(t, ctx.axes[a]) / l;
  }
  return g;
}

}  // namespace

Vec3 pattern_gradient(const Pattern& pattern, const TextureContext& ctx) {
  if (pattern.kind == PatternKind::kWrinkles) return wrinkles_normal(pattern, ctx);
  // A step of 0.02 of the pattern's size in texture space along each world axis (POV-Ray's
  // default normal `accuracy`): finer steps pick up the noise's smallest octaves as grain.
  double size = 1;
  for (const PatternStep& s : pattern.steps)
    if (s.transform) {
      const Mat4& m = s.transform->matrix();
      const double det = m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
                         m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
                         m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
      size *= std::cbrt(std::abs(det));
    }
  if (!(size > 0) || !std::isfinite(size)) size = 1;
  constexpr double kStep = 0.02;
  const PatternKind k = pattern.kind;
  const bool own_normal = k == PatternKind::kBumps || k == PatternKind::kDents ||
                          k == PatternKind::kRipples || k == PatternKind::kWaves;
  double scale = own_normal ? 1 : kPatternNormalScale;
  // POV-Ray's ripples and waves normals put the frequency inside the wave only: their tilt is
  // measured per wavelength, so a high frequency (water scaled by 1e5 at frequency 1e5) keeps
  // its steps inside one wave.
  if ((k == PatternKind::kRipples || k == PatternKind::kWaves) && std::abs(pattern.frequency) > 1)
    size /= std::abs(pattern.frequency);
  // A bump map's slope is POV-Ray's height step from one pixel to the next, not per unit of the
  // pattern: the slope over the image's width.
  if (k == PatternKind::kImage && pattern.image && pattern.image->width > 0)
    scale = 1.0 / double(pattern.image->width);
  // The slopes along the three axes from four samples at the corners of a tetrahedron,
  // p + h (s0 a0 + s1 a1 + s2 a2) with signs s = (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1): each
  // sign vector sums to 0 over the corners and their outer products sum to 4 I, so
  // sum_i f_i s_i / 4h is the gradient to first order, from four evaluations instead of six.
  Vec3 step[3];
  for (int a = 0; a < 3; ++a) {
    const Vec3& axis = ctx.axes[a];
    const double l = length(axis);
    step[a] = l > 0 ? (kStep * size / l) * axis : Vec3{0, 0, 0};
  }
  static constexpr double kCorners[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  Vec3 g{0, 0, 0};
  for (const auto& c : kCorners) {
    const double f = evaluate(pattern, ctx.p + c[0] * step[0] + c[1] * step[1] + c[2] * step[2]);
    g += f * Vec3{c[0], c[1], c[2]};
  }
  for (std::size_t a = 0; a < 3; ++a)
    g[a] = step[a] == Vec3{0, 0, 0} ? 0 : g[a] / (4 * kStep) * scale;
  return g;
}

namespace {

// The normal_map's entries around the pattern's value with their shares (a colour map's rule).
int map_pick(const Normal& normal, const Vec3& p, const Normal* picked[2], double share[2]) {
  const std::vector<NormalMapEntry>& map = normal.map;
  const double v = evaluate(normal.pattern, p);
  const int blocks = block_count(normal.pattern.kind);
  std::size_t a = 0, b = 0;
  double t = 0;
  if (blocks > 0) {
    a = b = std::size_t(std::clamp(std::lround(v * double(blocks - 1)), 0L, long(map.size()) - 1));
  } else if (!(v > map.front().weight)) {
    a = b = 0;
  } else if (v >= map.back().weight) {
    a = b = map.size() - 1;
  } else {
    b = 1;
    while (map[b].weight <= v) ++b;
    a = b - 1;
    const double span = map[b].weight - map[a].weight;
    t = span > 0 ? (v - map[a].weight) / span : 1;
  }
  picked[0] = map[a].normal.get(), share[0] = 1 - t;
  picked[1] = map[b].normal.get(), share[1] = t;
  return a == b ? 1 : 2;
}

}  // namespace

Vec3 normal_tilt(const Normal& normal, const TextureContext& ctx, int depth) {
  if (normal.average.empty() && normal.map.empty())
    return normal.bump_size * pattern_gradient(normal.pattern, ctx);
  // The unit normal each entry gives, averaged by weight; the tilt is what leans ctx.n onto the
  // mean's direction: mean = a n + t (t across n) points along n - (-t / a).
  const Normal* entries[2] = {nullptr, nullptr};
  double shares[2] = {0, 0};
  const bool average = !normal.average.empty();
  const int count = average ? int(normal.average.size()) : map_pick(normal, ctx.p, entries, shares);
  Vec3 mean{0, 0, 0};
  double total = 0;
  for (int i = 0; i < count; ++i) {
    const Normal* entry = average ? normal.average[std::size_t(i)].normal.get() : entries[i];
    const double weight = average ? normal.average[std::size_t(i)].weight : shares[i];
    if (!entry || depth > 16) continue;
    const Vec3 tilt = normal_tilt(*entry, ctx, depth + 1);
    const Vec3 n = ctx.n - (tilt - dot(tilt, ctx.n) * ctx.n);
    const double l = length(n);
    if (l > 0 && std::isfinite(l)) mean += (weight / l) * n;
    total += weight;
  }
  if (total == 0) return {0, 0, 0};
  const double a = dot(mean, ctx.n);
  if (!(a > 1e-9)) return {0, 0, 0};
  return -(1 / a) * (mean - a * ctx.n);
}

SurfaceLook evaluate(const TextureStack& texture, const TextureContext& ctx) {
  SurfaceLook look;
  Finish& f = look.finish;
  f = Finish{};
  f.phong = f.specular = f.reflection_min = f.reflection_max = f.crand = 0;
  double strongest = -1, diffuse_weight = 0, brilliance = 0;
  Vec3 through{1, 1, 1};
  Vec3 tilt{0, 0, 0};
  // From the top layer down: each is seen through the filter and transmit of those above.
  for (auto it = texture.layers.rbegin(); it != texture.layers.rend(); ++it) {
    const TextureLayer& layer = *it;
    const Rgbft c = evaluate(layer.pigment, ctx.p);
    const double opaque = std::clamp(1 - c.filter - c.transmit, 0.0, 1.0);
    const Vec3 seen = opaque * mul(through, c.rgb);
    const double vis = average(through);
    look.ambient += layer.finish.ambient * seen;
    look.diffuse += layer.finish.diffuse * seen;
    look.pigment += seen;
    const double w = vis * opaque * layer.finish.diffuse;
    diffuse_weight += w;
    brilliance += w * layer.finish.brilliance;
    add_finish(layer.finish, vis, f, strongest);
    if (layer.normal) tilt += vis * normal_tilt(*layer.normal, ctx);
    through = mul(through, c.filter * c.rgb + Vec3{c.transmit, c.transmit, c.transmit});
    if (!(through.x > 0 || through.y > 0 || through.z > 0)) break;
  }
  if (texture.map_pattern && (through.x > 0 || through.y > 0 || through.z > 0)) {
    // The patterned texture under the layers, seen through them.
    const SurfaceLook base = mapped_look(texture, ctx);
    const double vis = average(through);
    look.ambient += mul(through, base.ambient);
    look.diffuse += mul(through, base.diffuse);
    look.pigment += mul(through, base.pigment);
    diffuse_weight += vis;
    brilliance += vis * base.finish.brilliance;
    add_finish(base.finish, vis, f, strongest);
    tilt += vis * (ctx.n - base.normal);
    through = mul(through, base.through);
  }
  f.brilliance = diffuse_weight > 0 ? brilliance / diffuse_weight : 1;
  if (f.crand > 0) look.diffuse *= 1 - std::min(1.0, f.crand) * grain(ctx.p);
  look.through = through;
  look.normal = ctx.n;
  if (tilt.x != 0 || tilt.y != 0 || tilt.z != 0) {
    // Raised where the pattern is high: the normal leans away from the gradient's tangential
    // part (the part along n does not tilt it).
    const Vec3 tangential = tilt - dot(tilt, ctx.n) * ctx.n;
    const Vec3 n = ctx.n - tangential;
    const double l = length(n);
    if (l > 0 && std::isfinite(l)) look.normal = n / l;
  }
  return look;
}

namespace {

// The weighted mean of f over an average texture's entries (black when no weight is positive).
Vec3 mean_of(const TextureStack& texture, const Vec3& p,
             Vec3 (*f)(const TextureStack&, const Vec3&)) {
  Vec3 sum{0, 0, 0};
  double total = 0;
  for (const TextureMapEntry& e : texture.map) {
    if (!e.texture || !(e.at > 0)) continue;
    sum += e.at * f(*e.texture, p);
    total += e.at;
  }
  return total > 0 ? sum / total : sum;
}

}  // namespace

Vec3 pigment_color(const TextureStack& texture, const Vec3& p) {
  Vec3 through{1, 1, 1}, sum{0, 0, 0};
  for (auto it = texture.layers.rbegin(); it != texture.layers.rend(); ++it) {
    const Rgbft c = evaluate(it->pigment, p);
    sum += std::clamp(1 - c.filter - c.transmit, 0.0, 1.0) * mul(through, c.rgb);
    through = mul(through, c.filter * c.rgb + Vec3{c.transmit, c.transmit, c.transmit});
    if (!(through.x > 0 || through.y > 0 || through.z > 0)) return sum;
  }
  if (texture.average) return sum + mul(through, mean_of(texture, p, pigment_color));
  if (const MapPick m = texture.map_pattern ? pick(texture, p) : MapPick{}; m.a) {
    const Vec3 a = pigment_color(*m.a, p);
    sum += mul(through, m.b ? lerp(a, pigment_color(*m.b, p), m.t) : a);
  }
  return sum;
}

Vec3 transmittance(const TextureStack& texture, const Vec3& p) {
  Vec3 through{1, 1, 1};
  for (auto it = texture.layers.rbegin(); it != texture.layers.rend(); ++it) {
    const Rgbft c = evaluate(it->pigment, p);
    through = mul(through, c.filter * c.rgb + Vec3{c.transmit, c.transmit, c.transmit});
    if (!(through.x > 0 || through.y > 0 || through.z > 0)) return through;
  }
  if (texture.average) return mul(through, mean_of(texture, p, transmittance));
  if (const MapPick m = texture.map_pattern ? pick(texture, p) : MapPick{}; m.a) {
    const Vec3 a = transmittance(*m.a, p);
    through = mul(through, m.b ? lerp(a, transmittance(*m.b, p), m.t) : a);
  }
  return through;
}

}  // namespace raycast::texture
