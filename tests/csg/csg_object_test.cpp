// CSG objects over spheres and planes (boxes as six planes, bars as four): spans, hits and normals
// against inside(p) oracles along random rays, hand-computed cases, rays from inside, coincident
// faces. New closed shapes join by adding a case to kCases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "csg_oracle.h"

namespace raycast {
namespace {

using csg_test::check_random_rays;
using csg_test::Oracle;
using csg_test::scene_of;

// The cube [-h, h]^3 written as the intersection of six planes (box is not on this branch).
std::string cube_yaml(double h, const std::string& indent) {
  std::string s = indent + "- intersection:\n";
  const char* normals[] = {"[1, 0, 0]",  "[-1, 0, 0]", "[0, 1, 0]",
                           "[0, -1, 0]", "[0, 0, 1]",  "[0, 0, -1]"};
  const double signs[] = {1, -1};
  for (int i = 0; i < 6; ++i) {
    Vec3 p;
    p[i / 2] = signs[i % 2] * h;
    s += indent + "    - plane: {normal: " + normals[i] + ", point: [" + std::to_string(p.x) +
         ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + "]}\n";
  }
  return s;
}

bool in_cube(const Vec3& p, double h) {
  return std::abs(p.x) <= h && std::abs(p.y) <= h && std::abs(p.z) <= h;
}
bool in_ball(const Vec3& p, const Vec3& c, double r) { return length_squared(p - c) <= r * r; }

// A square bar along `axis` (0, 1, 2), turned 45 degrees about it: |a + b| <= w and |a - b| <= w
// for the two other coordinates. Stands in for a cylinder until cylinders reach this branch.
std::string bar_yaml(int axis, double w, const std::string& indent) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  std::string s = indent + "- intersection:\n";
  for (int sa : {1, -1})
    for (int sb : {1, -1}) {
      Vec3 n;
      n[a] = sa;
      n[b] = sb;
      const Vec3 p = (w / 2) * n;
      s += indent + "    - plane: {normal: [" + std::to_string(n.x) + ", " + std::to_string(n.y) +
           ", " + std::to_string(n.z) + "], point: [" + std::to_string(p.x) + ", " +
           std::to_string(p.y) + ", " + std::to_string(p.z) + "]}\n";
    }
  return s;
}
bool in_bar(const Vec3& p, int axis, double w) {
  const double x = p[(axis + 1) % 3], y = p[(axis + 2) % 3];
  return std::abs(x + y) <= w && std::abs(x - y) <= w;
}

struct Case {
  const char* name;
  std::string yaml;  // one entry of `objects`
  Oracle inside;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"CubeMinusSphere",
               "- difference:\n" + cube_yaml(1, "    ") + "    - sphere: {radius: 1.3}\n",
               [](const Vec3& p) { return in_cube(p, 1) && !in_ball(p, {}, 1.3); }});
  c.push_back({"UnionOfSpheres",
               "- union:\n    - sphere: {center: [-0.5, 0, 0], radius: 1}\n    - sphere: {center: "
               "[0.6, 0.2, 0], radius: 0.8}\n",
               [](const Vec3& p) {
                 return in_ball(p, {-0.5, 0, 0}, 1) || in_ball(p, {0.6, 0.2, 0}, 0.8);
               }});
  c.push_back({"IntersectionOfSpheres",
               "- intersection:\n    - sphere: {center: [-0.5, 0, 0], radius: 1}\n    - sphere: "
               "{center: [0.4, 0, 0.1], radius: 0.9}\n",
               [](const Vec3& p) {
                 return in_ball(p, {-0.5, 0, 0}, 1) && in_ball(p, {0.4, 0, 0.1}, 0.9);
               }});
  c.push_back({"SphereMinusTwoSpheres",
               "- difference:\n    - sphere: {radius: 1.2}\n    - sphere: {center: [0.8, 0, 0], "
               "radius: 0.7}\n"
               "    - sphere: {center: [-0.3, 0.5, 0.2], radius: 0.5}\n",
               [](const Vec3& p) {
                 return in_ball(p, {}, 1.2) && !in_ball(p, {0.8, 0, 0}, 0.7) &&
                        !in_ball(p, {-0.3, 0.5, 0.2}, 0.5);
               }});
  c.push_back({"HemisphereByPlane",
               "- intersection:\n    - sphere: {radius: 1}\n    - plane: {normal: [0.2, 1, 0.1], "
               "point: [0, 0.3, 0]}\n",
               [](const Vec3& p) {
                 return in_ball(p, {}, 1) && dot(Vec3{0.2, 1, 0.1}, p - Vec3{0, 0.3, 0}) <= 0;
               }});
  c.push_back({"PlaneMinusSphere_Unbounded",
               "- difference:\n    - plane: {normal: [0, 0, 1], point: [0, 0, 0.5]}\n    - sphere: "
               "{radius: 1}\n",
               [](const Vec3& p) { return p.z <= 0.5 && !in_ball(p, {}, 1); }});
  c.push_back(
      {"ThreeOrthogonalBarsIntersected",
       "- intersection:\n" + bar_yaml(0, 1, "    ") + bar_yaml(1, 1, "    ") +
           bar_yaml(2, 1, "    "),
       [](const Vec3& p) { return in_bar(p, 0, 1) && in_bar(p, 1, 1) && in_bar(p, 2, 1); }});
  // difference(union(a, b), intersection(c, d)) under a rotation and a non-uniform scale.
  {
    const Transform xf = Transform::translate({0.3, -0.2, 0.1}) * Transform::rotate({1, 2, 3}, 40) *
                         Transform::scale({1.5, 0.7, 1.1});
    c.push_back(
        {"NestedUnderNonUniformTransform",
         "- difference:\n"
         "    - union:\n"
         "        - sphere: {center: [-0.4, 0, 0], radius: 0.8}\n"
         "        - sphere: {center: [0.5, 0, 0], radius: 0.7}\n"
         "    - intersection:\n"
         "        - sphere: {center: [0, 0.5, 0], radius: 0.6}\n"
         "        - plane: {normal: [0, 0, -1], point: [0, 0, -0.1]}\n"
         "  transform: [{scale: [1.5, 0.7, 1.1]}, {rotate: {axis: [1, 2, 3], degrees: 40}}, "
         "{translate: [0.3, -0.2, 0.1]}]\n",
         [xf](const Vec3& w) {
           const Vec3 p = xf.inverse_point(w);
           const bool u = in_ball(p, {-0.4, 0, 0}, 0.8) || in_ball(p, {0.5, 0, 0}, 0.7);
           const bool i = in_ball(p, {0, 0.5, 0}, 0.6) && p.z >= -0.1;
           return u && !i;
         }});
  }
  // Inner nodes carry their own transforms, composed down to the leaves.
  c.push_back({"InnerTransformsCompose",
               "- difference:\n"
               "    - sphere: {radius: 1}\n"
               "    - union:\n"
               "        - sphere: {radius: 0.5}\n"
               "          transform: [{scale: [1, 2, 1]}]\n"
               "      transform: [{translate: [0.8, 0, 0]}]\n"
               "  transform: [{scale: 2}]\n",
               [](const Vec3& w) {
                 const Vec3 p = w / 2.0;
                 const Vec3 q = p - Vec3{0.8, 0, 0};
                 return in_ball(p, {}, 1) && !in_ball({q.x, q.y / 2, q.z}, {}, 0.5);
               }});
  return c;
}

