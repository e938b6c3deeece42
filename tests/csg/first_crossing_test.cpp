// The first-crossing walk (csg/first_crossing.h) against the span lists combined node by node
// (csg/span_ops.h): on random trees over random leaf lists with frequent ties, and through
// CsgShape's intersect on random scenes' rays against intersect_by_spans.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "csg/first_crossing.h"
#include "csg_oracle.h"
#include "objects/csg_tree.h"
#include "objects/prototype.h"
#include "random_tree.h"

namespace raycast {
namespace {

using csg_test::grow;
using csg_test::RandomTree;

// Sorted, disjoint spans (touching and zero-length allowed) on a coarse grid so that ends of
// different leaves coincide often; infinite ends sometimes. `prim` numbers every end.
SpanList random_list(std::mt19937& rng, int& tag) {
  std::uniform_int_distribution<int> count(0, 3), step(0, 2), coin(0, 7);
  SpanList l;
  double t = -6;
  const int n = count(rng);
  for (int i = 0; i < n; ++i) {
    LocalHit in, out;
    t += step(rng);
    in.t = t;
    t += step(rng);
    out.t = t;
    in.prim = tag++;
    out.prim = tag++;
    in.part = out.part = 0;
    l.add(in, out);
  }
  if (!l.empty() && coin(rng) == 0) l[0].in = {.t = -kInfinity, .part = kNoSurface};
  if (!l.empty() && coin(rng) == 0) l.back().out = {.t = kInfinity, .part = kNoSurface};
  return l;
}

// The operand's list by combine_spans, node by node, every list regularised.
SpanList combined(const RandomTree& t, std::int32_t code, const std::vector<SpanList>& lists,
                  const std::vector<char>& flipped) {
  const SpanList none;
  SpanList out;
  if (code < 0) {
    const auto leaf = static_cast<std::size_t>(-code - 1);
    SpanList l = lists[leaf];
    for (Span& s : l) {
      s.in.leaf = s.out.leaf = static_cast<std::int32_t>(leaf);
      s.in.flip = s.out.flip = flipped[leaf] != 0;
    }
    combine_spans(CsgOp::kUnion, l, none, out);
    return out;
  }
  const auto k = static_cast<std::size_t>(code);
  SpanList acc = combined(t, t.operands[k][0], lists, flipped);
  combine_spans(CsgOp::kUnion, acc, none, out);
  acc = out;
  for (std::size_t i = 1; i < t.operands[k].size(); ++i) {
    combine_spans(t.ops[k], acc, combined(t, t.operands[k][i], lists, flipped), out);
    acc = out;
  }
  return acc;
}

bool first_of(const SpanList& l, double tmin, double tmax, LocalHit& hit) {
  for (const Span& s : l)
    for (const LocalHit* e : {&s.in, &s.out})
      if (e->part != kNoSurface && e->t >= tmin && e->t <= tmax) {
        hit = *e;
        return true;
      }
  return false;
}

TEST(FirstCrossing, RandomTreesAndLists_SameCrossingAsCombinedLists) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> grid(-7, 12), coin(0, 3);
  int compared = 0, hits = 0, ties = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    RandomTree t;
    grow(rng, t, 3);
    if (t.ops.empty()) continue;  // a bare leaf is no tree
    CsgFormula f;
    for (std::size_t k = 0; k < t.ops.size(); ++k) f.add(t.ops[k], t.operands[k]);
    std::vector<char> flipped(t.leaves);
    for (char& c : flipped) c = coin(rng) == 0;
    f.finish(t.leaves, flipped);
    ASSERT_TRUE(f.is_tree());
    int tag = 0;
    std::vector<SpanList> lists;
    for (std::size_t i = 0; i < t.leaves; ++i) lists.push_back(random_list(rng, tag));
    const SpanList reference = combined(t, 0, lists, flipped);
    for (int w = 0; w < 4; ++w) {
      double tmin = grid(rng), tmax = grid(rng);
      if (tmin > tmax) std::swap(tmin, tmax);
      if (w == 3) tmax = kInfinity;
      std::vector<LeafEnd> ends;
      for (std::size_t i = 0; i < t.leaves; ++i)
        for (const Span& s : lists[i]) {
          ends.push_back({s.in.t, &s.in, s.in.part, static_cast<std::uint16_t>(i), false});
          ends.push_back({s.out.t, &s.out, s.out.part, static_cast<std::uint16_t>(i), true});
        }
      for (std::size_t i = 1; i < ends.size(); ++i) ties += ends[i].t == ends[i - 1].t;
      LocalHit want, got;
      const bool expect = first_of(reference, tmin, tmax, want);
      const bool walked = first_crossing(f, ends, tmin, tmax, got);
      ++compared;
      ASSERT_EQ(walked, expect) << "trial " << trial << " window " << tmin << " " << tmax;
      if (!expect) continue;
      ++hits;
      EXPECT_EQ(got.t, want.t) << "trial " << trial;
      EXPECT_EQ(got.prim, want.prim) << "trial " << trial;
      EXPECT_EQ(got.leaf, want.leaf) << "trial " << trial;
      EXPECT_EQ(got.flip, want.flip) << "trial " << trial;
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(hits, compared / 4);
  EXPECT_GT(ties, 1000);  // the tie rule is exercised, not only single crossings
}

TEST(FirstCrossing, Formula_TableAndTreeAgree) {
  // 13 leaves: no table; the same tree's first 12 leaves in a smaller tree use one.
  CsgFormula big, small;
  std::vector<std::int32_t> ops13, ops12;
  for (std::size_t i = 0; i < 13; ++i) ops13.push_back(csg_leaf_code(i));
  for (std::size_t i = 0; i < 12; ++i) ops12.push_back(csg_leaf_code(i));
  big.add(CsgOp::kDifference, ops13);
  small.add(CsgOp::kDifference, ops12);
  big.finish(13, std::vector<char>(13, 0));
  small.finish(12, std::vector<char>(12, 0));
  for (std::uint64_t m = 0; m < (1u << 12); ++m) {
    const bool want = (m & 1) && (m >> 1) == 0;  // in the first leaf and no other
    ASSERT_EQ(small.inside(m), want) << m;
    ASSERT_EQ(big.inside(m), want) << m;
  }
  EXPECT_TRUE(big.inside(1));
  EXPECT_FALSE(big.inside(1 | (1u << 12)));
  EXPECT_TRUE(big.leaf_flip(12));
  EXPECT_FALSE(big.leaf_flip(0));
}

TEST(FirstCrossing, SharedOperand_IsNotATree) {
  CsgFormula f;
  const std::int32_t ops[] = {csg_leaf_code(0), csg_leaf_code(0)};
  f.add(CsgOp::kUnion, ops);
  f.finish(1, std::vector<char>(1, 0));
  EXPECT_FALSE(f.is_tree());
}

// A random CSG object over every leaf kind the walk computes itself (whole sphere, box, closed
// cylinder and cone) and generic ones (plane, ellipsoid, torus), some turned and moved.
std::string random_object(std::mt19937& rng, int depth, const std::string& indent) {
  std::uniform_int_distribution<int> kind(0, 6), op(0, 2), arity(2, 3), coin(0, 3);
  std::uniform_real_distribution<double> u(-0.6, 0.6), r(0.3, 0.9);
  auto num = [&](double x) { return std::to_string(x); };
  if (depth == 0 || coin(rng) == 0) {
    std::string s = indent + "- ";
    const double c = u(rng);
    switch (kind(rng)) {
      case 0:
        s += "sphere: {center: [" + num(c) + ", " + num(u(rng)) + ", 0], radius: " + num(r(rng)) +
             "}";
        break;
      case 1:
        s += "box: {min: [" + num(c - 0.7) + ", -0.5, -0.6], max: [" + num(c + 0.5) + ", 0.6, " +
             num(r(rng)) + "]}";
        break;
      case 2:
        s += "cylinder: {from: [" + num(c) + ", -0.8, 0], to: [0, 0.8, " + num(u(rng)) +
             "], radius: " + num(r(rng) / 2) + "}";
        break;
      case 3:
        s += "cone: {from: [0, -0.7, " + num(c) +
             "], to: [0, 0.8, 0], radius_from: " + num(r(rng)) + "}";
        break;
      case 4:
        s += "plane: {normal: [" + num(u(rng)) + ", 1, 0.3], point: [0, " + num(c) + ", 0]}";
        break;
      case 5:
        s += "ellipsoid: {center: [0, " + num(c) + ", 0], radii: [0.8, 0.5, " + num(r(rng)) + "]}";
        break;
      default:
        s += "torus: {major_radius: 0.6, minor_radius: " + num(r(rng) / 3) + "}";
        break;
    }
    s += "\n";
    if (coin(rng) == 0)
      s += indent + "  transform: [{rotate: {axis: [1, 2, 3], degrees: " + num(90 * u(rng)) +
           "}}, {translate: [" + num(u(rng) / 3) + ", 0, 0.1]}]\n";
    return s;
  }
  static const char* const kOps[] = {"union", "intersection", "difference"};
  std::string s = indent + "- " + kOps[op(rng)] + ":\n";
  const int n = arity(rng);
  for (int i = 0; i < n; ++i) s += random_object(rng, depth - 1, indent + "    ");
  return s;
}

TEST(FirstCrossing, RandomScenes_IntersectEqualsTheCombinedLists) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0, rays = 0;
  for (int scene_index = 0; scene_index < 60; ++scene_index) {
    const std::string yaml = random_object(rng, 3, "");
    SCOPED_TRACE(yaml);
    const Scene scene = csg_test::scene_of(yaml);
    const auto* csg = std::get_if<CsgShape>(&scene.objects[0].shape);
    if (!csg) continue;  // a bare leaf
    for (int i = 0; i < 300; ++i) {
      const Vec3 target{u(rng) * 0.8, u(rng) * 0.8, u(rng) * 0.8};
      const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
      Ray ray{o, target - o};
      if (i % 3 == 1) ray.tmin = 0.5;               // starting inside or past a boundary
      if (i % 3 == 2) ray.tmax = 0.3 + u(rng) / 4;  // a shadow ray's segment
      if (i % 5 == 4) ray.o = target;               // from inside the tree's box
      LocalHit want, got;
      const bool expect = intersect_by_spans(*csg, ray, want);
      ASSERT_EQ(intersect(*csg, ray, got), expect) << "ray " << i;
      ASSERT_EQ(occluded(*csg, ray), expect) << "ray " << i;
      ++rays;
      if (!expect) continue;
      ++hits;
      EXPECT_EQ(got.t, want.t) << "ray " << i;
      EXPECT_EQ(got.part, want.part) << "ray " << i;
      EXPECT_EQ(got.prim, want.prim) << "ray " << i;
      EXPECT_EQ(got.leaf, want.leaf) << "ray " << i;
      EXPECT_EQ(got.flip, want.flip) << "ray " << i;
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(hits, rays / 5);
}

TEST(FirstCrossing, ExampleScene_IntersectEqualsTheCombinedLists) {
  const Scene scene = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/scenes/csg.yaml");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (const Object& object : scene.objects) {
    const auto* csg = std::get_if<CsgShape>(&object.shape);
    if (!csg) continue;
    const Aabb box = bounds(*csg);
    for (int i = 0; i < 2000; ++i) {
      const Vec3 target = box.centre() + 0.6 * mul(Vec3{u(rng), u(rng), u(rng)}, box.extent());
      const Vec3 o = box.centre() + 2.0 * mul(Vec3{u(rng), u(rng), u(rng)}, box.extent());
      const Ray ray{o, target - o};
      LocalHit want, got;
      const bool expect = intersect_by_spans(*csg, ray, want);
      ASSERT_EQ(intersect(*csg, ray, got), expect) << "ray " << i;
      if (!expect) continue;
      ++hits;
      EXPECT_EQ(got.t, want.t);
      EXPECT_EQ(got.part, want.part);
      EXPECT_EQ(got.leaf, want.leaf);
      EXPECT_EQ(got.flip, want.flip);
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(hits, 1000);
}

// The tree's ball test before the walk (csg_shape.cpp): rays from near and far (up to 1e4 times
// the object's size, where the test's cancellation is largest) aimed at points on the objects'
// surfaces, grazing them in every direction, answer as the combined lists do.
TEST(FirstCrossing, RaysAtSurfacePoints_TheBallTestDropsNoHit) {
  const Scene scene = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/scenes/csg.yaml");
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  std::vector<const CsgShape*> trees;  // the scene's CSG objects and the instances' (the nut)
  for (const Object& object : scene.objects) {
    if (const auto* csg = std::get_if<CsgShape>(&object.shape)) trees.push_back(csg);
    if (const auto* instance = std::get_if<InstanceShape>(&object.shape))
      for (const Object& part : instance->proto->objects)
        if (const auto* csg = std::get_if<CsgShape>(&part.shape)) trees.push_back(csg);
  }
  ASSERT_GE(trees.size(), 12u);
  for (const CsgShape* csg : trees) {
    const Aabb box = bounds(*csg);
    for (int i = 0; i < 3000; ++i) {
      // A point on the surface: the first crossing of a ray through the box.
      const Vec3 target = box.centre() + 0.6 * mul(Vec3{u(rng), u(rng), u(rng)}, box.extent());
      const Vec3 from = box.centre() + 2.0 * mul(Vec3{u(rng), u(rng), u(rng)}, box.extent());
      LocalHit first;
      if (!intersect_by_spans(*csg, Ray{from, target - from}, first)) continue;
      const Vec3 p = from + first.t * (target - from);
      // A ray through it from a random direction and distance (the point itself is on it).
      const double far = std::pow(10.0, 4 * (u(rng) + 1) / 2) * length(box.extent());
      const Vec3 o = p + far * normalize(Vec3{u(rng), u(rng), u(rng)});
      const Ray ray{o, p - o};
      LocalHit want, got;
      const bool expect = intersect_by_spans(*csg, ray, want);
      ASSERT_EQ(intersect(*csg, ray, got), expect) << "ray " << i;
      ASSERT_EQ(occluded(*csg, ray), expect) << "ray " << i;
      hits += expect;
      if (expect) {
        EXPECT_EQ(got.t, want.t);
        EXPECT_EQ(got.leaf, want.leaf);
      }
      if (HasFailure()) return;
    }
  }
  // Most of these rays hit (through a surface point); some graze past (tangent, rounding).
  EXPECT_GT(hits, 10000);
}

// More ends than the walk's buffer (40 spheres and 20 cylinders on one line, 60 leaves): the
// span-list path answers, the same as intersect_by_spans.
TEST(FirstCrossing, ManyEnds_FallBackToTheSpanLists) {
  std::string yaml = "- difference:\n    - union:\n";
  for (int i = 0; i < 40; ++i)
    yaml += "        - sphere: {center: [" + std::to_string(i) + ", 0, 0], radius: 0.4}\n";
  yaml += "    - union:\n";
  for (int i = 0; i < 20; ++i)
    yaml += "        - cylinder: {from: [" + std::to_string(i + 0.5) + ", -1, 0], to: [" +
            std::to_string(i + 0.5) + ", 1, 0], radius: 0.05}\n";
  const Scene scene = csg_test::scene_of(yaml);
  const auto& csg = std::get<CsgShape>(scene.objects[0].shape);
  for (const double tmin : {0.0, 10.0, 20.2, 38.9}) {
    Ray ray{{-1, 0.01, 0}, {1, 0, 0}};
    ray.tmin = tmin;
    LocalHit want, got;
    const bool expect = intersect_by_spans(csg, ray, want);
    ASSERT_TRUE(expect);
    ASSERT_TRUE(intersect(csg, ray, got));
    EXPECT_EQ(got.t, want.t);
    EXPECT_EQ(got.leaf, want.leaf);
  }
}

// docs/csg.md: a ray tangent to a sphere inside CSG reports no hit (a result has no zero-length
// interval). The span-list path passed a lone operand's list through uncombined and reported the
// touching point; the walk does not.
TEST(FirstCrossing, TangentToAnOperand_IsNoHit) {
  const Scene scene = csg_test::scene_of(
      "- union:\n"
      "    - sphere: {radius: 1}\n"
      "    - sphere: {center: [0, -9, 0], radius: 1}\n");
  const auto& csg = std::get<CsgShape>(scene.objects[0].shape);
  const Ray tangent{{-5, 1, 0}, {1, 0, 0}};  // the roots are exactly 5 and 5
  LocalHit hit;
  EXPECT_FALSE(intersect(csg, tangent, hit));
  EXPECT_FALSE(occluded(csg, tangent));
  EXPECT_TRUE(intersect_by_spans(csg, tangent, hit));  // the old answer, for the record
  const Ray through{{-5, 0.5, 0}, {1, 0, 0}};
  ASSERT_TRUE(intersect(csg, through, hit));
  EXPECT_LT(hit.t, 5);
}

}  // namespace
}  // namespace raycast
