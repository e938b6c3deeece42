// The packet kernels' leaf tests on every ISA (those the CPU lacks are skipped), packets of 8 and
// 16: rays with their own origins (an orthographic bundle, so each lane's watertight constants
// differ: the other packet tests share one origin), mixed masks, leaves of one to four groups,
// and bundles along a diagonal whose lanes differ in the watertight test's axis permutation.
// Every lane's hit equals the single-ray kernel's on the converted ray, bit for bit (checked to
// fail when a leaf test gives one lane another lane's origin).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh/mesh.h"
#include "mesh/mesh_packet16.h"
#include "mesh/procedural.h"
#include "mesh/wide_kernels.h"
#include "packet_checks.h"

namespace raycast {
namespace {

class PacketLeaves : public testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    kernels_ = mesh_kernels(GetParam());
    if (!kernels_) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  }
  const MeshKernels* kernels_ = nullptr;
};

TEST_P(PacketLeaves, OwnOriginsAndPermutations_EqualSingleRays) {
  const TriangleSoup sphere = make_octa_sphere(24);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int leaf_size : {4, 8, 12, 16}) {
    MeshBvhConfig config;
    config.max_leaf_size = leaf_size;
    const MeshBvh bvh = build_mesh_bvh(sphere.positions, sphere.triangles, config);
    std::vector<TraversalEntry> stack(traversal_stack_size(bvh));
    std::vector<PacketEntry> packet_stack(traversal_stack_size(bvh));
    int hits_seen = 0, shared_hits = 0;
    for (int i = 0; i < 300; ++i) {
      // Parallel rays from a small patch of origins: a few leaves each, several lanes per leaf.
      // Every other bundle runs along the diagonal (1, 1, -1) with each lane's direction nudged,
      // so the lanes' largest direction component (the permutation's kz) differs.
      const bool diagonal = i % 2 == 1;
      const Vec3 base{u(rng) * 0.6, u(rng) * 0.6, 3};
      const Vec3 d0 = diagonal ? Vec3{1, 1, -1} : Vec3{u(rng) * 0.1, u(rng) * 0.1, -1};
      const double spread = i % 3 == 0 ? 0.002 : 0.02;
      Ray rays[16];
      for (int l = 0; l < 16; ++l) {
        const Vec3 o = base + Vec3{u(rng) * spread, u(rng) * spread, u(rng) * spread};
        Vec3 d = d0;
        if (diagonal) d = Vec3{1 + u(rng) * 1e-3, 1 + u(rng) * 1e-3, -1 - u(rng) * 1e-3};
        const Vec3 from = diagonal ? o - Vec3{2, 2, 0} : o;
        const double s = std::ldexp(1.0, static_cast<int>(rng() % 9) - 4);
        rays[l] = Ray{from, d * s, 0.0, kInfinity};
      }
      for (int width : {8, 16}) {
        const int mask = static_cast<int>(rng() & ((1u << width) - 1));
        MeshBvhHit hits[16];
        for (MeshBvhHit& h : hits) h.triangle = 12345;  // idle lanes must keep this
        double scales[16];
        const int found = width == 8
                              ? kernels_->closest8_rays(bvh, rays, mask, hits, scales,
                                                        packet_stack.data(), stack.data())
                              : intersect_closest16(bvh, GetParam(), rays, mask, hits, scales);
        const int before = hits_seen;
        expect_lanes_equal_single_rays(*kernels_, bvh, rays, width, mask, found, hits, scales,
                                       stack.data(), i, hits_seen);
        if (!diagonal) shared_hits += hits_seen - before;
        if (HasFailure()) return;
      }
    }
    EXPECT_GT(hits_seen, 2000) << "leaf size " << leaf_size;
    EXPECT_GT(shared_hits, 1000) << "leaf size " << leaf_size;
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, PacketLeaves, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& info) {
                           return std::string(isa_name(info.param));
                         });

}  // namespace
}  // namespace raycast
