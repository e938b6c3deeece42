#include "render/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "render/glyphs.h"

namespace raycast {

namespace {

/// The ramp's stops, evenly spaced: dark blue, blue, cyan, green, yellow, red.
constexpr std::array<Vec3f, 6> kStops = {Vec3f{0.05f, 0.03f, 0.25f}, Vec3f{0.1f, 0.25f, 0.85f},
                                         Vec3f{0.1f, 0.75f, 0.9f},   Vec3f{0.2f, 0.8f, 0.3f},
                                         Vec3f{0.95f, 0.9f, 0.2f},   Vec3f{0.85f, 0.1f, 0.1f}};
constexpr int kBarWidth = 48;   // pixels added on the right
constexpr int kBarStripe = 12;  // the colour stripe's width

}  // namespace

Vec3f heat_color(double s) {
  if (!(s > 0)) return kStops[0];
  if (s >= 1) return kStops.back();
  const double at = s * double(kStops.size() - 1);
  const std::size_t i = std::size_t(at);
  const float f = float(at - double(i));
  return kStops[i] * (1 - f) + kStops[i + 1] * f;
}

HeatmapScale heatmap_scale(const Image& values) {
  double hi = 0;
  for (std::size_t i = 0; i < values.rgb.size(); i += 3)
    if (std::isfinite(values.rgb[i])) hi = std::max(hi, double(values.rgb[i]));
  return {0, hi > 0 ? hi : 1};
}

std::string scale_label(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

Image make_heatmap(const Image& values, const HeatmapScale& scale) {
  Image out(values.width + kBarWidth, values.height);
  const double span = scale.hi > scale.lo ? scale.hi - scale.lo : 1;
  for (int y = 0; y < values.height; ++y)
    for (int x = 0; x < values.width; ++x)
      out.set(x, y, heat_color((double(values.at(x, y).x) - scale.lo) / span));
  // The bar: high at the top, with the scale's ends and middle written beside it.
  const int top = 6, bottom = std::max(top + 1, values.height - 6);
  const int bar_x = values.width + 4;
  for (int y = 0; y < values.height; ++y)
    for (int x = values.width; x < out.width; ++x) out.set(x, y, Vec3f{1, 1, 1});
  for (int y = top; y < bottom; ++y)
    for (int x = bar_x; x < bar_x + kBarStripe; ++x)
      out.set(x, y, heat_color(double(bottom - 1 - y) / double(std::max(1, bottom - top - 1))));
  const Vec3f ink{0, 0, 0};
  const int text_x = bar_x + kBarStripe + 2;
  draw_text(out, text_x, top, scale_label(scale.hi), 1, ink);
  draw_text(out, text_x, (top + bottom) / 2 - 2, scale_label(0.5 * (scale.lo + scale.hi)), 1, ink);
  draw_text(out, text_x, bottom - 5, scale_label(scale.lo), 1, ink);
  return out;
}

}  // namespace raycast
