#pragma once
// Textures (docs/textures.md): layers of pigment, normal perturbation and finish, evaluated at a
// surface point through one context. A texture of several layers shows each lower layer through
// the filter and transmit of the layers above it (POV-Ray's layered textures).
#include <memory>
#include <optional>
#include <vector>

#include "math/vec3.h"
#include "texture/finish.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace raycast::texture {

struct Normal;
struct NormalMapEntry {
  double weight = 1;
  std::shared_ptr<const Normal> normal;
};

/// A normal perturbation: the surface normal tilted against the pattern's gradient (measured in
/// the pattern's own units, so scaling the pattern does not change the tilt), times bump_size.
/// With `average` entries it is POV-Ray's `average` normal instead: the weighted mean of the
/// normals each entry would give (pattern and bump_size unused). With `map` entries it is a
/// normal_map: the pattern's value picks (block patterns) or blends (entries sorted by their
/// value, in `weight`) the two neighbouring entries' normals, as a colour map blends colours.
struct Normal {
  Pattern pattern;
  double bump_size = 0.5;
  std::vector<NormalMapEntry> average;
  std::vector<NormalMapEntry> map;
};

/// Moves a normal's pattern, and its average's normals, by t.
void transform_normal(Normal& normal, const Transform& t);

struct TextureLayer {
  Pigment pigment;
  std::optional<Normal> normal;
  Finish finish;
};

/// Moves a layer's pigment and normal by t (POV-Ray's transformations of a texture).
void transform_layer(TextureLayer& layer, const Transform& t);

struct TextureStack;
struct TextureMapEntry {
  double at = 0;
  std::shared_ptr<const TextureStack> texture;
};

struct TextureStack {
  std::vector<TextureLayer> layers;  // the bottom layer first (over the map, when there is one)
  // A patterned texture under the layers: the pattern's value picks (block patterns) or blends
  // (sorted entries, as a colour map) whole textures.
  // With `average`, the map's textures are averaged with their `at` as weights (POV-Ray's
  // `average` texture) and the pattern is unused.
  std::optional<Pattern> map_pattern;
  std::vector<TextureMapEntry> map;
  bool average = false;
  bool may_transmit() const;  // some point shows what is behind the surface
  bool has_normal() const;
};

/// Where a texture is evaluated: the point in texture space, the texture-space images of the
/// world's unit axes (for the normal's gradient in world space), the unit world normal, (u, v).
struct TextureContext {
  Vec3 p;
  Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 n{0, 0, 1};
  double u = 0, v = 0;
};

/// What a texture gives a surface point: the colours its ambient and diffuse terms use (already
/// weighted by each layer's coefficient and visible fraction), the pigment colour (what metallic
/// highlights and reflections take), the light let through the whole stack (per channel), the
/// finish of its highlights and reflection (visible layers' sums), and the perturbed unit
/// normal.
struct SurfaceLook {
  Vec3 ambient{0, 0, 0};
  Vec3 diffuse{0, 0, 0};
  Vec3 pigment{0, 0, 0};
  Vec3 through{0, 0, 0};
  Finish finish;
  Vec3 normal{0, 0, 1};
};

SurfaceLook evaluate(const TextureStack& texture, const TextureContext& ctx);
/// The look of a stack's map alone (its entries picked or blended at ctx.p); empty without one.
SurfaceLook mapped_look(const TextureStack& texture, const TextureContext& ctx);

/// The colour the layers show at p, each seen through the filter and transmit of those above
/// (the albedo output and the raycast integrator's colour).
Vec3 pigment_color(const TextureStack& texture, const Vec3& p);

/// The light a texture lets through at a point (the shadow rays' filter): the product of the
/// layers' filter * colour + transmit, top layer first.
Vec3 transmittance(const TextureStack& texture, const Vec3& p);

/// POV-Ray draws bumps, dents, wrinkles, ripples and waves normals with functions of their own
/// and every other pattern's normal from its slope; this scales that slope so that the tilts
/// match POV-Ray 3.7's renders of its pattern examples (textures/patterns/*.pov: gradient, radial,
/// marble, granite, agate, crackle compared side by side), not a published constant.
inline constexpr double kPatternNormalScale = 0.3;

/// The gradient of the pattern's value at ctx.p along the world axes, per unit of the pattern's
/// own size (central differences of evaluate() over POV-Ray's default `accuracy`, 0.02), times
/// kPatternNormalScale for the patterns without a normal of their own. A wave's wrap (the ramp's
/// jump from 1 to 0) gives a steep thin line, as in POV-Ray.
Vec3 pattern_gradient(const Pattern& pattern, const TextureContext& ctx);

/// What a normal adds to the tilt at ctx (the vector whose part across ctx.n the normal leans
/// away from): bump_size times the pattern's gradient, or for an average normal the tilt that
/// gives the weighted mean of its entries' unit normals.
Vec3 normal_tilt(const Normal& normal, const TextureContext& ctx, int depth = 0);

}  // namespace raycast::texture
