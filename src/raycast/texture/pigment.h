#pragma once
// Pigments (docs/textures.md "Pigments"): a solid colour with filter and transmit, or a pattern
// whose value picks a colour from a colour map or a pigment from a pigment map (maps nest), or
// the weighted average of a list of pigments.
#include <memory>
#include <vector>

#include "math/vec3.h"
#include "texture/pattern.h"

namespace raycast::texture {

/// Linear RGB with POV-Ray's filter (light through, tinted by the colour) and transmit (light
/// through, untinted).
struct Rgbft {
  Vec3 rgb{0, 0, 0};
  double filter = 0, transmit = 0;
};

/// Componentwise a + t (b - a).
Rgbft mix(const Rgbft& a, const Rgbft& b, double t);

struct ColorMapEntry {
  double at = 0;
  Rgbft color;
};

struct Pigment;
struct PigmentMapEntry {
  double at = 0;
  std::shared_ptr<const Pigment> pigment;
};

/// The most entries a colour map or a pigment map holds (POV-Ray's bound).
inline constexpr std::size_t kMaxMapEntries = 256;

struct Pigment {
  // kAverage: POV-Ray's `average` pattern, the pigments of pigment_map averaged with their
  // `at` as weights (the pattern is unused). kImage: an image_map, the colours of the pattern's
  // image (clear where the image does not reach).
  enum class Kind : std::uint8_t { kSolid, kColorMap, kPigmentMap, kAverage, kImage };
  Kind kind = Kind::kSolid;
  Rgbft color;                               // kSolid
  Pattern pattern;                           // kColorMap, kPigmentMap
  std::vector<ColorMapEntry> color_map;      // sorted by `at`
  std::vector<PigmentMapEntry> pigment_map;  // sorted by `at`; a block pattern's list in order
};

/// The weighted mean of the entries' pigments at p, `at` being each one's weight (black when the
/// weights sum to 0).
Rgbft average_at(const std::vector<PigmentMapEntry>& map, const Vec3& p);

/// The colour a map gives at value v in [0, 1]: the first entry's below it, the last's above,
/// linear between neighbours (entries sorted by `at`; an empty map is black).
Rgbft lookup(const std::vector<ColorMapEntry>& map, double v);

/// The pigment's colour at p (texture space). Nesting is bounded by how pigments are built (each
/// map holds finished pigments), so the recursion ends.
Rgbft evaluate(const Pigment& pigment, const Vec3& p);

/// Whether any colour the pigment can give has filter or transmit above 0.
bool may_transmit(const Pigment& pigment);

}  // namespace raycast::texture

namespace raycast::texture {

/// Moves the whole pigment by t: its pattern and, recursively, every pigment of its map (as
/// POV-Ray transforms a pigment with its maps). Sub-pigments shared with other pigments are
/// copied, not changed.
void transform_pigment(Pigment& pigment, const Transform& t);

}  // namespace raycast::texture
