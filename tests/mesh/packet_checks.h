#pragma once
// Checks shared by the packet tests: each lane of a packet's answer against to_mesh_ray and the
// single-ray kernel, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesh/mesh.h"
#include "mesh/wide_kernels.h"

namespace raycast {

/// Whether to_mesh_ray takes its fast path (finite direction whose largest |component| has a
/// normal, not extreme exponent).
inline bool fast_conversion(const Ray& r) {
  if (!std::isfinite(r.d.x) || !std::isfinite(r.d.y) || !std::isfinite(r.d.z)) return false;
  const double m = std::max(std::abs(r.d.x), std::max(std::abs(r.d.y), std::abs(r.d.z)));
  const int e = std::ilogb(m);
  return m >= std::numeric_limits<double>::min() && e > -1022 && e < 1022;
}

/// Lanes [0, lanes) of packet `packet` traced with `mask` gave `found` (a hit mask), `hits` and
/// `scales`: idle lanes keep triangle 12345, active ones equal the single-ray kernel on the
/// converted ray. Adds the lanes that hit to `hits_seen`.
inline void expect_lanes_equal_single_rays(const MeshKernels& kernels, const MeshBvh& bvh,
                                           const Ray* rays, int lanes, int mask, int found,
                                           const MeshBvhHit* hits, const double* scales,
                                           TraversalEntry* stack, int packet, int& hits_seen) {
  ASSERT_GE(found, 0) << "packet " << packet;
  EXPECT_EQ(found & ~mask, 0);
  for (int l = 0; l < lanes; ++l) {
    if (!(mask >> l & 1)) {
      EXPECT_EQ(hits[l].triangle, 12345u);
      continue;
    }
    double scale;
    const MeshRay r = to_mesh_ray(rays[l], scale);
    EXPECT_EQ(scales[l], scale) << "packet " << packet << " lane " << l;
    MeshBvhHit one;
    const bool hit = kernels.closest(bvh, r, one, stack);
    ASSERT_EQ((found >> l & 1) != 0, hit) << "packet " << packet << " lane " << l;
    if (!hit) continue;
    ++hits_seen;
    EXPECT_EQ(hits[l].t, one.t);
    EXPECT_EQ(hits[l].b1, one.b1);
    EXPECT_EQ(hits[l].b2, one.b2);
    EXPECT_EQ(hits[l].triangle, one.triangle);
  }
}

}  // namespace raycast
