#pragma once
// POV-Ray's atmosphere as values (docs/rendering.md "Sky and fog"): a sky sphere drawn where a ray
// leaves the scene, and fogs that veil every ray segment by its length. A scene without them holds
// no Atmosphere at all, so the render pays one pointer test.
#include <optional>
#include <vector>

#include "math/transform.h"
#include "math/vec3.h"
#include "texture/noise.h"
#include "texture/pigment.h"

namespace raycast {

/// Pigments on a sphere at infinity, looked up by a ray's unit direction: the bottom layer first,
/// each upper one showing those below through its filter and transmit; what the top ones let
/// through of the bottom one shows the background.
struct SkySphere {
  std::vector<texture::Pigment> layers;
  Vec3 emission{1, 1, 1};  // scales the sky's colour (POV-Ray 3.7's brightness control)
  Transform to_sky;        // world direction -> the pigments' space (a point on the unit sphere)
};

/// A fog: the light of a segment of length d reaches the viewer attenuated by exp(-depth/distance)
/// (at least `transmit`), where depth is d for a constant fog and the integral of the ground fog's
/// density along the segment; the rest is the fog's colour, `filter` of it tinting the light.
struct Fog {
  enum class Kind : unsigned char { kConstant, kGround };
  Kind kind = Kind::kConstant;
  Vec3 color{0, 0, 0};
  double filter = 0, transmit = 0;
  double distance = 1;  // > 0
  // Ground fog: density 1 at heights up to `offset` along `up`, 1 / (1 + ((h - offset) / alt)^2)
  // above it (alt 0: no fog above the offset).
  double offset = 0, alt = 0;
  Vec3 up{0, 1, 0};  // unit length
  // Turbulence scales a segment's depth by 1 - min(1, scalar turbulence), looked up at the
  // point `turb_depth` of the way along the segment pushed by the turbulence displacement (the
  // amount moves the look-up; POV-Ray's renders thin the fog by a bounded fraction whatever it).
  texture::Turbulence turbulence;
  double turb_depth = 0.5;
  Transform to_fog;  // world -> the fog's own space (its transformations' inverse)
};

/// A rainbow: a ring of colours at `angle` +- `width` / 2 degrees around `direction` (the way
/// the sunlight travels), the colour map's 0 on the inside, veiling what lies behind it as a fog
/// of `distance` does (misses fully); its colours' transmit bounds the veil and their filter
/// tints the light behind. Only the arc within `arc_angle` / 2 of `up` (measured around the
/// direction) shows, fading out linearly beyond `falloff_angle` / 2.
struct Rainbow {
  Vec3 direction{0, 0, 1};  // unit length
  double angle = 42.5, width = 5;
  double distance = 1e7;
  std::vector<texture::ColorMapEntry> colors;  // sorted
  double jitter = 0;  // random shift of the map's index, at most +-jitter/2
  Vec3 up{0, 1, 0};
  double arc_angle = 360, falloff_angle = 360;  // degrees; falloff_angle <= arc_angle
};

struct Atmosphere {
  std::optional<SkySphere> sky;
  std::vector<Fog> fogs;
  std::vector<Rainbow> rainbows;
  bool empty() const { return !sky && fogs.empty() && rainbows.empty(); }
  bool veils() const { return !fogs.empty() || !rainbows.empty(); }
};

}  // namespace raycast
