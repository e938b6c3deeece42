// Packets of sixteen rays (mesh/mesh_packet16.h) on every ISA (those the CPU lacks are skipped):
// with mixed masks, mixed direction signs, non-finite origins and segment ends, and directions
// of any magnitude, each lane's hit and scale equal those of to_mesh_ray and the single-ray
// kernel, bit for bit; -1 exactly when an active ray needs the slow conversion. AVX-512 traces
// the sixteen as one packet, the others as two packets of eight.
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

class Packet16 : public testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    kernels_ = mesh_kernels(GetParam());
    if (!kernels_) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  }
  const MeshKernels* kernels_ = nullptr;
};

TEST_P(Packet16, Width) {
  EXPECT_EQ(packet_width(GetParam()), GetParam() == Isa::kAvx512 ? 16 : 8);
}

TEST_P(Packet16, MixedMasks_EqualSingleRays) {
  const TriangleSoup sphere = make_octa_sphere(16);
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(-1, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (bool quantised : {false, true}) {
    MeshBvhConfig config;
    config.quantise_above = quantised ? 0 : std::numeric_limits<std::size_t>::max();
    const MeshBvh bvh = build_mesh_bvh(sphere.positions, sphere.triangles, config);
    std::vector<TraversalEntry> stack(traversal_stack_size(bvh));
    int hits_seen = 0, slow_seen = 0, odd_seen = 0;
    for (int i = 0; i < 400; ++i) {
      // A camera-like bundle towards the sphere, each ray's direction scaled by its own power of
      // two (t scales back).
      const Vec3 o{u(rng) * 0.2, u(rng) * 0.2, 3 + u(rng)};
      Ray rays[16];
      for (int l = 0; l < 16; ++l) {
        const Vec3 d{u(rng) * 0.4, u(rng) * 0.4, -1};
        const int k =
            i % 4 == 0 ? static_cast<int>(rng() % 2000) - 1000 : static_cast<int>(rng() % 40) - 20;
        const double s = std::ldexp(1.0, k);
        rays[l] = Ray{o, d * s, (i % 5 == 0 ? 0.5 : 0.0) / s, (i % 7 == 0 ? 2.5 : kInfinity) / s};
      }
      // Lanes that cannot go in one packet or that need the slow conversion.
      switch (i % 10) {
        case 1:
          rays[11].d = rays[11].d * -1.0;
          break;  // a lane against the others
        case 2:
          rays[12].o.x = nan;
          break;  // NaN origin: no hit
        case 3:
          rays[13].o.y = kInfinity;
          break;  // infinite origin
        case 4:
          rays[9].tmin = nan;
          break;  // NaN segment end
        case 5:
          rays[14].d.z = nan;
          break;  // NaN direction: slow path
        case 6:
          rays[15].d = Vec3{kInfinity, 0, -1};
          break;  // infinite direction: slow
        case 7:
          rays[10].d = rays[10].d * 1e-310;
          break;  // subnormal: slow
        case 8:
          rays[3].d = Vec3{0, 0, -1};
          break;  // zero components
        default:
          break;
      }
      const int mask = i % 9 == 0   ? static_cast<int>(rng() & 0xFF00)  // upper half only
                       : i % 9 == 1 ? static_cast<int>(rng() & 0x00FF)  // lower half only
                                    : static_cast<int>(rng() & 0xFFFF);
      bool slow = false;
      for (int l = 0; l < 16; ++l) slow = slow || ((mask >> l & 1) && !fast_conversion(rays[l]));
      MeshBvhHit hits[16];
      for (MeshBvhHit& h : hits) h.triangle = 12345;  // idle lanes must keep this
      double scales[16];
      const int found = intersect_closest16(bvh, GetParam(), rays, mask, hits, scales);
      if (slow) {
        EXPECT_EQ(found, -1) << "packet " << i;
        ++slow_seen;
        continue;
      }
      expect_lanes_equal_single_rays(*kernels_, bvh, rays, 16, mask, found, hits, scales,
                                     stack.data(), i, hits_seen);
      if (i % 10 >= 1 && i % 10 <= 4) ++odd_seen;
      if (HasFailure()) return;
    }
    EXPECT_GT(hits_seen, 1000);
    EXPECT_GT(slow_seen, 30);
    EXPECT_GT(odd_seen, 100);
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, Packet16, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& info) {
                           return std::string(isa_name(info.param));
                         });

// The MeshShape call with the active ISA: the same LocalHit as one ray at a time, including
// packets with a slow-conversion lane (converted one by one).
TEST(Packet16Shape, EqualSingleRays) {
  const TriangleSoup soup = make_procedural_mesh("sphere", 5000);
  const MeshShape shape{make_mesh(soup.positions, soup.triangles)};
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits_seen = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 o{u(rng) * 0.3, u(rng) * 0.3, 3};
    Ray rays[16];
    for (int l = 0; l < 16; ++l)
      rays[l] = Ray{o, Vec3{u(rng) * 0.3, u(rng) * 0.3, -1}, 0, i % 3 ? kInfinity : 3.0};
    if (i % 7 == 0) rays[5].d = rays[5].d * 1e-310;  // the slow conversion
    const int mask = i % 5 ? static_cast<int>(rng() & 0xFFFF) : 0xFFFF;
    LocalHit hits[16];
    const int found = intersect16(shape, rays, mask, hits);
    EXPECT_EQ(found & ~mask, 0);
    for (int l = 0; l < 16; ++l) {
      if (!(mask >> l & 1)) continue;
      LocalHit one;
      const bool hit = intersect(shape, rays[l], one);
      ASSERT_EQ((found >> l & 1) != 0, hit) << "packet " << i << " lane " << l;
      if (!hit) continue;
      ++hits_seen;
      EXPECT_EQ(hits[l].t, one.t);
      EXPECT_EQ(hits[l].prim, one.prim);
      EXPECT_EQ(hits[l].part, one.part);
      EXPECT_EQ(hits[l].a, one.a);
      EXPECT_EQ(hits[l].b, one.b);
    }
    if (HasFailure()) return;
  }
  EXPECT_GT(hits_seen, 1000);
}

}  // namespace
}  // namespace raycast
