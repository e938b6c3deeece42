// ObjectSet's walks against a brute-force loop over every object, on each of its paths: the flat
// list of boxes one at a time (fewer than kBoxPairsFrom bounded objects), two at a time (up to
// kFlatLimit), and the BVH (more); random rays, rays parallel to the box slabs, and rays
// with NaN or infinite directions.
#include "objects/object_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <vector>

#include "load/loader.h"
#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "support/random.h"

namespace raycast {
namespace {

// Object i is a box, a sphere or a translated sphere by (i + kind) % 3.
std::vector<Object> random_objects(std::size_t bounded, testing::Rng& rng, bool with_plane,
                                   std::size_t kind) {
  std::vector<Object> objects;
  Object plane;  // unbounded: tried on every ray
  plane.shape = make_plane({0, 1, 0}, {0, -5, 0});
  if (with_plane) objects.push_back(std::move(plane));
  for (std::size_t i = 0; i < bounded; ++i) {
    const Vec3 c = rng.in_box(4);
    Object o;
    if ((i + kind) % 3 == 0) {
      o.shape = make_box(c - Vec3{0.5, 0.3, 0.4}, c + Vec3{0.5, 0.3, 0.4});
    } else {
      o.shape = make_sphere({0, 0, 0}, rng.uniform(0.2, 1.2));
      if ((i + kind) % 3 == 2)
        o.xf = Transform::translate(c);  // also through a transform
      else
        o.shape = make_sphere(c, rng.uniform(0.2, 1.2));
    }
    objects.push_back(std::move(o));
  }
  return objects;
}

void check_against_brute_force(std::size_t bounded, bool flat, bool with_plane = true,
                               std::size_t kind = 0) {
  testing::Rng rng(1234 + bounded + kind);
  const std::vector<Object> objects = random_objects(bounded, rng, with_plane, kind);
  ObjectSet set;
  set.build(objects);
  ASSERT_EQ(bounded <= ObjectSet::kFlatLimit, flat) << "the case must exercise its path";
  int hits = 0, blocked = 0;
  for (int n = 0; n < 2000; ++n) {
    Ray ray = testing::random_ray(rng, 8, 5);
    if (n % 2 == 1) ray.tmax = rng.uniform(0.05, 1.2);  // a segment (|d| is in [0.1, 10])
    if (!with_plane && n % 4 == 0)  // few objects: half the full rays aimed at the first one
      ray.d = raycast::bounds(objects[0]).centre() - ray.o;
    if (n % 10 == 3) ray.d[n % 3] = 0;           // parallel to a pair of slabs
    if (n % 10 == 5) ray.d[(n + 2) % 3] = -0.0;  // the same, in the other octant
    if (n % 10 == 7) {                           // along two axes, origin on a box face
      ray.d[n % 3] = ray.d[(n + 1) % 3] = 0;
      if (objects.size() > 1) ray.o[n % 3] = raycast::bounds(objects[1]).lo[n % 3];
    }
    if (n % 50 == 9) ray.d.y = std::numeric_limits<double>::quiet_NaN();
    if (n % 50 == 19) ray.d.x = kInfinity;
    // Nearest: the smallest t over every object's own nearest hit.
    double best = kInfinity;
    std::set<std::uint32_t> crossed;
    for (std::size_t i = 0; i < objects.size(); ++i) {
      LocalHit h;
      if (intersect(objects[i], ray, h)) {
        best = std::min(best, h.t);
        crossed.insert(std::uint32_t(i));
      }
    }
    LocalHit hit;
    std::int32_t index = -1;
    const bool found = set.intersect(objects, ray, hit, index);
    ASSERT_EQ(found, best < kInfinity) << n;
    if (found) {
      ++hits;
      EXPECT_EQ(hit.t, best) << n;
      LocalHit own;
      ASSERT_TRUE(intersect(objects[std::size_t(index)], ray, own));
      EXPECT_EQ(own.t, best) << n;
    }
    // Any: blocked exactly when some object crosses the segment.
    const bool occluded = set.occluded(objects, ray);
    EXPECT_EQ(occluded, !crossed.empty()) << n;
    blocked += occluded;
    // All: every crossed object visited, none twice.
    std::multiset<std::uint32_t> visited;
    set.all(ray, [&](std::uint32_t i) { visited.insert(i); });
    for (std::uint32_t i : crossed) EXPECT_EQ(visited.count(i), 1u) << n << " object " << i;
    for (std::uint32_t i : visited) EXPECT_EQ(visited.count(i), 1u) << n << " object " << i;
  }
  // The rays do meet objects (and miss them): the comparisons above are not vacuous.
  EXPECT_GT(hits, 100);
  EXPECT_LT(hits, 2000);
  EXPECT_GT(blocked, 100);
}

TEST(ObjectSet, FlatWalk_MatchesBruteForce) {
  for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(3)})
    check_against_brute_force(n, true);
}

// A set of one bounded object and nothing else takes the sole-object short cut (box, then the
// object): each kind alone (box, sphere, translated sphere).
TEST(ObjectSet, SoleObject_MatchesBruteForce) {
  for (std::size_t kind = 0; kind < 3; ++kind) check_against_brute_force(1, true, false, kind);
}

