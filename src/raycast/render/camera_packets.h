#pragma once
// The fixed-sample pixel loop with the camera rays traced as packets: a block of 4x2
// pixels (4x4 with 16-ray packets) traces its sample k as one packet through ScenePackets
// (scene/scene_packets.h), then each lane's hit is shaded on its own (Integrator::li_hit). Every
// pixel keeps its own SampleState and draws its numbers in the single-ray loop's order, so each
// pixel is that loop's bit for bit.
#include <cstdint>

#include "io/image.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "render/renderer.h"
#include "scene/scene_packets.h"

namespace raycast {

/// Renders the pixels of `tile` (a part of `region`, the rendered rectangle of the full image,
/// whose pixel (region.x0, region.y0) is image's (0, 0)) with `spp` samples each, as render()'s
/// fixed-sample loop does, and adds their rays to `rays`. `packets` must be usable().
void render_packet_tile(const ScenePackets& packets, const Camera& camera,
                        const Integrator& integrator, int spp, unsigned seed, const PixelRect& tile,
                        const PixelRect& region, Image& image, std::uint64_t& rays);

}  // namespace raycast
