#pragma once
// False-colour pictures of a per-pixel quantity (the cost outputs of render/pixel_record.h): a
// colour ramp from dark blue (low) through green and yellow to red (high), with a colour bar and
// its scale drawn beside the image.
#include <string>

#include "io/image.h"

namespace raycast {

/// The range a heatmap maps: `lo` to the ramp's start, `hi` to its end.
struct HeatmapScale {
  double lo = 0, hi = 0;
};

/// The ramp's colour at s in [0, 1] (clamped; NaN gives the start).
Vec3f heat_color(double s);

/// The scale of a grey image's first channel: 0 to its largest finite value (1 when that is 0).
HeatmapScale heatmap_scale(const Image& values);

/// The image's first channel in false colour over `scale`, with a colour bar on the right
/// labelled with the scale's ends and middle (the picture is 48 pixels wider than the image).
Image make_heatmap(const Image& values, const HeatmapScale& scale);

/// A number as the labels write it: up to 4 significant digits.
std::string scale_label(double value);

}  // namespace raycast
