// The generic binned-SAH builder: structure invariants over random boxes, for every option the
// mesh layer uses (leaf blocks, parallel binning on large nodes, small-node bins).
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <random>

#include <tbb/global_control.h>

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
    const Bvh bvh = build_bvh(in.boxes, c);
    check_structure(bvh, in, c.max_leaf_size);
  }
}

// The leaves' contents in traversal order (node numbering may differ with task order).
std::vector<std::uint32_t> leaves_in_order(const Bvh& bvh) {
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
}

Bvh build_with_threads(const Input& in, const BvhBuildConfig& c, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return build_bvh(in.boxes, c);
}

TEST(BvhBuild, OneTwoAndFourThreads_SameTree) {
  std::mt19937 rng(42);
  for (bool clustered : {false, true}) {
    const Input in = random_boxes(rng, 100000, clustered);
    BvhBuildConfig c;
    c.parallel_binning_threshold = 4096;  // parallel binning and partition over several chunks
    c.parallel_threshold = 512;
    c.leaf_block = 4;
    const Bvh one = build_with_threads(in, c, 1);
    check_structure(one, in, c.max_leaf_size);
    const std::vector<std::uint32_t> expected = leaves_in_order(one);
    for (int threads : {2, 4}) {
      const Bvh b = build_with_threads(in, c, threads);
      EXPECT_EQ(leaves_in_order(b), expected) << threads << " threads";
      EXPECT_EQ(b.nodes.size(), one.nodes.size());
      EXPECT_EQ(sah_cost(b, c), sah_cost(one, c));
    }
  }
}

// The thresholds choose how nodes are binned and partitioned (serially or in chunks), which may
// order primitives differently inside a leaf, but never which primitives a leaf gets.
TEST(BvhBuild, SerialOrParallelPartition_SameLeaves) {
  std::mt19937 rng(43);
  const Input in = random_boxes(rng, 40000, false);
  BvhBuildConfig serial;
  serial.parallel_binning_threshold = ~std::size_t(0);
  serial.parallel_threshold = ~std::size_t(0);
  BvhBuildConfig parallel;
  parallel.parallel_binning_threshold = 1024;
  parallel.parallel_threshold = 1024;
  auto sorted_leaves = [](const Bvh& bvh) {
    std::vector<std::uint32_t> out = leaves_in_order(bvh);
    for (auto b = out.begin(); b != out.end();) {
      const auto e = std::find(b, out.end(), ~0u);
      std::sort(b, e);
      b = e + 1;
    }
    return out;
  };
  EXPECT_EQ(sorted_leaves(build_bvh(in.boxes, serial)),
            sorted_leaves(build_bvh(in.boxes, parallel)));
}

TEST(BvhBuild, NearestTraversal_MatchesBruteForceOverBoxes) {
  std::mt19937 rng(7);
  const Input in = random_boxes(rng, 3000, false);
  const Bvh bvh = build_bvh(in.boxes);
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
  const Bvh bvh = build_bvh({});
  EXPECT_TRUE(bvh.empty());
  EXPECT_TRUE(bvh.prims.empty());
}

TEST(BvhBuild, HugeAndTinyCoordinates_EveryPrimOnceAndBoxesHoldThem) {
  // Boxes beyond float range (clamped in the build references: node boxes reach infinity) mixed
  // with ordinary and denormal-sized ones.
  Input in;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3000; ++i) {
    const double scale = i % 3 == 0 ? 1e300 : (i % 3 == 1 ? 1e-300 : 1.0);
    const Vec3 c{u(rng) * scale, u(rng) * scale, u(rng) * scale};
    const Vec3 e{0.1 * scale, 0.2 * scale, 0.05 * scale};
    in.boxes.push_back({c - e, c + e});
    in.centres.push_back(c);
  }
  in.boxes.push_back({{-DBL_MAX, -1, -1}, {DBL_MAX, 1, 1}});
  in.centres.push_back({0, 0, 0});
  BvhBuildConfig c;
  c.max_leaf_size = 4;
  check_structure(build_bvh(in.boxes, c), in, 4);
}

TEST(BvhBuild, BuildRef_RoundsOutwardsToTheNearestFloats) {
  const BvhBuildRef r = make_build_ref({{0.1, -0.1, 1}, {0.3, 1e-50, 2}}, 7);
  EXPECT_EQ(r.index, 7u);
  EXPECT_EQ(r.lo[0], std::nextafter(0.1f, 0.0f));  // 0.1f is above 0.1
  EXPECT_EQ(r.lo[1], -0.1f);                       // -0.1f is below -0.1
  EXPECT_EQ(r.lo[2], 1.0f);
  EXPECT_EQ(r.hi[0], 0.3f);  // 0.3f is above 0.3
  EXPECT_EQ(r.hi[1], std::nextafter(0.0f, 1.0f));
  EXPECT_EQ(r.hi[2], 2.0f);
  const BvhBuildRef big = make_build_ref({{-1e300, 0, 0}, {1e300, 0, 0}}, 0);
  EXPECT_EQ(big.lo[0], -kBuildRefLimit);
  EXPECT_EQ(big.hi[0], kBuildRefLimit);
}

TEST(BvhBuild, SahCost_TwoSeparateBoxes) {
  // Root [0,10]x[0,1]x[0,1] (half area 21) over two leaves of half area 3 each.
  const Input in{{{{0, 0, 0}, {1, 1, 1}}, {{9, 0, 0}, {10, 1, 1}}},
                 {{0.5, 0.5, 0.5}, {9.5, 0.5, 0.5}}};
  BvhBuildConfig c;
  c.max_leaf_size = 1;
  const Bvh bvh = build_bvh(in.boxes, c);
  ASSERT_EQ(bvh.nodes.size(), 3u);
  EXPECT_DOUBLE_EQ(sah_cost(bvh, c), 1 + 2 * 3.0 / 21);
  c.traversal_cost = 2;
  EXPECT_DOUBLE_EQ(sah_cost(bvh, c), 2 + 2 * 3.0 / 21);
  EXPECT_EQ(sah_cost(Bvh{}, c), 0);
}

}  // namespace
}  // namespace raycast