TEST(CsgObject, RandomRays_SpansHitsAndNormalsAgreeWithOracle) {
  unsigned seed = 1234;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const Scene scene = scene_of(c.yaml);
    ASSERT_EQ(scene.objects.size(), 1u);
    check_random_rays(scene.objects[0], c.inside, seed++, 300, 1.6);
    if (HasFailure()) return;
  }
}

TEST(CsgObject, CubeMinusSphere_HandComputedHits) {
  const Scene scene =
      scene_of("- difference:\n" + cube_yaml(1, "    ") + "    - sphere: {radius: 1.3}\n");
  SceneHit hit;
  // Through the corner region: the cube's face, then the sphere's cavity.
  ASSERT_TRUE(scene.intersect(Ray{{0.9, 0.9, -5}, {0, 0, 1}}, hit));
  EXPECT_EQ(hit.local.t, 4);
  SurfaceInfo si = scene.surface(Ray{{0.9, 0.9, -5}, {0, 0, 1}}, hit);
  EXPECT_EQ(si.n.z, -1);
  // From inside the solid at z = -0.5: the cavity wall, normal pointing into the cavity.
  const Ray inside{{0.9, 0.9, -0.5}, {0, 0, 1}};
  ASSERT_TRUE(scene.intersect(inside, hit));
  const double z = -std::sqrt(1.69 - 1.62);
  EXPECT_NEAR(hit.local.t, z + 0.5, 1e-15);
  si = scene.surface(inside, hit);
  const Vec3 expected = -Vec3{0.9, 0.9, z} / 1.3;
  EXPECT_NEAR(si.n.x, expected.x, 1e-12);
  EXPECT_NEAR(si.n.y, expected.y, 1e-12);
  EXPECT_NEAR(si.n.z, expected.z, 1e-12);
  // The centre line goes through the hole: nothing.
  EXPECT_FALSE(scene.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, hit));
  EXPECT_FALSE(scene.occluded(Ray{{0, 0, -5}, {0, 0, 1}}));
  // Every crossing of the final solid along the corner ray.
  std::vector<Crossing> all;
  scene.intersect_all(Ray{{0.9, 0.9, -5}, {0, 0, 1}}, all);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0].t, 4);
  EXPECT_NEAR(all[1].t, 5 + z, 1e-15);
  EXPECT_NEAR(all[2].t, 5 - z, 1e-15);
  EXPECT_EQ(all[3].t, 6);
}

