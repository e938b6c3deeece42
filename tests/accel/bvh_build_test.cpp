// The generic binned-SAH builder: structure invariants over random boxes, for every option the
// mesh layer uses (leaf blocks, parallel binning on large nodes, small-node bins).
#include <gtest/gtest.h>

#include <random>

#include "accel/bvh.h"
#include "accel/bvh_traverse.h"

namespace raycast {
namespace {

struct Input {
  std::vector<Aabb> boxes;
  std::vector<Vec3> centres;
};

Input random_boxes(std::mt19937& rng, std::size_t n, bool clustered) {
  std::uniform_real_distribution<double> u(-10, 10), s(0, 0.5);
  Input in;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 c{u(rng), u(rng), u(rng)};
    if (clustered && i % 3 == 0) c = {1, 2, 3};  // many coincident centres
    const Vec3 e{s(rng), s(rng), s(rng)};
    in.boxes.push_back({c - e, c + e});
    in.centres.push_back(c);
  }
  return in;
}

// Every primitive in exactly one leaf; leaves within the size limit; node boxes hold their
// children.
void check_structure(const Bvh& bvh, const Input& in, int max_leaf) {
  ASSERT_EQ(bvh.prims.size(), in.boxes.size());
  std::vector<int> seen(in.boxes.size(), 0);
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const BvhNode& n = bvh.nodes[stack.back()];
    stack.pop_back();
    if (n.is_leaf()) {
      EXPECT_LE(n.count, static_cast<std::uint32_t>(max_leaf));
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const std::uint32_t p = bvh.prims[i];
        ++seen[p];
        EXPECT_TRUE(n.box.contains(in.boxes[p].lo) && n.box.contains(in.boxes[p].hi))
            << "prim " << p;
      }
      continue;
    }
    for (std::uint32_t c : {n.first, n.first + 1}) {
      const Aabb& b = bvh.nodes[c].box;
      EXPECT_TRUE(n.box.contains(b.lo) && n.box.contains(b.hi));
      stack.push_back(c);
    }
  }
  for (std::size_t p = 0; p < seen.size(); ++p) EXPECT_EQ(seen[p], 1) << "prim " << p;
}

TEST(BvhBuild, RandomBoxes_EveryPrimOnceAndBoxesNest) {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    const Input in = random_boxes(rng, seed % 2 ? 5000 : 40000, seed % 3 == 0);
    BvhBuildConfig c;
    c.max_leaf_size = 1 + static_cast<int>(seed % 8);
    c.leaf_block = seed % 2 ? 4 : 1;
    c.bins = seed % 2 ? 16 : 32;
    c.parallel_binning_threshold = 2048;
    const Bvh bvh = build_bvh(in.boxes, in.centres, c);
    check_structure(bvh, in, c.max_leaf_size);
  }
}

TEST(BvhBuild, SameResultWhateverTheParallelism) {
  std::mt19937 rng(42);
  const Input in = random_boxes(rng, 40000, false);
  BvhBuildConfig serial;
  serial.parallel_binning_threshold = ~std::size_t(0);
  serial.parallel_threshold = ~std::size_t(0);
  BvhBuildConfig parallel;
  parallel.parallel_binning_threshold = 1024;
  parallel.parallel_threshold = 1024;
  const Bvh a = build_bvh(in.boxes, in.centres, serial);
  const Bvh b = build_bvh(in.boxes, in.centres, parallel);
  // Node numbering may differ with task order; the leaves' contents in traversal order may not.
  auto leaves = [](const Bvh& bvh) {
    std::vector<std::uint32_t> out, stack{0};
    while (!stack.empty()) {
      const BvhNode& n = bvh.nodes[stack.back()];
      stack.pop_back();
      if (n.is_leaf()) {
        out.insert(out.end(), bvh.prims.begin() + n.first, bvh.prims.begin() + n.first + n.count);
        out.push_back(~0u);
      } else {
        stack.push_back(n.first + 1);
        stack.push_back(n.first);
      }
    }
    return out;
  };
  EXPECT_EQ(leaves(a), leaves(b));
}

TEST(BvhBuild, NearestTraversal_MatchesBruteForceOverBoxes) {
  std::mt19937 rng(7);
  const Input in = random_boxes(rng, 3000, false);
  const Bvh bvh = build_bvh(in.boxes, in.centres);
  std::uniform_real_distribution<double> u(-12, 12);
  for (int i = 0; i < 500; ++i) {
    const Vec3 o{u(rng), u(rng), u(rng)}, d{u(rng), u(rng), u(rng)};
    const Vec3 inv = reciprocal(d);
    double best = kInfinity;
    for (const Aabb& b : in.boxes) {
      double t;
      if (intersect_slabs(b, o, inv, 0, best, t)) best = std::min(best, t);
    }
    double tmax = kInfinity;
    traverse_nearest(bvh, o, d, 0, tmax, [&](std::uint32_t p, double& t) {
      double te;
      if (intersect_slabs(in.boxes[p], o, inv, 0, t, te)) t = std::min(t, te);
    });
    EXPECT_EQ(tmax, best) << "ray " << i;
  }
}

TEST(BvhBuild, Empty_HasNoNodes) {
  const Bvh bvh = build_bvh({}, {});
  EXPECT_TRUE(bvh.empty());
  EXPECT_TRUE(bvh.prims.empty());
}

}  // namespace
}  // namespace raycast
