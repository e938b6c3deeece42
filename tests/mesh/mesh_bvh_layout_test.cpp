// The mesh BVH's memory layout: the same bytes, in the same places, for any thread count (the
// leaves' groups are placed in a serial pass, not in the order the builder's tasks run).
#include <gtest/gtest.h>

#include <cstring>

#include <tbb/global_control.h>

#include "mesh/mesh_bvh.h"
#include "mesh/procedural.h"

namespace raycast {
namespace {

MeshBvh build_with_threads(const TriangleSoup& mesh, int threads, const MeshBvhConfig& config) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return build_mesh_bvh(mesh.positions, mesh.triangles, config);
}

template <class V>
bool same_bytes(const V& a, const V& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0);
}

TEST(MeshBvhLayout, OneAndTwoThreads_SameArrays) {
  // Above the builder's parallel binning threshold (65536), so both builds split work; float
  // and quantised nodes.
  for (const char* name : {"sphere", "forest"}) {
    const TriangleSoup mesh = make_procedural_mesh(name, 200000);
    for (const bool quantised : {false, true}) {
      MeshBvhConfig config;
      config.quantise_above = quantised ? 0 : config.quantise_above;
      const MeshBvh a = build_with_threads(mesh, 1, config);
      const MeshBvh b = build_with_threads(mesh, 2, config);
      ASSERT_EQ(a.quantised, quantised) << name;
      EXPECT_EQ(a.root, b.root) << name;
      EXPECT_TRUE(same_bytes(a.nodes, b.nodes)) << name << " quantised " << quantised;
      EXPECT_TRUE(same_bytes(a.qnodes, b.qnodes)) << name << " quantised " << quantised;
      // NaN padding lanes are written by the same code in both: compared as bytes.
      EXPECT_TRUE(same_bytes(a.groups, b.groups)) << name << " quantised " << quantised;
    }
  }
}

}  // namespace
}  // namespace raycast
