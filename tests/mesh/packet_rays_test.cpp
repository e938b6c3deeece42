// The packet kernels' own conversion of double rays (MeshKernels::closest8_rays) on every ISA
// (those the CPU lacks are skipped): with mixed masks, directions of any magnitude and segment ends
// one rounding away from a hit, each lane's hit and scale equal those of to_mesh_ray (mesh/mesh.h)
// and the single-ray kernel, bit for bit; -1 exactly when an active ray needs the slow path.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "mesh/wide_kernels.h"
#include "packet_checks.h"

namespace raycast {
namespace {

class PacketRays : public testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    kernels_ = mesh_kernels(GetParam());
    if (!kernels_) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  }
  const MeshKernels* kernels_ = nullptr;
};

TEST_P(PacketRays, MixedMasks_EqualSingleRays) {
  const TriangleSoup sphere = make_octa_sphere(16);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  for (bool quantised : {false, true}) {
    MeshBvhConfig config;
    config.quantise_above = quantised ? 0 : std::numeric_limits<std::size_t>::max();
    const MeshBvh bvh = build_mesh_bvh(sphere.positions, sphere.triangles, config);
    std::vector<TraversalEntry> stack(traversal_stack_size(bvh));
    std::vector<PacketEntry> packet_stack(traversal_stack_size(bvh));
    int hits_seen = 0, slow_seen = 0, edge_seen = 0;
    for (int i = 0; i < 400; ++i) {
      // A camera-like bundle towards the sphere, each ray's direction scaled by its own power of
      // two (t scales back): the same segments in any units.
      const Vec3 o{u(rng) * 0.2, u(rng) * 0.2, 3 + u(rng)};
      Ray rays[8];
      for (int l = 0; l < 8; ++l) {
        const Vec3 d{u(rng) * 0.4, u(rng) * 0.4, -1};
        const int k =
            i % 4 == 0 ? static_cast<int>(rng() % 2000) - 1000 : static_cast<int>(rng() % 40) - 20;
        const double s = std::ldexp(1.0, k);
        rays[l] = Ray{o, d * s, (i % 5 == 0 ? 0.5 : 0.0) / s, (i % 7 == 0 ? 2.5 : kInfinity) / s};
        if (i % 11 == 0 && l == 3) rays[l].d = d * 1e-310;  // subnormal: the slow path
        if (i % 13 == 0 && l == 5) rays[l].d = d * 1e308;   // near overflow: the slow path
      }
      // Every third packet: segment ends next to lane 0's hit, so a wrong rounding direction of
      // tmin or tmax drops that hit.
      if (i % 3 == 0 && fast_conversion(rays[0])) {
        double scale;
        MeshBvhHit h;
        if (kernels_->closest(bvh, to_mesh_ray(rays[0], scale), h, stack.data())) {
          // Just above the float below the hit (tmax) or just below the float above it (tmin):
          // rounded outwards the segment keeps the hit, rounded to nearest it loses it.
          const float below = std::nextafter(h.t, -std::numeric_limits<float>::infinity()),
                      above = std::nextafter(h.t, std::numeric_limits<float>::infinity());
          for (int l = 0; l < 8; ++l) {
            rays[l].d = rays[0].d;
            rays[l].tmin = l % 2 ? std::nextafter(above * scale, 0.0) : rays[0].tmin;
            rays[l].tmax = l % 2 ? rays[0].tmax : std::nextafter(below * scale, kInfinity);
          }
          ++edge_seen;
        }
      }
      const int mask = static_cast<int>(rng() & 0xFF);
      bool slow = false;
      for (int l = 0; l < 8; ++l) slow = slow || ((mask >> l & 1) && !fast_conversion(rays[l]));
      MeshBvhHit hits[8];
      for (MeshBvhHit& h : hits) h.triangle = 12345;  // idle lanes must keep this
      double scales[8];
      const int found =
          kernels_->closest8_rays(bvh, rays, mask, hits, scales, packet_stack.data(), stack.data());
      if (slow) {
        EXPECT_EQ(found, -1) << "packet " << i;
        ++slow_seen;
        continue;
      }
      expect_lanes_equal_single_rays(*kernels_, bvh, rays, 8, mask, found, hits, scales,
                                     stack.data(), i, hits_seen);
      if (HasFailure()) return;
    }
    EXPECT_GT(hits_seen, 500);
    EXPECT_GT(slow_seen, 10);
    EXPECT_GT(edge_seen, 30);
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, PacketRays, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& info) {
                           return std::string(isa_name(info.param));
                         });

}  // namespace
}  // namespace raycast
