// POV-Ray's clipped_by and inverse as the reader builds them (CsgTree::leaf_hidden and
// leaf_inverse): a sphere clipped by a plane keeps only its surface below the plane and is open
// there; an inverse leaf is the complement of its solid, so an intersection with an inverse
// sphere is a difference, ray by ray.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "load/pov_loader.h"

namespace raycast {
namespace {

Scene pov(const std::string& text, std::vector<std::string>* warnings = nullptr) {
  return load_pov_scene_text(text, "t.pov", ".", -1, {}, warnings);
}

bool hit_point(const Scene& s, const Ray& ray, Vec3& p, Vec3& n) {
  SceneHit hit;
  if (!s.intersect(ray, hit)) return false;
  const SurfaceInfo si = s.surface(ray, hit, SurfaceNeeds::kGeometry);
  p = si.p;
  n = si.n;
  return true;
}

const char* kClippedSphere = "sphere { 0, 1 clipped_by { plane { y, 0.25 } } }\n";

TEST(ClippedBy, RayThroughTheCut_SeesTheInsideSurface) {
  std::vector<std::string> warnings;
  const Scene s = pov(kClippedSphere, &warnings);
  for (const std::string& w : warnings) EXPECT_EQ(w.find("clipped_by"), std::string::npos) << w;
  ASSERT_EQ(s.objects.size(), 1u);
  Vec3 p, n;
  // Down the y axis from above: the cap above y = 0.25 is gone, the bottom is hit from inside.
  ASSERT_TRUE(hit_point(s, Ray{{0, 5, 0}, {0, -1, 0}}, p, n));
  EXPECT_NEAR(p.y, -1, 1e-12);
  EXPECT_NEAR(n.y, -1, 1e-12);  // the sphere's own outward normal
  // Across above the cut: nothing; below it: the sphere's side.
  EXPECT_FALSE(hit_point(s, Ray{{-5, 0.5, 0}, {1, 0, 0}}, p, n));
  ASSERT_TRUE(hit_point(s, Ray{{-5, 0, 0}, {1, 0, 0}}, p, n));
  EXPECT_NEAR(p.x, -1, 1e-12);
  // The clipping plane itself is never a surface: a ray along it inside the sphere meets only
  // the sphere.
  ASSERT_TRUE(hit_point(s, Ray{{0, 0.25, 0}, {1, 0, 0}}, p, n));
  EXPECT_NEAR(length(p), 1, 1e-12);
}

TEST(ClippedBy, RandomRays_HitOnlyTheKeptHalfOfTheSphere) {
  const Scene s = pov(kClippedSphere);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  std::vector<Crossing> crossings;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    const Vec3 d = normalize(Vec3{u(rng), u(rng), u(rng)} - o);  // towards the sphere's box
    const Ray ray{o, d};
    // The sphere's crossings with y <= 0.25, in order, are the object's.
    const double b = dot(o, d), c = dot(o, o) - 1, disc = b * b - c;
    std::vector<double> want;
    if (disc > 0)
      for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
        if (t >= 0 && (o + t * d).y <= 0.25) want.push_back(t);
    crossings.clear();
    s.intersect_all(ray, crossings);
    ASSERT_EQ(crossings.size(), want.size()) << i;
    for (std::size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(crossings[k].t, want[k], 1e-9);
    Vec3 p, n;
    ASSERT_EQ(hit_point(s, ray, p, n), !want.empty());
    if (!want.empty()) {
      ++hits;
      EXPECT_NEAR(length(p), 1, 1e-9);
      EXPECT_LE(p.y, 0.25 + 1e-9);
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_TRUE(contains(s.objects[0], {0, 0, 0}));
  EXPECT_FALSE(contains(s.objects[0], {0, 0.5, 0}));
}

TEST(ClippedBy, TransformationsAfterItMoveTheClipToo) {
  Vec3 p, n;
  // Written after clipped_by: the plane moves with the sphere, the lower half stays.
  const Scene after = pov("sphere { 0, 1 clipped_by { plane { y, 0 } } translate 2 * y }\n");
  EXPECT_FALSE(hit_point(after, Ray{{-5, 2.5, 0}, {1, 0, 0}}, p, n));
  EXPECT_TRUE(hit_point(after, Ray{{-5, 1.5, 0}, {1, 0, 0}}, p, n));
  // Written before: only the sphere moves, the plane y = 0 cuts nothing of it.
  const Scene before = pov("sphere { 0, 1 translate 2 * y clipped_by { plane { y, 0 } } }\n");
  EXPECT_FALSE(hit_point(before, Ray{{-5, 2.5, 0}, {1, 0, 0}}, p, n));
  EXPECT_FALSE(hit_point(before, Ray{{-5, 1.5, 0}, {1, 0, 0}}, p, n));
}

TEST(ClippedBy, BoundedByAndClippedByShareTheirObjects) {
  Vec3 p, n;
  const Scene s =
      pov("sphere { 0, 1 bounded_by { box { -1, <1, 0.25, 1> } } clipped_by { bounded_by } }\n"
          "sphere { 3 * x, 1 clipped_by { plane { y, 0.25 } } bounded_by { clipped_by } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_FALSE(hit_point(s, Ray{{-5, 0.5, 0}, {1, 0, 0}}, p, n));
  ASSERT_TRUE(hit_point(s, Ray{{0, 5, 0}, {0, -1, 0}}, p, n));
  EXPECT_NEAR(p.y, -1, 1e-12);
  ASSERT_TRUE(hit_point(s, Ray{{3, 5, 0}, {0, -1, 0}}, p, n));
  EXPECT_NEAR(p.y, -1, 1e-12);
}

TEST(ClippedBy, ClippedUnion_ClipsEachChildAndKeepsTheirInnerSurfaces) {
  // Two overlapping spheres: the second one's surface inside the first stays (a union, not a
  // merge), both cut at y = 0.25.
  const Scene s =
      pov("union { sphere { 0, 1 } sphere { 0.5 * x, 1 } clipped_by { plane { y, 0.25 } } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  std::vector<Crossing> crossings;
  s.intersect_all(Ray{{-5, 0, 0}, {1, 0, 0}}, crossings);
  ASSERT_EQ(crossings.size(), 4u);  // x = -1, -0.5, 1, 1.5
  EXPECT_NEAR(crossings[1].t, 4.5, 1e-12);
  Vec3 p, n;
  EXPECT_FALSE(hit_point(s, Ray{{-5, 0.5, 0}, {1, 0, 0}}, p, n));
}

TEST(ClippedBy, OpenSurface_IsDrawnWholeWithAWarning) {
  std::vector<std::string> warnings;
  const Scene s = pov("disc { 0, y, 1 clipped_by { plane { x, 0 } } }\n", &warnings);
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("open surfaces"), std::string::npos) << warnings[0];
  Vec3 p, n;
  EXPECT_TRUE(hit_point(s, Ray{{0.5, 5, 0}, {0, -1, 0}}, p, n));
}

TEST(Inverse, StandaloneSphere_IsItsComplementWithFlippedNormals) {
  std::vector<std::string> warnings;
  const Scene s = pov("sphere { 0, 1 inverse }\n", &warnings);
  for (const std::string& w : warnings) EXPECT_EQ(w.find("inverse"), std::string::npos) << w;
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_FALSE(contains(s.objects[0], {0, 0, 0}));
  EXPECT_TRUE(contains(s.objects[0], {0, 5, 0}));
  Vec3 p, n;
  ASSERT_TRUE(hit_point(s, Ray{{-5, 0, 0}, {1, 0, 0}}, p, n));
  EXPECT_NEAR(p.x, -1, 1e-12);
  EXPECT_NEAR(n.x, 1, 1e-12);  // out of the complement: towards the centre
}

TEST(Inverse, IntersectionWithAnInverseSphere_IsTheDifference) {
  const Scene a = pov("intersection { box { -1, 1 } sphere { 0, 1.3 inverse } }\n");
  const Scene b = pov("difference { box { -1, 1 } sphere { 0, 1.3 } }\n");
  const Scene c = pov("difference { box { -1, 1 } sphere { 0, 1.3 } inverse } \n");
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    const Ray ray{o, normalize(1.2 * Vec3{u(rng), u(rng), u(rng)} - o)};
    Vec3 pa, na, pb, nb, pc, nc;
    const bool ha = hit_point(a, ray, pa, na), hb = hit_point(b, ray, pb, nb);
    ASSERT_EQ(ha, hb) << i;
    // The inverse difference has the same surface, its normals turned the other way.
    ASSERT_EQ(hit_point(c, ray, pc, nc), hb) << i;
    if (!ha) continue;
    ++hits;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(pa[k], pb[k], 1e-12);
      EXPECT_NEAR(na[k], nb[k], 1e-12);
      EXPECT_NEAR(pc[k], pb[k], 1e-12);
      EXPECT_NEAR(nc[k], -nb[k], 1e-12);
    }
    EXPECT_EQ(contains(a.objects[0], o), contains(b.objects[0], o));
    EXPECT_NE(contains(c.objects[0], o), contains(b.objects[0], o));
  }
  EXPECT_GT(hits, 1000);
}

TEST(Inverse, InverseUnionInsideADifference_KeepsWhatItCovers) {
  // difference { A, inverse(union of B, C) } = A within B or C.
  const Scene s =
      pov("#declare U = union { sphere { -x, 0.8 } sphere { x, 0.8 } }\n"
          "difference { box { <-2, -0.5, -0.5>, <2, 0.5, 0.5> } object { U inverse } }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_TRUE(contains(s.objects[0], {1, 0, 0}));
  EXPECT_TRUE(contains(s.objects[0], {-1, 0, 0}));
  EXPECT_FALSE(contains(s.objects[0], {0, 0, 0}));    // between the spheres
  EXPECT_FALSE(contains(s.objects[0], {1, 0.7, 0}));  // in a sphere, outside the box
}

}  // namespace
}  // namespace raycast
