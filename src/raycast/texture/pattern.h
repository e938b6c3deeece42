#pragma once
// POV-Ray 3.7's patterns as functions of a point in texture space (docs/textures.md "Patterns"):
// a pattern kind with its parameters, the wave that shapes its value, turbulence, and the
// transformations and warps between the texture's space and the pattern's.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "math/transform.h"
#include "math/vec3.h"
#include "texture/image_map.h"
#include "texture/noise.h"
#include "texture/pattern_function.h"

namespace raycast::texture {

enum class PatternKind : std::uint8_t {
  kAgate,
  kBoxed,
  kBozo,
  kBrick,
  kBumps,
  kCells,
  kChecker,
  kCrackle,
  kCylindrical,
  kDents,
  kFunction,
  kGradient,
  kGranite,
  kHexagon,
  kImage,
  kLeopard,
  kMarble,
  kOnion,
  kPlanar,
  kQuilted,
  kRadial,
  kRipples,
  kSpherical,
  kSpiral1,
  kSpiral2,
  kSpotted,
  kSquare,
  kTriangular,
  kWaves,
  kWood,
  kWrinkles,
};

/// The pattern named `name` as POV-Ray spells it ("bozo", "spiral1" ...), or nothing.
std::optional<PatternKind> pattern_kind(std::string_view name);
/// POV-Ray's name of a pattern kind.
std::string_view pattern_name(PatternKind kind);
/// How many discrete values a block pattern has (checker 2, brick 2, hexagon 3, square 4,
/// triangular 6), 0 for the continuous patterns. A block pattern's value k/(n-1) picks the k-th
/// entry of its list.
int block_count(PatternKind kind);

/// The wave that maps a pattern's raw value (after frequency and phase) into [0, 1].
enum class WaveForm : std::uint8_t { kRamp, kTriangle, kSine, kScallop, kCubic, kPoly };

/// One step between texture space and the pattern's space, in the order written: a
/// transformation (the point is moved by its inverse) or a turbulence warp.
struct PatternStep {
  std::optional<Transform> transform;  // set: a transformation; else the warp below
  Turbulence warp;
};

struct Pattern {
  PatternKind kind = PatternKind::kBozo;
  Vec3 vector{1, 0, 0};  // gradient's direction; brick_size
  double amount = 0;     // spiral arms; mortar; agate_turb; quilted control0
  double amount2 = 0;    // quilted control1
  WaveForm wave = WaveForm::kRamp;
  bool wave_given = false;  // marble and wood default to the triangle wave
  double exponent = 1;      // poly_wave's exponent
  double frequency = 1, phase = 0;
  Turbulence turbulence;    // classic turbulence: applied before the pattern's own steps
  int noise_generator = 2;  // POV-Ray 3.7's default
  std::vector<PatternStep> steps;
  std::shared_ptr<const PatternFunction> function;  // kFunction
  std::shared_ptr<const ImageMap> image;            // kImage: its grey; an image_map pigment's
};

/// A new pattern of `kind` with POV-Ray's defaults for it (brick size, mortar, agate_turb ...).
Pattern make_pattern(PatternKind kind);

/// Appends a transformation that moves the pattern (texture space -> pattern space is its
/// inverse), merged with a transformation just before it.
void transform_pattern(Pattern& p, const Transform& t);

/// The pattern's value at p (texture space), in [0, 1]: the steps undone, turbulence, the raw
/// pattern, then frequency, phase and the wave (continuous patterns) or the block index k/(n-1).
double evaluate(const Pattern& pattern, const Vec3& p);

/// The point of the pattern's own space that p (texture space) is evaluated at: the steps
/// undone, then the classic turbulence (not for marble and agate, which add it to their value).
Vec3 pattern_point(const Pattern& pattern, const Vec3& p);
/// A direction of the pattern's own space in texture space (the steps' transformations).
Vec3 pattern_vector(const Pattern& pattern, const Vec3& v);

/// The raw pattern function at a point of the pattern's own space (no steps, no wave): what each
/// pattern defines (gradient: p.v, onion: |p|, ...). Continuous patterns give values whose
/// fractional part or clamp to [0, 1] the wave takes; block patterns their index.
double raw_pattern(const Pattern& pattern, const Vec3& p);

/// The wave forms on a value already scaled by frequency and shifted by phase.
double apply_wave(WaveForm wave, double v, double exponent);

}  // namespace raycast::texture
