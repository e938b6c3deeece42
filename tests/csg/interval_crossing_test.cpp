// The interval walk (csg/interval_crossing.h) against first_crossing on random trees over random
// single intervals with frequent ties, and CsgShape's intersect (which takes the interval walk
// for trees of one-interval leaves) against the gather's walk (intersect_by_gather) on random
// trees of spheres, boxes, cylinders, cones and half-spaces: grid-aligned so that faces
// coincide, with rays along faces, tangent to spheres, from surface points, from inside, and
// with NaN and infinite components.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "csg/first_crossing.h"
#include "csg/interval_crossing.h"
#include "csg_oracle.h"
#include "objects/csg_tree.h"
#include "objects/prototype.h"
#include "random_tree.h"

namespace raycast {
namespace {

using csg_test::grow;
using csg_test::RandomTree;

TEST(IntervalCrossing, RandomTreesAndIntervals_SameAsFirstCrossing) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> grid(-6, 6), len(0, 3), coin(0, 9), flipcoin(0, 3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int compared = 0, hits = 0, ties = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    RandomTree t;
    grow(rng, t, 3);
    if (t.ops.empty() || t.leaves > CsgFormula::kMaxLeaves) continue;
    CsgFormula f;
    for (std::size_t k = 0; k < t.ops.size(); ++k) f.add(t.ops[k], t.operands[k]);
    std::vector<char> flipped(t.leaves);
    for (char& c : flipped) c = flipcoin(rng) == 0;
    f.finish(t.leaves, flipped);
    ASSERT_TRUE(f.is_tree());
    // One interval per leaf on a coarse grid (ties, zero length), sometimes infinite at an end
    // (no surface there), sometimes absent, rarely NaN.
    std::vector<LeafInterval> iv(t.leaves);
    std::uint64_t present = 0;
    for (std::size_t i = 0; i < t.leaves; ++i) {
      if (coin(rng) == 0) continue;
      LeafInterval& v = iv[i];
      v.t0 = grid(rng);
      v.t1 = v.t0 + len(rng);
      v.part0 = static_cast<std::int32_t>(2 * i);
      v.part1 = static_cast<std::int32_t>(2 * i + 1);
      if (coin(rng) == 0) v = {-kInfinity, v.t1, kNoSurface, v.part1};
      if (coin(rng) == 0) v = {v.t0, kInfinity, v.part0, kNoSurface};
      if (trial % 97 == 0 && coin(rng) == 0) (coin(rng) < 5 ? v.t0 : v.t1) = nan;
      present |= std::uint64_t{1} << i;
    }
    std::vector<LeafEnd> ends;
    for (std::size_t i = 0; i < t.leaves; ++i) {
      if (!((present >> i) & 1)) continue;
      const auto leaf = static_cast<std::uint16_t>(i);
      ends.push_back({iv[i].t0, nullptr, iv[i].part0, leaf, false});
      ends.push_back({iv[i].t1, nullptr, iv[i].part1, leaf, true});
    }
    for (std::size_t a = 0; a < ends.size(); ++a)
      for (std::size_t b = a + 1; b < ends.size(); ++b)
        ties += ends[a].t == ends[b].t && ends[a].leaf != ends[b].leaf;
    for (int w = 0; w < 5; ++w) {
      double tmin = grid(rng), tmax = grid(rng);
      if (tmin > tmax && w != 4) std::swap(tmin, tmax);  // w = 4: sometimes an empty window
      if (w == 3) tmax = kInfinity;
      if (w == 2) tmin = -kInfinity;
      std::vector<LeafEnd> sorted = ends;  // first_crossing sorts its argument
      LocalHit want, got;
      const bool expect = first_crossing(f, sorted, tmin, tmax, want);
      const bool walked = interval_crossing(f, iv, present, tmin, tmax, got);
      ++compared;
      ASSERT_EQ(walked, expect) << "trial " << trial << " window " << tmin << " " << tmax;
      if (!expect) continue;
      ++hits;
      EXPECT_EQ(got.t, want.t) << "trial " << trial;
      EXPECT_EQ(got.part, want.part) << "trial " << trial;
      EXPECT_EQ(got.prim, want.prim) << "trial " << trial;
      EXPECT_EQ(got.leaf, want.leaf) << "trial " << trial;
      EXPECT_EQ(got.flip, want.flip) << "trial " << trial;
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(hits, compared / 5);
  EXPECT_GT(ties, 10000);  // crossings of several leaves at one t are exercised
}

// Two leaves (the unrolled walk), every operation and flip, on a fine grid of ends.
TEST(IntervalCrossing, TwoLeaves_SameAsFirstCrossing) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> grid(-4, 4), len(0, 2), op(0, 2), coin(0, 7);
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    CsgFormula f;
    const std::int32_t operands[] = {csg_leaf_code(0), csg_leaf_code(1)};
    f.add(static_cast<CsgOp>(op(rng)), operands);
    f.finish(2, std::vector<char>{static_cast<char>(coin(rng) == 0), 0});
    LeafInterval iv[2];
    for (std::int32_t i = 0; i < 2; ++i) {
      iv[i] = {static_cast<double>(grid(rng)), 0, 2 * i, 2 * i + 1};
      iv[i].t1 = iv[i].t0 + len(rng);
      if (coin(rng) == 0) iv[i] = {-kInfinity, iv[i].t1, kNoSurface, iv[i].part1};
      if (coin(rng) == 0) iv[i] = {iv[i].t0, kInfinity, iv[i].part0, kNoSurface};
    }
    if (trial % 50 == 0) iv[trial % 100 == 0 ? 0 : 1].t1 = std::numeric_limits<double>::quiet_NaN();
    LeafEnd ends[4];
    for (std::uint16_t i = 0; i < 2; ++i) {
      ends[2 * i] = {iv[i].t0, nullptr, iv[i].part0, i, false};
      ends[2 * i + 1] = {iv[i].t1, nullptr, iv[i].part1, i, true};
    }
    double tmin = grid(rng), tmax = grid(rng);
    if (tmin > tmax) std::swap(tmin, tmax);
    if (coin(rng) == 0) tmax = kInfinity;
    LocalHit want, got;
    const bool expect = first_crossing(f, ends, tmin, tmax, want);
    ASSERT_EQ(interval_crossing(f, iv, 3, tmin, tmax, got), expect) << "trial " << trial;
    if (!expect) continue;
    ++hits;
    EXPECT_EQ(got.t, want.t) << "trial " << trial;
    EXPECT_EQ(got.part, want.part) << "trial " << trial;
    EXPECT_EQ(got.leaf, want.leaf) << "trial " << trial;
    EXPECT_EQ(got.flip, want.flip) << "trial " << trial;
    if (HasFailure()) return;
  }
  EXPECT_GT(hits, 5000);
}

// A random tree of the leaves the interval walk takes, on a grid of quarters so that box faces,
// cylinder caps and planes coincide and spheres share centres and radii.
std::string convex_object(std::mt19937& rng, int depth, const std::string& indent) {
  std::uniform_int_distribution<int> kind(0, 4), op(0, 2), arity(2, 3), coin(0, 3), q(-3, 3);
  auto num = [](double x) { return std::to_string(x); };
  auto quarter = [&] { return num(0.25 * q(rng)); };
  if (depth == 0 || coin(rng) == 0) {
    std::string s = indent + "- ";
    switch (kind(rng)) {
      case 0:
        s += "sphere: {center: [" + quarter() + ", " + quarter() +
             ", 0], radius: " + num(0.25 * (2 + coin(rng))) + "}";
        break;
      case 1: {
        const int x0 = q(rng), y0 = q(rng);
        s += "box: {min: [" + num(0.25 * x0) + ", " + num(0.25 * y0) + ", -0.5], max: [" +
             num(0.25 * (x0 + 1 + coin(rng))) + ", " + num(0.25 * (y0 + 1 + coin(rng))) + ", " +
             num(0.25 * (1 + coin(rng))) + "]}";
        break;
      }
      case 2:
        if (coin(rng) < 2)  // along an axis: caps on the grid
          s += "cylinder: {from: [" + quarter() + ", -0.75, 0], to: [" + quarter() +
               ", 0.5, 0], radius: " + num(0.25 * (1 + coin(rng))) + "}";
        else
          s += "cylinder: {from: [0, -0.5, " + quarter() + "], to: [0.5, 0.75, 0], radius: 0.3}";
        break;
      case 3:
        s += "cone: {from: [0, -0.5, " + quarter() +
             "], to: [0, 0.75, 0], radius_from: " + num(0.25 * (2 + coin(rng))) +
             (coin(rng) == 0 ? ", radius_to: 0.25" : "") + "}";
        break;
      default:
        s += coin(rng) < 2 ? "plane: {normal: [0, 1, 0], point: [0, " + quarter() + ", 0]}"
                           : "plane: {normal: [1, 1, -1], point: [0, " + quarter() + ", 0]}";
        break;
    }
    s += "\n";
    if (coin(rng) == 0)
      s += indent + "  transform: [{rotate: {axis: [1, 2, 3], degrees: 30}}, {translate: [" +
           quarter() + ", 0, 0]}]\n";
    return s;
  }
  static const char* const kOps[] = {"union", "intersection", "difference"};
  std::string s = indent + "- " + kOps[op(rng)] + ":\n";
  const int n = arity(rng);
  for (int i = 0; i < n; ++i) s += convex_object(rng, depth - 1, indent + "    ");
  return s;
}

void expect_same(const CsgShape& csg, const Ray& ray, int i, int& hits) {
  LocalHit want, got;
  const bool expect = intersect_by_gather(csg, ray, want);
  ASSERT_EQ(intersect(csg, ray, got), expect) << "ray " << i;
  ASSERT_EQ(occluded(csg, ray), expect) << "ray " << i;
  if (!expect) return;
  ++hits;
  // Bit for bit (the sign of a zero included), and the same record.
  EXPECT_EQ(std::signbit(got.t), std::signbit(want.t)) << "ray " << i;
  EXPECT_EQ(got.t, want.t) << "ray " << i;
  EXPECT_EQ(got.part, want.part) << "ray " << i;
  EXPECT_EQ(got.prim, want.prim) << "ray " << i;
  EXPECT_EQ(got.leaf, want.leaf) << "ray " << i;
  EXPECT_EQ(got.flip, want.flip) << "ray " << i;
  EXPECT_EQ(got.a, want.a) << "ray " << i;
  EXPECT_EQ(got.b, want.b) << "ray " << i;
}

TEST(IntervalCrossing, ConvexLeafTrees_IntersectEqualsTheGather) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> q(-6, 6), axis(0, 2);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int hits = 0, rays = 0, trees = 0;
  for (int scene_index = 0; scene_index < 150; ++scene_index) {
    const std::string yaml = convex_object(rng, 3, "");
    SCOPED_TRACE(yaml);
    const Scene scene = csg_test::scene_of(yaml);
    const auto* csg = std::get_if<CsgShape>(&scene.objects[0].shape);
    if (!csg) continue;  // a bare leaf
    ASSERT_EQ(csg->tree->interval_leaves, csg->tree->leaves.size() <= CsgTree::kIntervalLeaves);
    ++trees;
    for (int i = 0; i < 400; ++i) {
      Ray ray;
      switch (i % 8) {
        case 0:
        case 1: {  // from outside through the tree's region
          const Vec3 target{u(rng) * 0.8, u(rng) * 0.8, u(rng) * 0.8};
          const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
          ray = Ray{o, target - o};
          break;
        }
        case 2: {  // along an axis from a grid point: along faces, through edges and caps
          Vec3 o{0.25 * q(rng), 0.25 * q(rng), 0.25 * q(rng)}, d;
          const int a = axis(rng);
          o[a] = -3;
          d[a] = 1;
          ray = Ray{o, d};
          break;
        }
        case 3: {  // from inside (a point of the region), a segment or a half-line
          const Vec3 o{u(rng) * 0.5, u(rng) * 0.5, u(rng) * 0.5};
          ray = Ray{o, Vec3{u(rng), u(rng), u(rng)}};
          if (i % 16 == 3) ray.tmax = 0.4;
          break;
        }
        case 4: {  // tangent to a sphere leaf of radius 0.5 at the origin, if there is one
          const double y = 0.5;
          ray = Ray{{-3, y, 0.25 * q(rng)}, {1, 0, 0}};
          break;
        }
        case 5: {  // from a surface point of the tree (a shadow ray's start), either way
          const Vec3 target{u(rng) * 0.8, u(rng) * 0.8, u(rng) * 0.8};
          const Vec3 from{3 * u(rng), 3 * u(rng), 3 * u(rng)};
          LocalHit first;
          if (!intersect_by_gather(*csg, Ray{from, target - from}, first)) continue;
          const Vec3 p = from + first.t * (target - from);
          ray = Ray{p, Vec3{u(rng), u(rng), u(rng)}};
          ray.tmin = i % 16 == 5 ? 0.0 : 1e-9;
          if (i % 32 == 5) ray.tmax = 0.7;
          break;
        }
        case 6: {  // windows starting and ending anywhere
          const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
          ray = Ray{o, Vec3{u(rng), u(rng), u(rng)} * 0.1 - o};
          ray.tmin = 0.5 + u(rng) / 2;
          ray.tmax = ray.tmin + (u(rng) + 1) / 4;
          break;
        }
        default: {  // NaN and infinite components
          Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
          Vec3 d = -o;
          const int a = axis(rng);
          switch ((i / 8) % 5) {
            case 0:
              o[a] = nan;
              break;
            case 1:
              d[a] = nan;
              break;
            case 2:
              d[a] = kInfinity;
              break;
            case 3:
              o[a] = -kInfinity;
              break;
            default:
              d = {0, 0, 0};
              break;
          }
          ray = Ray{o, d};
          break;
        }
      }
      ++rays;
      expect_same(*csg, ray, i, hits);
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(trees, 100);
  EXPECT_GT(hits, rays / 6);
}

// The trees of scenes/csg.yaml that the interval walk takes (all but the notched torus) answer
// as the gather does on rays through their boxes and from their surfaces.
TEST(IntervalCrossing, ExampleScene_IntersectEqualsTheGather) {
  const Scene scene = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/scenes/csg.yaml");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<const CsgShape*> trees;
  for (const Object& object : scene.objects) {
    if (const auto* csg = std::get_if<CsgShape>(&object.shape)) trees.push_back(csg);
    if (const auto* instance = std::get_if<InstanceShape>(&object.shape))
      for (const Object& part : instance->proto->objects)
        if (const auto* csg = std::get_if<CsgShape>(&part.shape)) trees.push_back(csg);
  }
  int walked = 0, hits = 0;
  for (const CsgShape* csg : trees) {
    walked += csg->tree->interval_leaves;
    const Aabb box = bounds(*csg);
    for (int i = 0; i < 2000; ++i) {
      const Vec3 target = box.centre() + 0.6 * mul(Vec3{u(rng), u(rng), u(rng)}, box.extent());
      const Vec3 o = box.centre() + 2.0 * mul(Vec3{u(rng), u(rng), u(rng)}, box.extent());
      Ray ray{o, target - o};
      if (i % 2 == 1) {  // from the surface point towards a light-like direction
        LocalHit first;
        if (!intersect_by_gather(*csg, ray, first)) continue;
        ray = Ray{ray.at(first.t), Vec3{u(rng), 1 + u(rng), u(rng)}};
      }
      expect_same(*csg, ray, i, hits);
      if (HasFailure()) return;
    }
  }
  EXPECT_GE(walked, 11);  // 7 objects' trees of which 6 walked, and the 5 instances' nut
  EXPECT_GT(hits, 5000);
}

}  // namespace
}  // namespace raycast
