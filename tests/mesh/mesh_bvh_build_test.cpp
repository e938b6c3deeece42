// The mesh BVH's build: the same tree for any thread count, and leaves sized for the leaf test.
#include <gtest/gtest.h>

#include <cstring>

#include <tbb/global_control.h>

#include "mesh/mesh_bvh.h"
#include "mesh/procedural.h"

namespace raycast {
namespace {

MeshBvh build_with_threads(const TriangleSoup& mesh, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return build_mesh_bvh(mesh.positions, mesh.triangles);
}

// The tree under `ref` depth first, as bytes: each node's used mask and child boxes, each leaf's
// groups (vertices, triangle ids). Where nodes and groups sit in their arrays is left out: the
// binary builder numbers its nodes in the order its tasks finish, so the layout may differ with
// the thread count while the tree is the same.
void serialise(const MeshBvh& bvh, std::uint32_t ref, std::vector<unsigned char>& out) {
  const auto put = [&](const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    out.insert(out.end(), c, c + n);
  };
  if (ref & kLeafBit) {
    const std::uint32_t first = ref & 0x1FFFFFFFu, count = ((ref >> 29) & 3u) + 1;
    put(&count, sizeof count);
    for (std::uint32_t g = first; g < first + count; ++g) {
      put(bvh.groups[g].v, sizeof bvh.groups[g].v);  // NaN padding lanes: compared as bytes
      put(bvh.groups[g].id, sizeof bvh.groups[g].id);
    }
    return;
  }
  const WideNode& n = bvh.nodes[ref];
  put(&n.used, sizeof n.used);
  put(n.box, sizeof n.box);
  for (int i = 0; i < kNodeWidth; ++i)
    if (n.used >> i & 1) serialise(bvh, n.child[i], out);
}

// Leaf references of the tree under `ref`.
void leaves(const MeshBvh& bvh, std::uint32_t ref, std::vector<std::uint32_t>& out) {
  if (ref & kLeafBit) {
    out.push_back(ref);
    return;
  }
  const WideNode& n = bvh.nodes[ref];
  for (int i = 0; i < kNodeWidth; ++i)
    if (n.used >> i & 1) leaves(bvh, n.child[i], out);
}

TEST(MeshBvhBuild, OneAndTwoThreads_SameTree) {
  // Above the builder's parallel binning threshold (65536), so both builds split work.
  for (const char* name : {"sphere", "forest"}) {
    const TriangleSoup mesh = make_procedural_mesh(name, 200000);
    const MeshBvh a = build_with_threads(mesh, 1);
    const MeshBvh b = build_with_threads(mesh, 2);
    ASSERT_EQ(a.depth, b.depth) << name;
    ASSERT_EQ(a.nodes.size(), b.nodes.size()) << name;
    ASSERT_EQ(a.groups.size(), b.groups.size()) << name;
    std::vector<unsigned char> sa, sb;
    serialise(a, a.root, sa);
    serialise(b, b.root, sb);
    EXPECT_TRUE(sa == sb) << name;
  }
}

TEST(MeshBvhBuild, DefaultLeaves_FitOneLeafPass) {
  // The default SAH charges leaves per pair of groups (MeshBvhConfig::leaf_block 8), the AVX2 and
  // AVX-512 leaf test's pass: every leaf is one or two groups, and most hold more than 4
  // triangles.
  const TriangleSoup mesh = make_procedural_mesh("sphere", 100000);
  const MeshBvh bvh = build_mesh_bvh(mesh.positions, mesh.triangles);
  std::vector<std::uint32_t> refs;
  leaves(bvh, bvh.root, refs);
  ASSERT_FALSE(refs.empty());
  std::size_t two = 0;
  for (std::uint32_t ref : refs) {
    const std::uint32_t groups = ((ref >> 29) & 3u) + 1;
    EXPECT_LE(groups, 2u);
    two += groups == 2;
  }
  EXPECT_GT(2 * two, refs.size());
}

}  // namespace
}  // namespace raycast
