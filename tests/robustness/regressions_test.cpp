// The bugs the robustness tests found, each pinned with its exact inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "geometry/plane.h"
#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSub = std::numeric_limits<double>::denorm_min();

// A subnormal direction put the box's hit at t = inf (7 / 5e-324 overflows): |d|^2 underflows,
// so the ray is outside the rays' domain and the scene answers nothing.
TEST(Regression, SubnormalDirection_NoHitAtInfinity) {
  const Scene scene = load_scene_text("objects:\n  - box: {min: [-1, -2, -3], max: [1, 2, 3]}\n");
  const Ray ray{{-7, 0.5, 0.25}, {kSub, kSub, kSub}, 0, kInf};
  EXPECT_FALSE(is_valid(ray));
  SceneHit hit;
  EXPECT_FALSE(scene.intersect(ray, hit));
  EXPECT_FALSE(scene.occluded(ray));
  std::vector<Crossing> all;
  scene.intersect_all(ray, all);
  EXPECT_TRUE(all.empty());
}

// A huge direction from the sphere's centre: |d|^2 overflowed and the hit came back at t = 0
// with a NaN normal.
TEST(Regression, HugeDirection_NoHitWithNaNNormal) {
  const Scene scene = load_scene_text("objects:\n  - sphere: {radius: 1}\n");
  const Ray ray{{0, 0, 0}, {1e300, 1e300, -1e300}, 0, kInf};
  EXPECT_FALSE(is_valid(ray));
  SceneHit hit;
  EXPECT_FALSE(scene.intersect(ray, hit));
  std::vector<Crossing> all;
  scene.intersect_all(ray, all);
  EXPECT_TRUE(all.empty());
  // Just inside the domain the same ray hits where it should.
  const Ray ok{{0, 0, 0}, {1e150, 1e150, -1e150}, 0, kInf};
  ASSERT_TRUE(is_valid(ok));
  ASSERT_TRUE(scene.intersect(ok, hit));
  EXPECT_NEAR(hit.local.t * 1e150 * std::sqrt(3.0), 1.0, 1e-12);
  const SurfaceInfo s = scene.surface(ok, hit);
  EXPECT_NEAR(length(s.n), 1.0, 1e-12);
}

// A huge origin: o . o overflowed and the sphere reported a hit with a NaN normal.
TEST(Regression, HugeOrigin_NoHitWithNaNNormal) {
  const Scene scene = load_scene_text("objects:\n  - ellipsoid: {radii: [1, 2, 3]}\n");
  const Ray ray{{-1e300, 0, 0}, {1, 0, 0}, 0, kInf};
  EXPECT_FALSE(is_valid(ray));
  SceneHit hit;
  EXPECT_FALSE(scene.intersect(ray, hit));
  std::vector<Crossing> all;
  scene.intersect_all(ray, all);
  EXPECT_TRUE(all.empty());
}

// d . n subnormal: the plane's span ended at a surface crossing at t = -inf, which intersect_all
// reported for tmin = -inf. Now the line counts as parallel: one span with open ends or none.
TEST(Regression, PlaneSpans_NearlyParallel_NoCrossingAtInfinity) {
  const Plane plane = make_plane({0, 1, 0}, {0, 0, 0});
  const Ray ray{{5, 4, 3}, {1, kSub, -kSub}, -kInf, kInf};
  ASSERT_TRUE(is_valid(ray));
  SpanList spans;
  raycast::spans(plane, ray, spans);
  EXPECT_TRUE(spans.empty());  // above the plane: outside its half-space
  const Ray below{{5, -4, 3}, {1, kSub, -kSub}, -kInf, kInf};
  raycast::spans(plane, below, spans);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].in.part, kNoSurface);
  EXPECT_EQ(spans[0].out.part, kNoSurface);

  const Scene scene =
      load_scene_text("objects:\n  - plane: {normal: [0, 1, 0], point: [0, 0, 0]}\n");
  std::vector<Crossing> all;
  scene.intersect_all(ray, all);
  EXPECT_TRUE(all.empty());
}

// A 65536 x 65536 image passed the per-side limits and would have allocated 48 GiB.
TEST(Regression, HugeImageInSceneFile_RefusedAtItsPosition) {
  try {
    load_scene_text("objects: []\nimage: {width: 65536, height: 65536}\n", "s.yaml");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 8);
    EXPECT_EQ(e.message(),
              "image.width * image.height must be at most 268435456 pixels, got 65536 x 65536");
  }
  EXPECT_NO_THROW(load_scene_text("objects: []\nimage: {width: 65536, height: 4096}\n"));
}

}  // namespace
}  // namespace raycast
