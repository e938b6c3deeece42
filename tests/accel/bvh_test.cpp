#include "accel/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "accel/bvh_traverse.h"
#include "geometry/box.h"
#include "support/random.h"

namespace raycast {
namespace {

struct Prims {
  std::vector<Box> shapes;
  std::vector<Aabb> boxes;
  std::vector<Vec3> centres;
  void add(const Box& b) {
    shapes.push_back(b);
    boxes.push_back(bounds(b));
    centres.push_back(boxes.back().centre());
  }
};

Prims random_boxes(testing::Rng& rng, int n, double spread) {
  std::uniform_real_distribution<double> pos(-spread, spread), size(0.01, 1.5);
  Prims p;
  for (int i = 0; i < n; ++i) {
    const Vec3 lo{pos(rng), pos(rng), pos(rng)};
    p.add(make_box(lo, lo + Vec3{size(rng), size(rng), size(rng)}));
  }
  return p;
}

// Checks the tree's invariants; returns its depth (a root-only tree has depth 1).
int check_structure(const Bvh& bvh, const Prims& p, int max_leaf) {
  EXPECT_EQ(bvh.prims.size(), p.boxes.size());
  std::vector<std::uint32_t> sorted(bvh.prims.begin(), bvh.prims.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i) << "not a permutation";
  if (bvh.empty()) return 0;
  int depth = 0;
  std::vector<std::pair<std::uint32_t, int>> stack{{0, 1}};
  std::size_t leaf_prims = 0;
  while (!stack.empty()) {
    const auto [index, d] = stack.back();
    stack.pop_back();
    depth = std::max(depth, d);
    const BvhNode& node = bvh.nodes.at(index);
    if (node.is_leaf()) {
      EXPECT_LE(node.count, static_cast<std::uint32_t>(max_leaf));
      leaf_prims += node.count;
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Aabb& b = p.boxes[bvh.prims[i]];
        EXPECT_TRUE(node.box.contains(b.lo) && node.box.contains(b.hi));
      }
      continue;
    }
    for (std::uint32_t c : {node.first, node.first + 1}) {
      const Aabb& b = bvh.nodes.at(c).box;
      EXPECT_TRUE(node.box.contains(b.lo) && node.box.contains(b.hi));
      stack.push_back({c, d + 1});
    }
  }
  EXPECT_EQ(leaf_prims, p.boxes.size());
  return depth;
}

// The nearest hit and any-hit through the BVH against testing every primitive.
void compare_with_brute_force(const Bvh& bvh, const Prims& p, testing::Rng& rng, int rays,
                              double spread) {
  for (int i = 0; i < rays; ++i) {
    Ray ray = testing::random_ray(rng, spread, spread);
    if (i % 3 == 0) ray.tmax = std::uniform_real_distribution<double>(0, spread)(rng);
    double best = kInfinity;
    bool any = false;
    for (const Box& b : p.shapes) {
      LocalHit h;
      if (intersect(b, ray, h)) {
        any = true;
        best = std::min(best, h.t);
      }
    }
    double tmax = ray.tmax, found = kInfinity;
    std::int64_t found_prim = -1;
    traverse_nearest(bvh, ray.o, ray.d, ray.tmin, tmax, [&](std::uint32_t prim, double& t) {
      Ray r = ray;
      r.tmax = t;
      LocalHit h;
      if (intersect(p.shapes[prim], r, h)) {
        t = h.t;
        found = h.t;
        found_prim = prim;
      }
    });
    ASSERT_EQ(found, best) << "ray " << i;
    if (found_prim >= 0) {
      LocalHit h;
      ASSERT_TRUE(intersect(p.shapes[found_prim], ray, h));
      EXPECT_EQ(h.t, best);
    }
    const bool blocked =
        traverse_any(bvh, ray.o, ray.d, ray.tmin, ray.tmax,
                     [&](std::uint32_t prim) { return occluded(p.shapes[prim], ray); });
    ASSERT_EQ(blocked, any) << "ray " << i;
    std::vector<char> visited(p.shapes.size(), 0);
    traverse_all(bvh, ray.o, ray.d, ray.tmin, ray.tmax,
                 [&](std::uint32_t prim) { visited[prim] = 1; });
    for (std::size_t k = 0; k < p.shapes.size(); ++k) {
      if (occluded(p.shapes[k], ray)) {
        EXPECT_TRUE(visited[k]) << "ray " << i << " prim " << k;
      }
    }
  }
}

TEST(Bvh, NoPrimitives_EmptyTreeAndNoHits) {
  const Bvh bvh = build_bvh({});
  EXPECT_TRUE(bvh.empty());
  EXPECT_TRUE(bvh.prims.empty());
  double tmax = kInfinity;
  int calls = 0;
  traverse_nearest(bvh, {0, 0, 0}, {1, 0, 0}, 0, tmax, [&](std::uint32_t, double&) { ++calls; });
  EXPECT_FALSE(traverse_any(bvh, {0, 0, 0}, {1, 0, 0}, 0, kInfinity, [&](std::uint32_t) {
    ++calls;
    return true;
  }));
  EXPECT_EQ(calls, 0);
}

TEST(Bvh, OnePrimitive_SingleLeaf) {
  Prims p;
  p.add(make_box({1, -1, -1}, {2, 1, 1}));
  const Bvh bvh = build_bvh(p.boxes);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_TRUE(bvh.nodes[0].is_leaf());
  check_structure(bvh, p, 8);
  testing::Rng rng(1);
  compare_with_brute_force(bvh, p, rng, 500, 3);
  double tmax = kInfinity;
  std::uint32_t seen = 99;
  traverse_nearest(bvh, {0, 0, 0}, {1, 0, 0}, 0, tmax,
                   [&](std::uint32_t prim, double&) { seen = prim; });
  EXPECT_EQ(seen, 0u);
}

TEST(Bvh, AllEqualCentres_SplitByIndexAndStillCorrect) {
  Prims p;
  for (int i = 0; i < 1000; ++i) {
    const double h = 0.1 + 0.001 * i;  // nested boxes around one centre
    p.add(make_box({-h, -h, -h}, {h, h, h}));
  }
  BvhBuildConfig config;
  config.max_leaf_size = 4;
  const Bvh bvh = build_bvh(p.boxes, config);
  const int depth = check_structure(bvh, p, 4);
  EXPECT_LE(depth, 12);  // halving 1000 down to leaves of 4
  testing::Rng rng(2);
  compare_with_brute_force(bvh, p, rng, 300, 2);
}

TEST(Bvh, RandomBoxes_NearestAndAnyHitMatchBruteForce) {
  const unsigned seed = 12345;
  SCOPED_TRACE("seed " + std::to_string(seed));
  testing::Rng rng(seed);
  for (int n : {2, 3, 17, 100, 2000}) {
    const Prims p = random_boxes(rng, n, 10);
    const Bvh bvh = build_bvh(p.boxes);
    check_structure(bvh, p, BvhBuildConfig{}.max_leaf_size);
    compare_with_brute_force(bvh, p, rng, n >= 2000 ? 300 : 1000, 12);
  }
}

TEST(Bvh, ParallelBuild_SameTreeAsSerial) {
  testing::Rng rng(6);
  const Prims p = random_boxes(rng, 20000, 50);
  BvhBuildConfig serial;
  serial.parallel_threshold = ~std::size_t{0};
  BvhBuildConfig parallel;
  parallel.parallel_threshold = 64;
  const Bvh a = build_bvh(p.boxes, serial);
  const Bvh b = build_bvh(p.boxes, parallel);
  check_structure(b, p, 8);
  EXPECT_EQ(a.prims, b.prims);
  compare_with_brute_force(b, p, rng, 100, 55);
}

// Pinned bug: with centres at 2^(5 i) each SAH split could only peel off the largest primitive,
// so the tree grew deeper than the traversal stacks (128 entries), which then silently dropped
// subtrees. Deep nodes now split at the object median.
TEST(Bvh, SuperExponentiallySpacedBoxes_DepthBoundedAndTraversalComplete) {
  Prims p;
  for (int i = 0; i < 200; ++i) {
    const double c = std::ldexp(1.0, 5 * i);
    p.add(make_box({c, -1, -1}, {1.2 * c, 1, 1}));
  }
  BvhBuildConfig config;
  config.max_leaf_size = 1;
  const Bvh bvh = build_bvh(p.boxes, config);
  const int depth = check_structure(bvh, p, 1);
  EXPECT_LE(depth, 100);
  // A ray along the chain crosses every box: every one must be visited, the last one found.
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  std::vector<char> visited(p.shapes.size(), 0);
  traverse_all(bvh, ray.o, ray.d, 0, kInfinity, [&](std::uint32_t prim) { visited[prim] = 1; });
  EXPECT_EQ(std::count(visited.begin(), visited.end(), 1), 200);
  EXPECT_TRUE(traverse_any(bvh, ray.o, ray.d, 0, kInfinity,
                           [&](std::uint32_t prim) { return prim == 199; }));
  // Nearest, when only the farthest box counts as a hit.
  double tmax = kInfinity, best = kInfinity;
  traverse_nearest(bvh, ray.o, ray.d, 0, tmax, [&](std::uint32_t prim, double& t) {
    LocalHit h;
    if (prim == 199 && intersect(p.shapes[prim], Ray{ray.o, ray.d, 0, t}, h)) t = best = h.t;
  });
  EXPECT_EQ(best, std::ldexp(1.0, 5 * 199));
  testing::Rng rng(7);
  compare_with_brute_force(bvh, p, rng, 200, 2);
}

}  // namespace
}  // namespace raycast