// A sole CSG object of whole spheres and boxes skips the box test (the tree culls itself); one
// with another leaf keeps it: both answer as the object asked directly.
TEST(ObjectSet, SoleCsgObject_MatchesTheObject) {
  const char* texts[] = {
      "objects:\n  - difference:\n      - sphere: {radius: 0.45}\n"
      "      - box: {min: [-0.2, -1, -0.2], max: [0.2, 1, 0.2]}\n"
      "    transform: [{rotate: {axis: [1, 1, 0], degrees: 40}}, {translate: [0.3, -0.2, 0.1]}]\n",
      "objects:\n  - union:\n      - sphere: {radius: 0.5}\n"
      "      - sphere: {center: [0.6, 0, 0], radius: 0.3}\n",
      "objects:\n  - difference:\n      - torus: {major_radius: 0.9, minor_radius: 0.3}\n"
      "      - box: {min: [-0.5, -0.5, -1.5], max: [0.5, 0.5, -0.5]}\n"};
  for (const char* text : texts) {
    const Scene scene = load_scene_text(text);
    const std::vector<Object> objects = scene.objects;
    ASSERT_EQ(objects.size(), 1u);
    ObjectSet set;
    set.build(objects);
    testing::Rng rng(5);
    int hits = 0;
    for (int n = 0; n < 4000; ++n) {
      Ray ray = testing::random_ray(rng, 2, 1);
      if (n % 2 == 1) ray.tmax = rng.uniform(0.05, 3.0);
      if (n % 4 == 0) ray.d = rng.in_box(0.3) - ray.o;  // aimed near the object
      if (n % 10 == 3) ray.d[n % 3] = 0;
      if (n % 20 == 7) ray.o = rng.in_box(0.3);  // starting inside or near it
      LocalHit want, got;
      const bool expected = intersect(objects[0], ray, want) && want.t <= ray.tmax;
      std::int32_t index = -1;
      ASSERT_EQ(set.intersect(objects, ray, got, index), expected) << text << n;
      if (expected) {
        ++hits;
        EXPECT_EQ(got.t, want.t) << n;
        EXPECT_EQ(index, 0) << n;
      }
      EXPECT_EQ(set.occluded(objects, ray), occluded(objects[0], ray)) << text << n;
    }
    EXPECT_GT(hits, 400) << text;
  }
}

TEST(ObjectSet, PairedBoxWalk_MatchesBruteForce) {
  static_assert(ObjectSet::kBoxPairsFrom > 1 &&
                ObjectSet::kBoxPairsFrom < ObjectSet::kFloatBoxesFrom &&
                ObjectSet::kFloatBoxesFrom <= ObjectSet::kFlatLimit);
  // Both sides of each switch-over: one box at a time, pairs (even and odd counts), float groups.
  for (std::size_t n :
       {ObjectSet::kBoxPairsFrom - 1, ObjectSet::kBoxPairsFrom, std::size_t(5),
        ObjectSet::kFloatBoxesFrom - 1, ObjectSet::kFloatBoxesFrom, ObjectSet::kFlatLimit})
    check_against_brute_force(n, true);
}

TEST(ObjectSet, BvhWalk_MatchesBruteForce) {
  for (std::size_t n : {ObjectSet::kFlatLimit + 1, std::size_t(40)})
    check_against_brute_force(n, false);
}

// A set of one untransformed mesh takes its own short path (box, then the mesh): the same
// answers as the general walk, which a second, far-away object forces on the same mesh.
TEST(ObjectSet, SoleMesh_AnswersAsTheGeneralWalk) {
  const TriangleSoup soup = make_octa_sphere(24, 1.0, {0.2, -0.1, 0.3});
  Object mesh;
  mesh.shape = MeshShape{make_mesh(soup.positions, soup.triangles)};
  Object far;
  far.shape = make_sphere({100, 100, 100}, 0.5);
  const std::vector<Object> sole{mesh}, pair{mesh, far};
  ObjectSet a, b;
  a.build(sole);
  b.build(pair);
  testing::Rng rng(77);
  int hits = 0;
  for (int n = 0; n < 4000; ++n) {
    Ray ray = testing::random_ray(rng, 3, 1.5);
    if (n % 2 == 1) ray.tmax = rng.uniform(0.05, 3.0);
    if (n % 10 == 3) ray.d[n % 3] = 0;
    if (n % 50 == 9) ray.d.y = std::numeric_limits<double>::quiet_NaN();
    LocalHit ha, hb;
    std::int32_t ia = -1, ib = -1;
    const bool fa = a.intersect(sole, ray, ha, ia), fb = b.intersect(pair, ray, hb, ib);
    ASSERT_EQ(fa, fb) << n;
    if (fa) {
      ++hits;
      EXPECT_EQ(ha.t, hb.t) << n;
      EXPECT_EQ(ha.prim, hb.prim) << n;
      EXPECT_EQ(ia, ib) << n;
    }
    EXPECT_EQ(a.occluded(sole, ray), b.occluded(pair, ray)) << n;
  }
  EXPECT_GT(hits, 400);  // the rays do reach the mesh
}

}  // namespace
}  // namespace raycast
