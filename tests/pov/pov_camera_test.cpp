// POV-Ray cameras as the import builds them: the projection keywords, their angles, the frame
// of direction, right and up kept as written (lengths, skew), orthographic's angle mode, and the
// rays at the image's centre and corners.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/pov_loader.h"
#include "render/camera.h"

namespace raycast {
namespace {

Scene load(const std::string& camera, std::vector<std::string>* warnings = nullptr) {
  return load_pov_scene_text(camera + "\nsphere { 0, 1 }", "t.pov", ".", -1, {}, warnings);
}

void expect_near(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(PovCamera, Fisheye_AngleAndRays) {
  const Scene s = load("camera { fisheye location 0 look_at z angle 180 }");
  ASSERT_TRUE(s.camera && s.camera->frame);
  EXPECT_EQ(s.camera->type, CameraType::kFisheye);
  EXPECT_EQ(s.camera->angle, 180);
  const Camera cam(*s.camera, 160, 120);
  // POV-Ray's +z is raycast's -z (the left-handed frame is mirrored); +x stays right.
  expect_near(cam.ray(80, 60).d, {0, 0, -1});
  expect_near(cam.ray(80, 0).d, {0, 1, 0});                // the circle's top: 90 degrees up
  EXPECT_FALSE(cam.ray(0, 0).tmin <= cam.ray(0, 0).tmax);  // a corner: outside the circle
}

TEST(PovCamera, LensesWithoutAngle_Take90Degrees_Spherical360By180) {
  EXPECT_EQ(load("camera { ultra_wide_angle location 0 look_at z }").camera->angle, 90);
  EXPECT_EQ(load("camera { panoramic location 0 }").camera->type, CameraType::kPanoramic);
  const Scene sph = load("camera { spherical location 0 look_at z }");
  EXPECT_EQ(sph.camera->angle, 360);
  const Camera cam(*sph.camera, 200, 100);
  expect_near(cam.ray(0, 0).d, {0, 1, 0});
  expect_near(cam.ray(150, 50).d, {1, 0, 0});
  const Scene two = load("camera { spherical angle 120, 40 location 0 look_at z }");
  EXPECT_EQ(two.camera->angle, 120);
  EXPECT_EQ(two.camera->vertical_angle, 40);
}

TEST(PovCamera, Cylinder_KindsOneToFour_OthersAreErrors) {
  const Scene s = load("camera { cylinder 3 location 0 look_at z angle 90 }");
  EXPECT_EQ(s.camera->type, CameraType::kCylinder);
  EXPECT_EQ(s.camera->cylinder, 3);
  const Camera cam(*s.camera, 160, 120);
  expect_near(cam.ray(80, 0).o, {0, 0.5, 0});  // the viewpoint moves up the axis by up / 2
  try {
    load("camera { cylinder 5 }");
    ADD_FAILURE() << "cylinder 5 loaded";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("1, 2, 3 or 4"), std::string::npos) << e.what();
  }
}

TEST(PovCamera, Omnimax_IsAFisheyeOf180Degrees_Warned) {
  std::vector<std::string> warnings;
  const Scene s = load("camera { omnimax location 0 look_at z }", &warnings);
  EXPECT_EQ(s.camera->type, CameraType::kOmnimax);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("omnimax"), std::string::npos) << warnings[0];
}

TEST(PovCamera, RightAndUp_KeepTheirLengthsAndSkew_TheAspectIsTheirs) {
  const Scene s = load("camera { location 0 direction z right <2, 0, 0.5> up y }");
  ASSERT_TRUE(s.camera->frame);
  const CameraFrame& f = *s.camera->frame;
  expect_near(f.right, {2, 0, -0.5});  // mirrored z
  expect_near(f.direction, {0, 0, -1});
  EXPECT_EQ(s.image.width, std::lround(480 * std::sqrt(4.25)));  // as |right| / |up| asks
  const Camera cam(*s.camera, 64, 48);
  expect_near(cam.ray(0, 0).d, normalize(Vec3{-1, 0.5, -1 + 0.25}));
}

TEST(PovCamera, Angle_SetsDirectionFromRight_AfterLookAt) {
  const Scene s = load("camera { location <0, 0, -5> angle 90 right x up 0.75 * y look_at 0 }");
  const Camera cam(*s.camera, 4, 3);
  // 90 degrees across right: the right edge's ray is 45 degrees off the axis.
  expect_near(cam.ray(4, 1.5).d, normalize(Vec3{1, 0, -1}));
}

TEST(PovCamera, Orthographic_WithoutUpAndRight_SeesThePerspectiveViewAtLookAt) {
  // The default right (1.33) and direction (1): at look_at 6 away the view is 8 wide.
  const Scene s = load("camera { orthographic location <0, 0, -5> look_at <0, 0, 1> }");
  EXPECT_EQ(s.camera->type, CameraType::kOrthographic);
  EXPECT_NEAR(length(s.camera->frame->right), 1.33 * 6, 1e-12);
  EXPECT_NEAR(length(s.camera->frame->up), 6, 1e-12);
  const Scene given = load("camera { orthographic location <0, 0, -5> up 3*y right 8*x }");
  EXPECT_EQ(length(given.camera->frame->right), 8);
  const Scene angle = load("camera { orthographic location <0, 0, -5> angle 90 look_at <0,0,1> }");
  EXPECT_NEAR(length(angle.camera->frame->right), 12, 1e-12);  // 2 * 6 * tan(45)
  // `angle 0` is no angle (POV-Ray renders such scenes as if it were not written).
  const Scene zero =
      load("camera { orthographic location <0, 0, -5> angle 0 right 8*x up 3*y look_at 0 }");
  EXPECT_NEAR(length(zero.camera->frame->right), 8, 1e-12);
}

TEST(PovCamera, Sky_TiltsTheFrame) {
  const Scene s = load("camera { location 0 sky <1, 1, 0> look_at z }");
  const Camera cam(*s.camera, 160, 120);
  // Up leans towards +x by 45 degrees.
  expect_near(cam.ray(80, 0).d, normalize(Vec3{0.5 * std::sqrt(0.5), 0.5 * std::sqrt(0.5), -1}));
}

}  // namespace
}  // namespace raycast