TEST(CsgObject, HitAtTmaxCounts_HitBeyondDoesNot) {
  const Scene scene =
      scene_of("- difference:\n    - sphere: {radius: 2}\n    - sphere: {radius: 1}\n");
  SceneHit hit;
  EXPECT_TRUE(scene.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 0, 3}, hit));
  EXPECT_EQ(hit.local.t, 3);
  EXPECT_FALSE(scene.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 0, std::nextafter(3.0, 0.0)}, hit));
  // tmin past the outer wall: the cavity wall at t = 4, flipped.
  const Ray r{{0, 0, -5}, {0, 0, 1}, 3.5, kInfinity};
  ASSERT_TRUE(scene.intersect(r, hit));
  EXPECT_EQ(hit.local.t, 4);
  EXPECT_TRUE(hit.local.flip);
  EXPECT_EQ(scene.surface(r, hit).n.z, 1);
}

TEST(CsgObject, CoincidentFaces_AreDeterministic) {
  // A cube minus an equal cube is empty for every ray.
  const Scene empty = scene_of("- difference:\n" + cube_yaml(1, "    ") + cube_yaml(1, "    "));
  testing::Rng rng(7);
  SceneHit hit;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d = rng.direction();
    const Vec3 o = rng.in_box(1.5) - 3.0 * normalize(d);
    EXPECT_FALSE(empty.intersect(Ray{o, d}, hit)) << "ray " << i;
  }
  // Axis-aligned rays exactly along the shared faces too.
  EXPECT_FALSE(empty.intersect(Ray{{1, 0.3, -5}, {0, 0, 1}}, hit));
  EXPECT_FALSE(empty.intersect(Ray{{1, 1, -5}, {0, 0, 1}}, hit));
  // A square hole through a cube sharing the top and bottom faces: open through, solid beside.
  const Scene hole = scene_of("- difference:\n" + cube_yaml(1, "    ") + "    - intersection:\n" +
                              "        - plane: {normal: [1, 0, 0], point: [0.5, 0, 0]}\n"
                              "        - plane: {normal: [-1, 0, 0], point: [-0.5, 0, 0]}\n"
                              "        - plane: {normal: [0, 1, 0], point: [0, 0.5, 0]}\n"
                              "        - plane: {normal: [0, -1, 0], point: [0, -0.5, 0]}\n"
                              "        - plane: {normal: [0, 0, 1], point: [0, 0, 1]}\n"
                              "        - plane: {normal: [0, 0, -1], point: [0, 0, -1]}\n");
  for (double x = -0.45; x < 0.5; x += 0.1)
    EXPECT_FALSE(hole.intersect(Ray{{x, 0.1, -5}, {0, 0, 1}}, hit));
  ASSERT_TRUE(hole.intersect(Ray{{0.75, 0.1, -5}, {0, 0, 1}}, hit));
  EXPECT_EQ(hit.local.t, 4);
  // Touching spheres: their union is one span along the line of centres; the intersection none.
  const char* a = "    - sphere: {center: [-1, 0, 0], radius: 1}\n";
  const char* b = "    - sphere: {center: [1, 0, 0], radius: 1}\n";
  const Ray axis{{-5, 0, 0}, {1, 0, 0}};
  std::vector<Crossing> all;
  scene_of(std::string("- union:\n") + a + b).intersect_all(axis, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].t, 3);
  EXPECT_EQ(all[1].t, 7);
  scene_of(std::string("- intersection:\n") + a + b).intersect_all(axis, all);
  EXPECT_TRUE(all.empty());
}

