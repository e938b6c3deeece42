#include "render/camera_packets.h"

#include <array>
#include <bit>
#include <utility>

#include "math/lane_array.h"

namespace raycast {

namespace {

// The lanes' sample states, lane l for pixel (x0 + l % 4, y0 + l / 4) (SampleState has no
// default: its generator is always some pixel's).
template <std::size_t... L>
std::array<SampleState, sizeof...(L)> lane_states(std::index_sequence<L...>, int x0, int y0,
                                                  unsigned seed) {
  return {SampleState{Rng::for_pixel(x0 + int(L % 4), y0 + int(L / 4), seed), 0}...};
}

template <int W>
void render_blocks(const ScenePackets& packets, const Camera& camera, const Integrator& integrator,
                   int spp, unsigned seed, const PixelRect& tile, const PixelRect& region,
                   Image& image, std::uint64_t& rays) {
  constexpr int kRows = W / 4;
  for (int y0 = tile.y0; y0 < tile.y1; y0 += kRows) {
    for (int x0 = tile.x0; x0 < tile.x1; x0 += 4) {
      // The block's pixels inside the tile (the tile's right and bottom blocks may be partial).
      int mask = 0;
      for (int l = 0; l < W; ++l)
        if (x0 + l % 4 < tile.x1 && y0 + l / 4 < tile.y1) mask |= 1 << l;
      std::array<SampleState, W> state = lane_states(std::make_index_sequence<W>{}, x0, y0, seed);
      LaneArray<Color, W> sum;  // spp > 1: the active lanes' sums
      LaneArray<Ray, W> ray;
      LaneArray<SceneHit, W> hit;
      if (spp > 1)
        for (int l = 0; l < W; ++l) sum[l] = Color{0, 0, 0};
      for (int k = 0; k < spp; ++k) {
        for (int m = mask; m != 0; m &= m - 1) {
          const int l = std::countr_zero(static_cast<unsigned>(m));
          const int x = x0 + l % 4, y = y0 + l / 4;
          if (spp == 1) {  // the centre, as sample_offset gives for n = 1
            ray[l] = camera.ray(x + 0.5, y + 0.5);
            continue;
          }
          double ox, oy;
          const double jx = state[l].rng.uniform();
          const double jy = state[l].rng.uniform();
          sample_offset(k, spp, jx, jy, ox, oy);
          ray[l] = camera.ray(x + ox, y + oy);
        }
        const int found = packets.intersect(ray.data(), mask, hit.data());
        for (int m = mask; m != 0; m &= m - 1) {
          const int l = std::countr_zero(static_cast<unsigned>(m));
          const Color c = integrator.li_hit(ray[l], found >> l & 1, hit[l], state[l]);
          if (spp == 1)
            image.set(x0 + l % 4 - region.x0, y0 + l / 4 - region.y0, Vec3f(c));
          else
            sum[l] += c;
        }
      }
      for (int m = mask; m != 0; m &= m - 1) {
        const int l = std::countr_zero(static_cast<unsigned>(m));
        if (spp > 1)
          image.set(x0 + l % 4 - region.x0, y0 + l / 4 - region.y0, Vec3f(sum[l] / double(spp)));
        rays += state[l].rays;
      }
    }
  }
}

}  // namespace

void render_packet_tile(const ScenePackets& packets, const Camera& camera,
                        const Integrator& integrator, int spp, unsigned seed, const PixelRect& tile,
                        const PixelRect& region, Image& image, std::uint64_t& rays) {
  if (packets.width() > 8)
    render_blocks<16>(packets, camera, integrator, spp, seed, tile, region, image, rays);
  else
    render_blocks<8>(packets, camera, integrator, spp, seed, tile, region, image, rays);
}

}  // namespace raycast
