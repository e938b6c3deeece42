#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/camera.h"

namespace raycast {
namespace {

constexpr double kTol = 1e-12;

void expect_near(const Vec3& a, const Vec3& b, double tol = kTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

CameraDesc perspective() {
  CameraDesc c;
  c.position = {1, 2, 3};
  c.look_at = {-2, 0.5, -4};
  c.up = {0, 1, 0};
  c.fov = 50;
  return c;
}

TEST(Camera, CentrePixel_PointsAtLookAt) {
  const CameraDesc desc = perspective();
  const Camera camera(desc, 5, 3);  // odd sizes: pixel (2, 1)'s centre is the image centre
  const Ray r = camera.ray(2.5, 1.5);
  expect_near(r.o, desc.position);
  expect_near(r.d, normalize(desc.look_at - desc.position));
  EXPECT_NEAR(length(r.d), 1, kTol);
  EXPECT_EQ(r.tmin, 0);
  EXPECT_EQ(r.tmax, kInfinity);
}

TEST(Camera, TopAndBottomEdges_SpanTheVerticalFov) {
  const CameraDesc desc = perspective();
  const Camera camera(desc, 8, 6);
  const Vec3 w = normalize(desc.look_at - desc.position);
  const Ray top = camera.ray(4, 0), bottom = camera.ray(4, 6);
  EXPECT_NEAR(std::acos(dot(top.d, w)) * 180 / std::numbers::pi, 25, 1e-9);
  EXPECT_NEAR(std::acos(dot(top.d, bottom.d)) * 180 / std::numbers::pi, 50, 1e-9);
  EXPECT_GT(dot(top.d, desc.up), dot(bottom.d, desc.up));  // the top of the image is up
}

TEST(Camera, HorizontalExtent_FollowsTheAspectRatio) {
  CameraDesc desc;
  desc.position = {0, 0, 0};
  desc.look_at = {0, 0, -1};
  desc.fov = 90;  // image plane at distance 1 spans y in [-1, 1]
  const Camera camera(desc, 200, 100);
  const Ray right = camera.ray(200, 50);
  // Looking along -z with y up, the right of the image is +x (right-handed), at x = 2 on the plane.
  expect_near(right.d, normalize(Vec3{2, 0, -1}));
}

TEST(Camera, Orthographic_RaysAreParallelAndSpanHeight) {
  CameraDesc desc;
  desc.type = CameraType::kOrthographic;
  desc.position = {0, 0, 10};
  desc.look_at = {0, 0, 0};
  desc.height = 4;
  const Camera camera(desc, 30, 20);
  const Vec3 w{0, 0, -1};
  for (double x : {0.0, 7.5, 30.0})
    for (double y : {0.0, 13.0, 20.0}) expect_near(camera.ray(x, y).d, w);
  expect_near(camera.ray(15, 10).o, desc.position);
  expect_near(camera.ray(15, 0).o, {0, 2, 10});   // top edge: height / 2 up
  expect_near(camera.ray(30, 10).o, {3, 0, 10});  // right edge: aspect * height / 2
}

}  // namespace
}  // namespace raycast
