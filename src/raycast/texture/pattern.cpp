#include "texture/pattern.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace raycast::texture {

namespace {

struct NamedKind {
  std::string_view name;
  PatternKind kind;
};
constexpr std::array<NamedKind, 31> kNames = {{
    {"agate", PatternKind::kAgate},
    {"boxed", PatternKind::kBoxed},
    {"bozo", PatternKind::kBozo},
    {"brick", PatternKind::kBrick},
    {"bumps", PatternKind::kBumps},
    {"cells", PatternKind::kCells},
    {"checker", PatternKind::kChecker},
    {"crackle", PatternKind::kCrackle},
    {"cylindrical", PatternKind::kCylindrical},
    {"dents", PatternKind::kDents},
    {"function", PatternKind::kFunction},
    {"gradient", PatternKind::kGradient},
    {"granite", PatternKind::kGranite},
    {"hexagon", PatternKind::kHexagon},
    {"image_pattern", PatternKind::kImage},
    {"leopard", PatternKind::kLeopard},
    {"marble", PatternKind::kMarble},
    {"onion", PatternKind::kOnion},
    {"planar", PatternKind::kPlanar},
    {"quilted", PatternKind::kQuilted},
    {"radial", PatternKind::kRadial},
    {"ripples", PatternKind::kRipples},
    {"spherical", PatternKind::kSpherical},
    {"spiral1", PatternKind::kSpiral1},
    {"spiral2", PatternKind::kSpiral2},
    {"spotted", PatternKind::kSpotted},
    {"square", PatternKind::kSquare},
    {"triangular", PatternKind::kTriangular},
    {"waves", PatternKind::kWaves},
    {"wood", PatternKind::kWood},
    {"wrinkles", PatternKind::kWrinkles},
}};

double fraction(double v) { return v - std::floor(v); }

}  // namespace

std::optional<PatternKind> pattern_kind(std::string_view name) {
  for (const NamedKind& n : kNames)
    if (n.name == name) return n.kind;
  return std::nullopt;
}

std::string_view pattern_name(PatternKind kind) {
  for (const NamedKind& n : kNames)
    if (n.kind == kind) return n.name;
  return "?";
}

int block_count(PatternKind kind) {
  switch (kind) {
    case PatternKind::kChecker:
    case PatternKind::kBrick:
      return 2;
    case PatternKind::kHexagon:
      return 3;
    case PatternKind::kSquare:
      return 4;
    case PatternKind::kTriangular:
      return 6;
    default:
      return 0;
  }
}

Pattern make_pattern(PatternKind kind) {
  Pattern p;
  p.kind = kind;
  switch (kind) {
    case PatternKind::kBrick:
      p.vector = {8, 3, 4.5};  // brick_size
      p.amount = 0.5;          // mortar
      break;
    case PatternKind::kAgate:
      p.amount = 1;  // agate_turb
      break;
    case PatternKind::kQuilted:
      p.amount = 0, p.amount2 = 1;  // control0, control1
      break;
    case PatternKind::kSpiral1:
    case PatternKind::kSpiral2:
      p.amount = 1;  // arms
      break;
    case PatternKind::kGradient:
      p.vector = {1, 0, 0};
      break;
    default:
      break;
  }
  return p;
}

void transform_pattern(Pattern& p, const Transform& t) {
  if (!p.steps.empty() && p.steps.back().transform) {
    p.steps.back().transform = t * *p.steps.back().transform;
    return;
  }
  p.steps.push_back({t, {}});
}

double apply_wave(WaveForm wave, double v, double exponent) {
  switch (wave) {
    case WaveForm::kRamp:
      return fraction(v);
    case WaveForm::kTriangle: {
      const double f = fraction(v);
      return f < 0.5 ? 2 * f : 2 - 2 * f;
    }
    case WaveForm::kSine:
      return 0.5 + 0.5 * std::sin(2 * std::numbers::pi * v);
    case WaveForm::kScallop:
      return std::abs(std::sin(std::numbers::pi * v));
    case WaveForm::kCubic: {
      const double f = fraction(v);
      return f * f * (3 - 2 * f);
    }
    case WaveForm::kPoly:
      return std::pow(fraction(v), std::max(exponent, 0.0));
  }
  return fraction(v);
}

Vec3 pattern_point(const Pattern& pattern, const Vec3& p) {
  // The steps as written move the pattern: undo them from the last to the first.
  Vec3 q = p;
  for (auto it = pattern.steps.rbegin(); it != pattern.steps.rend(); ++it) {
    if (it->transform)
      q = it->transform->inverse_point(q);
    else
      q += turbulence_offset(q, it->warp, pattern.noise_generator);
  }
  const PatternKind k = pattern.kind;
  // Marble and agate add turbulence to their value (raw_pattern); the others, wood included,
  // are displaced by it.
  if (pattern.turbulence.any() && k != PatternKind::kMarble && k != PatternKind::kAgate)
    q += turbulence_offset(q, pattern.turbulence, pattern.noise_generator);
  return q;
}

Vec3 pattern_vector(const Pattern& pattern, const Vec3& v) {
  Vec3 out = v;
  for (const PatternStep& s : pattern.steps)
    if (s.transform) out = s.transform->vector(out);
  return out;
}

double evaluate(const Pattern& pattern, const Vec3& p) {
  const PatternKind k = pattern.kind;
  const double raw = raw_pattern(pattern, pattern_point(pattern, p));
  if (!std::isfinite(raw)) return 0;
  const int blocks = block_count(k);
  if (blocks > 0) return raw / double(blocks - 1);
  const bool triangle_default = k == PatternKind::kMarble || k == PatternKind::kWood;
  const WaveForm wave = pattern.wave_given ? pattern.wave
                        : triangle_default ? WaveForm::kTriangle
                                           : WaveForm::kRamp;
  const double v = raw * pattern.frequency + pattern.phase;
  // A value of exactly 1 (the clamped patterns' top) stays 1 under the ramp.
  if (wave == WaveForm::kRamp && v == 1 && pattern.frequency == 1) return 1;
  return std::clamp(apply_wave(wave, v, pattern.exponent), 0.0, 1.0);
}

}  // namespace raycast::texture
