#include "texture/pigment.h"

#include <algorithm>
#include <cmath>

namespace raycast::texture {

Rgbft mix(const Rgbft& a, const Rgbft& b, double t) {
  return {a.rgb + t * (b.rgb - a.rgb), a.filter + t * (b.filter - a.filter),
          a.transmit + t * (b.transmit - a.transmit)};
}

Rgbft lookup(const std::vector<ColorMapEntry>& map, double v) {
  if (map.empty()) return {};
  if (!(v > map.front().at)) return map.front().color;
  if (v >= map.back().at) return map.back().color;
  // The first entry above v (maps are small: a linear walk beats a search for 2-8 entries).
  std::size_t i = 1;
  while (map[i].at <= v) ++i;
  const ColorMapEntry& a = map[i - 1];
  const ColorMapEntry& b = map[i];
  const double span = b.at - a.at;
  return span > 0 ? mix(a.color, b.color, (v - a.at) / span) : b.color;
}

namespace {

Rgbft pigment_at(const std::vector<PigmentMapEntry>& map, double v, const Vec3& p, bool block) {
  if (map.empty()) return {};
  if (block) {
    // A block pattern's value k/(n-1) picks entry k.
    const double n = double(map.size());
    const auto k = std::size_t(std::clamp(std::lround(v * (n - 1)), 0L, long(map.size()) - 1));
    return evaluate(*map[k].pigment, p);
  }
  if (!(v > map.front().at)) return evaluate(*map.front().pigment, p);
  if (v >= map.back().at) return evaluate(*map.back().pigment, p);
  std::size_t i = 1;
  while (map[i].at <= v) ++i;
  const PigmentMapEntry& a = map[i - 1];
  const PigmentMapEntry& b = map[i];
  const double span = b.at - a.at;
  if (!(span > 0)) return evaluate(*b.pigment, p);
  const double t = (v - a.at) / span;
  return mix(evaluate(*a.pigment, p), evaluate(*b.pigment, p), t);
}

}  // namespace

Rgbft average_at(const std::vector<PigmentMapEntry>& map, const Vec3& p) {
  Rgbft sum;
  double total = 0;
  for (const PigmentMapEntry& e : map) {
    if (!e.pigment) continue;
    const Rgbft c = evaluate(*e.pigment, p);
    sum = {sum.rgb + e.at * c.rgb, sum.filter + e.at * c.filter, sum.transmit + e.at * c.transmit};
    total += e.at;
  }
  if (total == 0) return {};
  return {sum.rgb / total, sum.filter / total, sum.transmit / total};
}

Rgbft evaluate(const Pigment& pigment, const Vec3& p) {
  switch (pigment.kind) {
    case Pigment::Kind::kSolid:
      return pigment.color;
    case Pigment::Kind::kColorMap: {
      const double v = evaluate(pigment.pattern, p);
      const int blocks = block_count(pigment.pattern.kind);
      if (blocks > 0 && !pigment.color_map.empty()) {
        // The block's colours in the order listed.
        const auto n = long(pigment.color_map.size());
        const auto k = std::size_t(std::clamp(std::lround(v * double(blocks - 1)), 0L, n - 1));
        return pigment.color_map[k].color;
      }
      return lookup(pigment.color_map, v);
    }
    case Pigment::Kind::kPigmentMap: {
      const double v = evaluate(pigment.pattern, p);
      // The sub-pigments live in the same texture space; the pattern's own steps only move the
      // pattern.
      return pigment_at(pigment.pigment_map, v, p, block_count(pigment.pattern.kind) > 0);
    }
    case Pigment::Kind::kAverage:
      return average_at(pigment.pigment_map, p);
    case Pigment::Kind::kImage: {
      double u = 0, v = 0;
      const ImageMap* image = pigment.pattern.image.get();
      if (!image || !image_uv(*image, pattern_point(pigment.pattern, p), u, v))
        return {{1, 1, 1}, 0, 1};
      const ImagePixel c = image_sample(*image, u, v);
      return {{c.r, c.g, c.b}, c.filter, c.transmit};
    }
  }
  return {};
}

bool may_transmit(const Pigment& pigment) {
  switch (pigment.kind) {
    case Pigment::Kind::kSolid:
      return pigment.color.filter > 0 || pigment.color.transmit > 0;
    case Pigment::Kind::kColorMap:
      return std::any_of(
          pigment.color_map.begin(), pigment.color_map.end(),
          [](const ColorMapEntry& e) { return e.color.filter > 0 || e.color.transmit > 0; });
    case Pigment::Kind::kImage:
      return pigment.pattern.image &&
             (pigment.pattern.image->transmits || pigment.pattern.image->once);
    case Pigment::Kind::kPigmentMap:
    case Pigment::Kind::kAverage:
      return std::any_of(
          pigment.pigment_map.begin(), pigment.pigment_map.end(),
          [](const PigmentMapEntry& e) { return e.pigment && may_transmit(*e.pigment); });
  }
  return false;
}

}  // namespace raycast::texture

namespace raycast::texture {

void transform_pigment(Pigment& pigment, const Transform& t) {
  if (pigment.kind == Pigment::Kind::kSolid) return;
  transform_pattern(pigment.pattern, t);
  for (PigmentMapEntry& e : pigment.pigment_map) {
    if (!e.pigment) continue;
    auto moved = std::make_shared<Pigment>(*e.pigment);
    transform_pigment(*moved, t);
    e.pigment = std::move(moved);
  }
}

}  // namespace raycast::texture
