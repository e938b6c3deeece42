#include "load/read_textures.h"

#include <algorithm>
#include <filesystem>

#include "io/image.h"

namespace raycast {

namespace {

constexpr int kMaxPigmentDepth = 16;

texture::WaveForm read_wave(Fields& f) {
  const std::string w = f.string("wave", "default");
  if (w == "ramp") return texture::WaveForm::kRamp;
  if (w == "triangle") return texture::WaveForm::kTriangle;
  if (w == "sine") return texture::WaveForm::kSine;
  if (w == "scallop") return texture::WaveForm::kScallop;
  if (w == "cubic") return texture::WaveForm::kCubic;
  if (w == "poly") return texture::WaveForm::kPoly;
  f.fail("wave",
         f.name("wave") + " must be ramp, triangle, sine, scallop, cubic or poly, got " + w);
}

Vec3 number_or_vec3(Fields& f, const std::string& key, const Vec3& fallback) {
  const YamlNode n = f.optional(key);
  if (!n) return fallback;
  if (n.IsScalar()) {
    const double v = read_number(f.ctx(), n, f.name(key));
    return {v, v, v};
  }
  return read_vec3(f.ctx(), n, f.name(key));
}

// The pattern and its modifiers, read from the mapping that names it.
texture::Pattern read_pattern(Fields& f) {
  const std::string name = f.string("pattern");
  const std::optional<texture::PatternKind> kind = texture::pattern_kind(name);
  if (!kind) f.fail("pattern", f.name("pattern") + ": no pattern named '" + name + "'");
  texture::Pattern p = texture::make_pattern(*kind);
  if (*kind == texture::PatternKind::kFunction) {
    // A formula in x, y, z of the pattern's space (the isosurface's syntax).
    const std::string text = f.string("function");
    try {
      p.function = texture::formula_function(compile_formula(text));
    } catch (const ExpressionError& e) {
      f.fail("function", f.name("function") + ": " + e.what());
    }
  }
  p.vector = f.vec3("direction", p.vector);
  if (*kind == texture::PatternKind::kBrick) p.vector = f.vec3("brick_size", p.vector);
  if (*kind == texture::PatternKind::kBrick) p.amount = f.non_negative("mortar", p.amount);
  if (*kind == texture::PatternKind::kAgate) p.amount = f.number("agate_turb", p.amount);
  if (*kind == texture::PatternKind::kSpiral1 || *kind == texture::PatternKind::kSpiral2)
    p.amount = f.number("arms", p.amount);
  if (*kind == texture::PatternKind::kQuilted) {
    p.amount = f.number("control0", p.amount);
    p.amount2 = f.number("control1", p.amount2);
  }
  if (f.has("wave")) {
    p.wave = read_wave(f);
    p.wave_given = true;
  }
  p.exponent = f.non_negative("exponent", p.exponent);
  p.frequency = f.number("frequency", p.frequency);
  p.phase = f.number("phase", p.phase);
  p.turbulence.amount = number_or_vec3(f, "turbulence", p.turbulence.amount);
  p.turbulence.octaves = f.integer("octaves", p.turbulence.octaves, 1, 10);
  p.turbulence.omega = f.number("omega", p.turbulence.omega);
  p.turbulence.lambda = f.number("lambda", p.turbulence.lambda);
  p.noise_generator = f.integer("noise_generator", p.noise_generator, 1, 3);
  if (f.has("scale")) {
    const Vec3 s = number_or_vec3(f, "scale", {1, 1, 1});
    if (!(s.x != 0 && s.y != 0 && s.z != 0)) f.fail("scale", f.name("scale") + " must not be 0");
    texture::transform_pattern(p, Transform::scale(s));
  }
  if (f.has("transform"))
    texture::transform_pattern(p, read_transform(f.ctx(), f.required("transform")));
  return p;
}

texture::Rgbft read_rgbft(const SourceContext& ctx, const YamlNode& node, const std::string& what) {
  const std::vector<double> v = read_numbers(ctx, node, what);
  if (v.size() < 3 || v.size() > 5)
    fail_at(ctx, node,
            what + " must be [r, g, b], [r, g, b, filter] or [r, g, b, filter, transmit]");
  return {{v[0], v[1], v[2]}, v.size() > 3 ? v[3] : 0, v.size() > 4 ? v[4] : 0};
}

// A map's entries [value, X] sorted by value; at most 256.
template <class Entry, class Read>
std::vector<Entry> read_map(const SourceContext& ctx, const YamlNode& node, const std::string& what,
                            Read read) {
  if (!node.IsSequence() || node.size() == 0)
    fail_at(ctx, node, what + " must be a non-empty list of [value, entry]");
  if (node.size() > texture::kMaxMapEntries)
    fail_at(ctx, node, what + " has more than 256 entries");
  std::vector<Entry> out;
  for (const YamlNode& e : node) {
    if (!e.IsSequence() || e.size() != 2) fail_at(ctx, e, what + ": each entry is [value, entry]");
    out.push_back(Entry{read_number(ctx, e[0], what), read(e[1])});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Entry& a, const Entry& b) { return a.at < b.at; });
  return out;
}

// An average's weights: none negative, some positive.
double weight_of(const texture::PigmentMapEntry& e) { return e.at; }
double weight_of(const texture::NormalMapEntry& e) { return e.weight; }
template <class Entry>
void check_weights(const SourceContext& ctx, const YamlNode& node, const std::vector<Entry>& map,
                   const std::string& what) {
  double total = 0;
  for (const Entry& e : map) {
    if (!(weight_of(e) >= 0))
      fail_at(ctx, node, what + ": an average's weights must not be negative");
    total += weight_of(e);
  }
  if (!(total > 0)) fail_at(ctx, node, what + ": an average's weights must not all be 0");
}

// {pattern: image_map, file: FILE, map_type, once, interpolate, scale, transform}: a PNG's
// linear colours, its alpha as transmit.
texture::Pigment read_image_pigment(Fields& f) {
  const std::string name = f.string("file");
  const std::filesystem::path path = std::filesystem::path(name).is_absolute()
                                         ? std::filesystem::path(name)
                                         : std::filesystem::path(f.ctx().dir) / name;
  texture::ImageMap image;
  const std::string projection = f.string("map_type", "planar");
  if (projection == "spherical") {
    image.projection = texture::ImageProjection::kSpherical;
  } else if (projection == "cylindrical") {
    image.projection = texture::ImageProjection::kCylindrical;
  } else if (projection != "planar") {
    f.fail("map_type", f.name("map_type") + " must be planar, spherical or cylindrical");
  }
  image.once = f.boolean("once", false);
  image.interpolate = f.boolean("interpolate", false);
  PngPixels png;
  try {
    png = load_png_pixels(path.string());
  } catch (const ImageError& e) {
    f.fail("file", f.name("file") + ": " + e.what());
  }
  image.width = png.width;
  image.height = png.height;
  image.pixels.resize(std::size_t(png.width) * std::size_t(png.height));
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const float* c = &png.rgba[4 * i];
    image.pixels[i] = {srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2]), 0,
                       1 - c[3]};
    if (c[3] < 1) image.transmits = true;
  }
  texture::Pigment p;
  p.kind = texture::Pigment::Kind::kImage;
  p.pattern = texture::make_pattern(texture::PatternKind::kImage);
  p.pattern.image = std::make_shared<const texture::ImageMap>(std::move(image));
  if (f.has("scale")) {
    const Vec3 s = number_or_vec3(f, "scale", {1, 1, 1});
    if (!(s.x != 0 && s.y != 0 && s.z != 0)) f.fail("scale", f.name("scale") + " must not be 0");
    texture::transform_pattern(p.pattern, Transform::scale(s));
  }
  if (f.has("transform"))
    texture::transform_pattern(p.pattern, read_transform(f.ctx(), f.required("transform")));
  return p;
}

}  // namespace

