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

// The lenses on a 200 x 100 image (aspect 2): looking along -z with y up, so right is +x and the
// default frame has up of length 1 and right of length 2.
CameraDesc lens(CameraType type, double angle) {
  CameraDesc c;
  c.type = type;
  c.position = {0, 0, 0};
  c.look_at = {0, 0, -1};
  c.angle = angle;
  return c;
}

bool is_empty(const Ray& r) { return !(r.tmin <= r.tmax); }

TEST(CameraLens, Fisheye_RadiusIsTheAngleFromTheAxis_OutsideTheCircleNoRay) {
  const Camera cam(lens(CameraType::kFisheye, 180), 200, 100);
  expect_near(cam.ray(100, 50).d, {0, 0, -1});
  expect_near(cam.ray(150, 50).d, {1, 0, 0});  // half the height from the centre: 90 degrees
  expect_near(cam.ray(100, 0).d, {0, 1, 0});
  const double t = std::sqrt(0.125) * std::numbers::pi;  // (0.25, 0.25) from the centre
  expect_near(cam.ray(125, 25).d,
              Vec3{std::sin(t) / std::sqrt(2), std::sin(t) / std::sqrt(2), -std::cos(t)});
  EXPECT_TRUE(is_empty(cam.ray(0, 0)));     // a corner
  EXPECT_TRUE(is_empty(cam.ray(200, 50)));  // the right edge, outside the circle
  EXPECT_FALSE(is_empty(cam.ray(100, 50)));
  // Omnimax is drawn as a fisheye of 180 degrees, whatever its angle.
  expect_near(Camera(lens(CameraType::kOmnimax, 90), 200, 100).ray(150, 50).d, {1, 0, 0});
}

TEST(CameraLens, UltraWideAngle_AnglesScaleWithTheSides) {
  const Camera cam(lens(CameraType::kUltraWideAngle, 180), 200, 100);
  expect_near(cam.ray(100, 50).d, {0, 0, -1});
  expect_near(cam.ray(200, 50).d, {1, 0, 0});                             // 90 degrees right
  expect_near(cam.ray(100, 0).d, normalize(Vec3{0, 1, -1}));              // 45 up (half the aspect)
  expect_near(cam.ray(200, 0).d, normalize(Vec3{1, std::sqrt(0.5), 0}));  // the corner
}

TEST(CameraLens, Panoramic_HalfTurnEachWay_OnTheFrameEllipsoid) {
  const Camera cam(lens(CameraType::kPanoramic, 10), 200, 100);  // the angle is not used
  expect_near(cam.ray(100, 50).d, {0, 0, -1});
  expect_near(cam.ray(200, 50).d, {1, 0, 0});
  expect_near(cam.ray(150, 50).d, normalize(Vec3{2, 0, -1}));  // right has length 2
  expect_near(cam.ray(100, 25).d, normalize(Vec3{0, 1, -1}));
  expect_near(cam.ray(100, 100).d, {0, -1, 0});
}

TEST(CameraLens, Cylinders_AroundAndAlongTheAxis) {
  CameraDesc c = lens(CameraType::kCylinder, 180);
  for (int kind = 1; kind <= 4; ++kind) {
    c.cylinder = kind;
    const Camera cam(c, 200, 100);
    const Ray centre = cam.ray(100, 50), corner = cam.ray(200, 0);
    expect_near(centre.o, {0, 0, 0});
    expect_near(centre.d, {0, 0, -1});
    switch (kind) {
      case 1:  // vertical axis: 90 degrees right, up by half of up's length
        expect_near(corner.d, normalize(Vec3{1, 0.5, 0}));
        break;
      case 2:  // horizontal axis: 90 degrees up, right by half of right's length
        expect_near(corner.d, normalize(Vec3{1, 1, 0}));
        break;
      case 3:  // the viewpoint moves up the axis
        expect_near(corner.o, {0, 0.5, 0});
        expect_near(corner.d, {1, 0, 0});
        break;
      case 4:
        expect_near(corner.o, {1, 0, 0});
        expect_near(corner.d, {0, 1, 0});
        break;
    }
  }
}

TEST(CameraLens, Spherical_LongitudeAndLatitude) {
  CameraDesc c = lens(CameraType::kSpherical, 360);
  const Camera cam(c, 200, 100);  // vertical angle: half the horizontal
  expect_near(cam.ray(100, 50).d, {0, 0, -1});
  expect_near(cam.ray(150, 50).d, {1, 0, 0});
  expect_near(cam.ray(125, 50).d, normalize(Vec3{1, 0, -1}));
  expect_near(cam.ray(0, 0).d, {0, 1, 0});
  expect_near(cam.ray(100, 100).d, {0, -1, 0});
  c.angle = 180;
  c.vertical_angle = 60;
  const double a = 30 * std::numbers::pi / 180;
  expect_near(Camera(c, 200, 100).ray(100, 0).d, {0, std::sin(a), -std::cos(a)});
  expect_near(Camera(c, 200, 100).ray(200, 50).d, {1, 0, 0});
}

TEST(CameraFrame, SkewedPerspective_SpansRightAndUpAtDirection) {
  CameraDesc c;
  c.position = {1, 2, 3};
  c.frame = CameraFrame{{0, 0, -2}, {2, 0, 0.5}, {0, 1, 0}};
  const Camera cam(c, 64, 48);  // the frame's aspect (2), not the image's, decides the view
  expect_near(cam.ray(32, 24).d, {0, 0, -1});
  expect_near(cam.ray(32, 24).o, {1, 2, 3});
  // Top-left corner: direction - right / 2 + up / 2.
  expect_near(cam.ray(0, 0).d, normalize(Vec3{-1, 0.5, -2.25}));
  expect_near(cam.ray(64, 48).d, normalize(Vec3{1, -0.5, -1.75}));
}

TEST(CameraFrame, Orthographic_OriginsSpanRightAndUp) {
  CameraDesc c;
  c.type = CameraType::kOrthographic;
  c.position = {0, 0, 5};
  c.frame = CameraFrame{{0, 0, -3}, {4, 0, 0}, {0, 2, 0}};
  const Camera cam(c, 10, 10);
  expect_near(cam.ray(0, 0).o, {-2, 1, 5});
  expect_near(cam.ray(10, 10).o, {2, -1, 5});
  expect_near(cam.ray(0, 0).d, {0, 0, -1});
}

}  // namespace
}  // namespace raycast