TEST(CsgObject, RaysFromInside_SeeTheFirstBoundary) {
  const Scene scene = scene_of(
      "- union:\n    - sphere: {radius: 1}\n    - sphere: {center: [1.5, 0, 0], radius: 1}\n");
  SceneHit hit;
  // Starting inside the first sphere, the shared interior hides the second sphere's near wall.
  const Ray r{{0, 0, 0}, {1, 0, 0}};
  ASSERT_TRUE(scene.intersect(r, hit));
  EXPECT_EQ(hit.local.t, 2.5);
  EXPECT_EQ(scene.surface(r, hit).n.x, 1);
  // Inside a half-space clipped sphere, looking at the cut.
  const Scene cut = scene_of(
      "- intersection:\n    - sphere: {radius: 1}\n    - plane: {normal: [0, 1, 0], point: [0, "
      "0.5, 0]}\n");
  const Ray up{{0, 0, 0}, {0, 1, 0}};
  ASSERT_TRUE(cut.intersect(up, hit));
  EXPECT_EQ(hit.local.t, 0.5);
  EXPECT_EQ(cut.surface(up, hit).n.y, 1);
}

// Random trees of spheres and planes; the oracle is the boolean of the leaves' own contains().
std::string random_tree(testing::Rng& rng, int depth, const std::string& indent) {
  std::uniform_int_distribution<int> op(0, 2), kind(0, 5), arity(2, 3);
  std::uniform_real_distribution<double> u(-1, 1), r(0.3, 0.9);
  if (depth == 0 || kind(rng) == 0) {
    if (kind(rng) == 0)
      return indent + "- plane: {normal: [" + std::to_string(u(rng)) + ", " +
             std::to_string(u(rng)) + ", 0.5], point: [" + std::to_string(0.3 * u(rng)) +
             ", 0, 0]}\n";
    return indent + "- sphere: {center: [" + std::to_string(u(rng)) + ", " +
           std::to_string(u(rng)) + ", " + std::to_string(u(rng)) +
           "], radius: " + std::to_string(r(rng)) + "}\n";
  }
  const char* ops[] = {"union", "intersection", "difference"};
  std::string s = indent + "- " + ops[op(rng)] + ":\n";
  const int n = arity(rng);
  for (int i = 0; i < n; ++i) s += random_tree(rng, depth - 1, indent + "    ");
  return s;
}