texture::Pigment read_pigment(const SourceContext& ctx, const YamlNode& node, int depth) {
  if (depth > kMaxPigmentDepth) fail_at(ctx, node, "pigments are nested more than 16 deep");
  Fields f(ctx, node, "texture");
  texture::Pigment p;
  if (f.has("color")) {
    p.color = read_rgbft(ctx, f.required("color"), f.name("color"));
    f.finish();
    return p;
  }
  if (f.has("pattern") && f.string("pattern") == "image_map") {
    p = read_image_pigment(f);
    f.finish();
    return p;
  }
  if (f.has("pattern") && f.string("pattern") == "average") {
    // The pigments' weighted mean: each entry's value is its weight.
    p.kind = texture::Pigment::Kind::kAverage;
    p.pigment_map = read_map<texture::PigmentMapEntry>(
        ctx, f.required("pigments"), f.name("pigments"), [&](const YamlNode& c) {
          return std::make_shared<const texture::Pigment>(read_pigment(ctx, c, depth + 1));
        });
    check_weights(ctx, f.required("pigments"), p.pigment_map, f.name("pigments"));
    f.finish();
    return p;
  }
  p.pattern = read_pattern(f);
  if (f.has("colors")) {
    p.kind = texture::Pigment::Kind::kColorMap;
    p.color_map = read_map<texture::ColorMapEntry>(
        ctx, f.required("colors"), f.name("colors"),
        [&](const YamlNode& c) { return read_rgbft(ctx, c, f.name("colors")); });
  } else if (f.has("pigments")) {
    p.kind = texture::Pigment::Kind::kPigmentMap;
    p.pigment_map = read_map<texture::PigmentMapEntry>(
        ctx, f.required("pigments"), f.name("pigments"), [&](const YamlNode& c) {
          return std::make_shared<const texture::Pigment>(read_pigment(ctx, c, depth + 1));
        });
  } else {
    // POV-Ray's default map: black to white.
    p.kind = texture::Pigment::Kind::kColorMap;
    p.color_map = {{0, {{0, 0, 0}, 0, 0}}, {1, {{1, 1, 1}, 0, 0}}};
  }
  f.finish();
  return p;
}

