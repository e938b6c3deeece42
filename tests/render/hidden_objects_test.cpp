// Objects hidden from camera rays or from mirrored rays (Object::seen_by_camera,
// seen_in_reflections; POV-Ray's no_image and no_reflection): what each kind of ray sees, that
// hidden objects still cast shadows, the YAML keys and the POV-Ray reader's.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_error.h"
#include "load/loader.h"
#include "load/pov_loader.h"
#include "render/explain.h"
#include "render/renderer.h"

namespace raycast {
namespace {

// Looking down -z at a red sphere in front of a green wall; a mirror behind the camera is not
// in view, so the second scene below looks at the sphere through a mirror instead.
std::string front_scene(const std::string& sphere_keys) {
  return R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 10}
image: {width: 3, height: 3, samples: 1}
render: {background: [0, 0, 1], ambient: [1, 1, 1]}
materials:
  red: {color: [1, 0, 0], ambient: 1, diffuse: 0}
  green: {color: [0, 1, 0], ambient: 1, diffuse: 0}
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
    material: red
    )" + sphere_keys +
         R"(
  - plane: {normal: [0, 0, 1], point: [0, 0, -3]}
    material: green
)";
}

// The camera looks at a mirror that shows a red sphere beside the camera.
std::string mirror_scene(const std::string& sphere_keys) {
  return R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 4}
image: {width: 3, height: 3, samples: 1}
render: {background: [0, 0, 1], ambient: [1, 1, 1], max_depth: 3}
materials:
  red: {color: [1, 0, 0], ambient: 1, diffuse: 0}
  mirror: {color: [0, 0, 0], ambient: 0, diffuse: 0, reflection: 1}
objects:
  - box: {min: [-5, -5, -1], max: [5, 5, 0]}
    material: mirror
  - sphere: {center: [0, 0, 10], radius: 1}
    material: red
    )" + sphere_keys +
         R"(
)";
}

Vec3f centre(const std::string& yaml) {
  RenderOptions o;
  o.spp = 1;
  o.progress = false;
  return render(load_scene_text(yaml), o).at(1, 1);
}

TEST(HiddenObjects, ImageFalse_CameraRaysSeeWhatLiesBehind) {
  EXPECT_EQ(centre(front_scene("")), Vec3f(1, 0, 0));
  EXPECT_EQ(centre(front_scene("image: false")), Vec3f(0, 1, 0));
  EXPECT_EQ(centre(front_scene("reflections: false")), Vec3f(1, 0, 0));
}

TEST(HiddenObjects, ReflectionsFalse_MirroredRaysSeeWhatLiesBehind) {
  // The camera at z = 5 sits inside the red sphere's reach only through the mirror: the sphere
  // at z = 10 is behind the camera.
  EXPECT_EQ(centre(mirror_scene("")), Vec3f(1, 0, 0));
  EXPECT_EQ(centre(mirror_scene("reflections: false")), Vec3f(0, 0, 1));
  EXPECT_EQ(centre(mirror_scene("image: false")), Vec3f(1, 0, 0));
}

TEST(HiddenObjects, HiddenObject_StillCastsItsShadow) {
  const std::string scene = R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 10}
image: {width: 3, height: 3, samples: 1}
render: {background: [0, 0, 0], ambient: [0, 0, 0]}
lights:
  - {type: point, position: [0, 0, 20]}
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
    image: false
  - plane: {normal: [0, 0, 1], point: [0, 0, -3]}
)";
  EXPECT_EQ(centre(scene), Vec3f(0, 0, 0)) << "the wall behind the hidden sphere is in its shadow";
}

TEST(HiddenObjects, ExplainedPixel_EqualsTheRender) {
  const Scene scene = load_scene_text(front_scene("image: false"));
  ExplainOptions o;
  o.x = 1;
  o.y = 1;
  o.width = 3;
  o.height = 3;
  EXPECT_EQ(Vec3f(explain_pixel(scene, o).color), Vec3f(0, 1, 0));
}

TEST(HiddenObjects, YamlFlags_MustBeBooleansOnWholeObjects) {
  EXPECT_THROW(load_scene_text(front_scene("image: sometimes")), SceneError);
  const std::string operand = R"(
objects:
  - union:
      - sphere: {center: [0, 0, 0], radius: 1}
        reflections: false
      - sphere: {center: [1, 0, 0], radius: 1}
)";
  EXPECT_THROW(load_scene_text(operand), SceneError);
}

TEST(HiddenObjects, PovNoImageAndNoReflection_HideTheObject) {
  const Scene scene = load_pov_scene_text(R"(
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 no_image }
sphere { x, 1 no_reflection }
box { -1, 1 }
)",
                                          "hidden.pov", ".");
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_FALSE(scene.objects[0].seen_by_camera);
  EXPECT_TRUE(scene.objects[0].seen_in_reflections);
  EXPECT_TRUE(scene.objects[1].seen_by_camera);
  EXPECT_FALSE(scene.objects[1].seen_in_reflections);
  EXPECT_TRUE(scene.objects[2].seen_by_camera && scene.objects[2].seen_in_reflections);
}

}  // namespace
}  // namespace raycast