TEST(CsgObject, RandomTrees_AgreeWithPointClassification) {
  const unsigned seed = 99;
  testing::Rng rng(seed);
  for (int tree = 0; tree < 40; ++tree) {
    const std::string yaml = "- union:\n" + random_tree(rng, 4, "    ");
    SCOPED_TRACE(::testing::Message() << "tree " << tree << ":\n" << yaml);
    const Scene scene = scene_of(yaml);
    const Object& obj = scene.objects[0];
    const Oracle inside = [&](const Vec3& p) { return contains(obj, p); };
    testing::Rng ray_rng(seed + tree);
    for (int i = 0; i < 40; ++i) {
      SCOPED_TRACE(::testing::Message() << "ray " << i);
      const Vec3 d = ray_rng.direction();
      const Vec3 o = ray_rng.in_box(1.5) - (i % 2 ? 0.0 : 4.0) * d;
      csg_test::check_ray(obj, inside, Ray{o, d}, 8, 300);
      if (HasFailure()) return;
    }
  }
}

TEST(CsgObject, DeepNesting_EvaluatesWithinTheLimit) {
  // 100 nested differences of shrinking spheres: B100 - (B99 - (B98 - ... (B1 - B0.5))) is the
  // ball of radius 0.5 and the shells 1..2, 3..4, ..., 99..100.
  std::string yaml;
  std::string indent;
  for (int i = 0; i < 100; ++i) {
    yaml += indent + "- difference:\n" + indent +
            "    - sphere: {radius: " + std::to_string(100 - i) + "}\n";
    indent += "    ";
  }
  yaml += indent + "- sphere: {radius: 0.5}\n";
  const Scene scene = scene_of(yaml);
  std::vector<Crossing> all;
  scene.intersect_all(Ray{{0, 0, -200}, {0, 0, 1}}, all);
  // 50 shells crossed twice on each side, and the core ball.
  ASSERT_EQ(all.size(), 202u);
  EXPECT_EQ(all[0].t, 100);
  EXPECT_EQ(all[100].t, 199.5);
  SceneHit hit;
  ASSERT_TRUE(scene.intersect(Ray{{0, 0, 0}, {0, 0, 1}}, hit));
  EXPECT_EQ(hit.local.t, 0.5);
  ASSERT_TRUE(scene.intersect(Ray{{0, 0, 0.75}, {0, 0, 1}}, hit));
  EXPECT_EQ(hit.local.t, 0.25);
  EXPECT_EQ(scene.surface(Ray{{0, 0, 0.75}, {0, 0, 1}}, hit).n.z, -1);
}

TEST(CsgObject, ConcurrentQueries_MatchSequentialAnswers) {
  // Per-thread scratch lists: many threads querying one scene give the sequential answers.
  const Scene scene =
      scene_of("- difference:\n" + cube_yaml(1, "    ") + "    - sphere: {radius: 1.3}\n" +
               "- union:\n    - sphere: {center: [3, 0, 0], radius: 1}\n"
               "    - intersection:\n        - sphere: {center: [3.5, 0, 0], radius: 1}\n"
               "        - plane: {normal: [0, 1, 0], point: [0, 0.2, 0]}\n");
  testing::Rng rng(11);
  std::vector<Ray> rays;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 d = rng.direction();
    rays.push_back({rng.in_box(2) + Vec3{1.5, 0, 0} - 4.0 * d, d});
  }
  std::vector<double> sequential(rays.size()), parallel(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    SceneHit h;
    sequential[i] = scene.intersect(rays[i], h) ? h.local.t : -1;
  }
  tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
    SceneHit h;
    parallel[i] = scene.intersect(rays[i], h) ? h.local.t : -1;
  });
  EXPECT_EQ(sequential, parallel);
  EXPECT_GT(std::count_if(sequential.begin(), sequential.end(), [](double t) { return t >= 0; }),
            2000);
}

}  // namespace
}  // namespace raycast