texture::Normal read_normal(const SourceContext& ctx, const YamlNode& node, int depth) {
  if (depth > kMaxPigmentDepth) fail_at(ctx, node, "normals are nested more than 16 deep");
  Fields f(ctx, node, "normal");
  texture::Normal n;
  if (f.has("pattern") && f.string("pattern") == "average") {
    // The normals' weighted mean: entries [weight, normal].
    const YamlNode list = f.required("normals");
    const std::string what = f.name("normals");
    if (!list.IsSequence() || list.size() == 0 || list.size() > texture::kMaxMapEntries)
      fail_at(ctx, list, what + " must be a list of 1 to 256 [weight, normal]");
    for (const YamlNode& e : list) {
      if (!e.IsSequence() || e.size() != 2)
        fail_at(ctx, e, what + ": each entry is [weight, normal]");
      n.average.push_back({read_number(ctx, e[0], what), std::make_shared<const texture::Normal>(
                                                             read_normal(ctx, e[1], depth + 1))});
    }
    check_weights(ctx, list, n.average, what);
    n.bump_size = 1;
    f.finish();
    return n;
  }
  n.bump_size = f.number("bump_size", n.bump_size);
  n.pattern = read_pattern(f);
  f.finish();
  return n;
}

bool wants_texture(const YamlNode& material) {
  if (!material.IsMap()) return false;
  const YamlNode t = material["texture"];
  if (t && t.IsMap() && t["pattern"]) return true;
  for (const char* key : {"normal", "layers", "brilliance", "metallic", "crand", "roughness",
                          "reflection_max", "reflection_falloff", "reflection_metallic"})
    if (material[key]) return true;
  return false;
}

}  // namespace raycast

namespace raycast {

namespace {

// The finish keys of a material or a layer over `base`.
texture::Finish read_finish(Fields& f, texture::Finish base) {
  base.ambient = f.non_negative("ambient", base.ambient);
  base.diffuse = f.non_negative("diffuse", base.diffuse);
  base.brilliance = f.non_negative("brilliance", base.brilliance);
  base.phong = f.non_negative("specular", base.phong);
  base.phong_size = f.non_negative("shininess", base.phong_size);
  base.specular = f.non_negative("blinn", base.specular);
  base.roughness = f.positive("roughness", base.roughness);
  base.metallic = f.non_negative("metallic", base.metallic);
  base.crand = f.non_negative("crand", base.crand);
  base.reflection_min = base.reflection_max = f.non_negative("reflection", base.reflection_min);
  base.reflection_max = f.non_negative("reflection_max", base.reflection_max);
  base.reflection_fresnel = f.boolean("fresnel", base.reflection_fresnel);
  base.reflection_falloff = f.non_negative("reflection_falloff", base.reflection_falloff);
  base.reflection_metallic = f.boolean("reflection_metallic", base.reflection_metallic);
  return base;
}

texture::TextureLayer read_layer(const SourceContext& ctx, const YamlNode& node) {
  Fields f(ctx, node, "layer");
  texture::TextureLayer layer;
  layer.pigment = read_pigment(ctx, f.required("texture"));
  if (f.has("normal")) layer.normal = read_normal(ctx, f.required("normal"));
  layer.finish = read_finish(f, texture::Finish{});
  f.finish();
  return layer;
}

}  // namespace

void read_texture_keys(Fields& f, Material& m) {
  auto stack = std::make_shared<texture::TextureStack>();
  texture::TextureLayer base;
  if (f.has("texture")) {
    base.pigment = read_pigment(f.ctx(), f.required("texture"));
  } else {
    base.pigment.color = {m.color, 0, 0};
  }
  if (f.has("normal")) base.normal = read_normal(f.ctx(), f.required("normal"));
  texture::Finish finish;
  finish.ambient = m.ambient;
  finish.diffuse = m.diffuse;
  finish.phong = m.specular;
  finish.phong_size = m.shininess;
  finish.reflection_min = finish.reflection_max = m.reflection;
  finish.reflection_fresnel = m.fresnel;
  base.finish = read_finish(f, finish);
  stack->layers.push_back(std::move(base));
  if (f.has("layers")) {
    const YamlNode layers = f.required("layers");
    if (!layers.IsSequence() || layers.size() == 0 || layers.size() > 64)
      fail_at(f.ctx(), layers, "material.layers must be a list of 1 to 64 layers");
    for (const YamlNode& l : layers) stack->layers.push_back(read_layer(f.ctx(), l));
  }
  m.texture = std::move(stack);
}

}  // namespace raycast
