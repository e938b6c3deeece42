#include "load/loader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/scene_error.h"

namespace raycast {
namespace {

// Loads `text` as "s.yaml" and checks the error's position and exact message.
void expect_error(const std::string& text, int line, int column, const std::string& message) {
  try {
    load_scene_text(text, "s.yaml");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_EQ(e.message(), message) << e.what();
  }
}

std::string temp_file(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() / ("raycast_loader_test_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

TEST(Loader, UnknownKey_NamedAtItsPosition) {
  expect_error("objects:\n  - sphere: {radius: 1, radus: 2}\n", 2, 25,
               "unknown key 'radus' in sphere (did you mean 'radius'?)");
  expect_error("objects:\n  - cube: {radius: 1}\n", 2, 5,
               "unknown key 'cube' in object (expected a shape, group, union, intersection, "
               "difference, use or name, material, transform, shadows, image, reflections)");
  expect_error("objects: []\ncamra: {}\n", 2, 1,
               "unknown key 'camra' in scene (did you mean 'camera'?)");
  expect_error("objects: []\nzzzzzz: {}\n", 2, 1, "unknown key 'zzzzzz' in scene");
}

TEST(Loader, MisspeltRequiredKey_NamedWithTheKeyItResembles) {
  expect_error(
      "objectz:\n  - sphere: {radius: 1}\n", 1, 1,
      "unknown key 'objectz' in scene (did you mean 'objects'?); scene.objects is required");
  expect_error("objects:\n  - sphere: {radus: 1}\n", 2, 14,
               "unknown key 'radus' in sphere (did you mean 'radius'?); sphere.radius is required");
}

TEST(Loader, DuplicateKey_IsAnErrorNamingBothPositions) {
  expect_error("objects:\n  - sphere: {radius: 1, radius: 2}\n", 2, 25,
               "key 'radius' is given twice in sphere (first at 2:14)");
  expect_error("objects: []\nobjects:\n  - sphere: {radius: 1}\n", 2, 1,
               "key 'objects' is given twice in scene (first at 1:1)");
  expect_error("camera: {fov: 30, fov: 40}\nobjects: []\n", 1, 19,
               "key 'fov' is given twice in camera (first at 1:10)");
}

TEST(Loader, WrongType_SaysWhatWasExpected) {
  expect_error("objects:\n  - sphere: {radius: abc}\n", 2, 22,
               "sphere.radius must be a number, got abc");
  expect_error("objects:\n  - sphere: [1, 2]\n", 2, 13,
               "sphere must be a mapping, got a list of 2");
  expect_error("objects: {a: 1}\n", 1, 10, "objects must be a list, got a mapping");
  expect_error("objects:\n  - box: {min: 0, max: [1, 1, 1]}\n", 2, 16,
               "box.min must be a list of 3 numbers, got 0");
}

TEST(Loader, WrongListLength_NamesTheLength) {
  expect_error("objects:\n  - sphere: {center: [1, 2], radius: 1}\n", 2, 22,
               "sphere.center must be a list of 3 numbers, got a list of 2");
  expect_error("objects:\n  - triangle: {vertices: [[0, 0, 0], [1, 1, 1]]}\n", 2, 26,
               "triangle.vertices must be a list of 3 [x, y, z] points, got a list of 2");
  expect_error("objects:\n  - triangle: {vertices: [[0, 0, 0], [1, 0], [0, 1, 0]]}\n", 2, 38,
               "triangle.vertices[1] must be a list of 3 numbers, got a list of 2");
}

TEST(Loader, RadiusNotPositive_IsRejected) {
  expect_error("objects:\n  - sphere: {radius: -1}\n", 2, 22, "sphere.radius must be > 0, got -1");
  expect_error("objects:\n  - sphere: {radius: 0}\n", 2, 22, "sphere.radius must be > 0, got 0");
  expect_error("objects:\n  - disk: {radius: -2}\n", 2, 20, "disk.radius must be > 0, got -2");
}

TEST(Loader, NanAndInfinity_AreRejected) {
  expect_error("objects:\n  - sphere: {radius: .nan}\n", 2, 22,
               "sphere.radius must be finite, got .nan");
  expect_error("objects:\n  - sphere: {radius: .inf}\n", 2, 22,
               "sphere.radius must be finite, got .inf");
  expect_error("objects:\n  - sphere: {center: [0, -.inf, 0], radius: 1}\n", 2, 26,
               "sphere.center[1] must be finite, got -.inf");
  expect_error("objects:\n  - box: {min: [0, 0, 0], max: [1, .NaN, 1]}\n", 2, 36,
               "box.max[1] must be finite, got .NaN");
  expect_error("objects:\n  - disk: {radius: 1, height: .inf}\n", 2, 31,
               "disk.height must be finite, got .inf");
}

TEST(Loader, MissingField_IsRequired) {
  expect_error("objects:\n  - box: {min: [0, 0, 0]}\n", 2, 10, "box.max is required");
  expect_error("objects:\n  - disk: {center: [0, 0, 0], radius: 1}\n", 2, 11,
               "disk.normal is required");
  expect_error("camera: {}\n", 1, 1, "scene.objects is required");
}

TEST(Loader, MissingOrUnsupportedTexture_IsAnErrorAtTheFileField) {
  const std::string text =
      "materials:\n  m: {texture: {image: {file: %s}}}\nobjects:\n  - sphere: {radius: 1}\n";
  char missing[256], exr[256];
  std::snprintf(missing, sizeof missing, text.c_str(), "no_such_texture.png");
  std::snprintf(exr, sizeof exr, text.c_str(), "t.exr");
  for (const char* scene : {missing, exr}) {
    try {
      load_scene_text(scene, "s.yaml", "/nonexistent-dir");
      ADD_FAILURE() << "no error for " << scene;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.line(), 2) << e.what();
      EXPECT_EQ(e.column(), 31) << e.what();
      EXPECT_EQ(e.message().rfind("texture image: /nonexistent-dir/", 0), 0u) << e.what();
    }
  }
}

TEST(Loader, UnknownMaterial_IsNamed) {
  expect_error("objects:\n  - sphere: {radius: 1}\n    material: glas\n", 3, 15,
               "unknown material 'glas'");
}

TEST(Loader, BasicShapeValues_AreValidatedWithPositions) {
  expect_error("objects:\n  - triangle: {vertices: [[0, 0, 0], [1, 1, 1], [2, 2, 2]]}\n", 2, 26,
               "triangle.vertices are collinear or coincide (a degenerate triangle)");
  expect_error("objects:\n  - triangle: {vertices: [[0, 0, 0], [0, 0, 0], [0, 1, 0]]}\n", 2, 26,
               "triangle.vertices are collinear or coincide (a degenerate triangle)");
  expect_error(
      "objects:\n  - triangle: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], normals: [[0, 0, 1], "
      "[0, 0, 0], [0, 0, 1]]}\n",
      2, 82, "triangle.normals[1] must be a non-zero vector");
  expect_error("objects:\n  - box: {min: [0, 0, 0], max: [1, 0, 1]}\n", 2, 32,
               "box.max must be > min on every axis, got 0 <= 0 on y");
  expect_error("objects:\n  - disk: {radius: 1, inner_radius: 1}\n", 2, 37,
               "disk.inner_radius must be in [0, radius), got 1");
  expect_error("objects:\n  - disk: {radius: 1, phi_max: 0}\n", 2, 32,
               "disk.phi_max must be in (0, 360], got 0");
  expect_error("objects:\n  - disk: {center: [0, 0, 0], normal: [0, 0, 1], radius: 1, height: 2}\n",
               2, 69, "disk.height cannot be combined with center and normal (use a transform)");
  expect_error("objects:\n  - parallelogram: {origin: [0, 0, 0], u: [1, 0, 0], v: [2, 0, 0]}\n", 2,
               57, "parallelogram.v and u must be non-zero and not parallel");
  expect_error("objects:\n  - parallelogram: {origin: [0, 0, 0], u: [1, 0, 0], v: [0, 0, 0]}\n", 2,
               57, "parallelogram.v must be a non-zero vector");
}

TEST(Loader, SyntaxError_ReportsWhereTheUnclosedCollectionOpened) {
  expect_error("objects:\n  - sphere: {radius: 1\n  - plane: {normal: [0, 1, 0]}\n", 2, 13,
               "this '{' is never closed (end of map flow not found at 3:10)");
  expect_error("objects: [\n  {sphere: {radius: 1}}\n", 1, 10,
               "this '[' is never closed (end of sequence flow not found at 3:1)");
  expect_error("objects: []\ncamera: {fov: 30}}\n", 2, 18, "illegal flow end");
}

TEST(Loader, SyntaxError_ReportsYamlPosition) {
  expect_error("objects:\n  - sphere: {radius: 1\n", 2, 13,
               "this '{' is never closed (end of map flow not found at 3:1)");
}

TEST(Loader, EmptyFile_IsAnErrorWithoutPosition) {
  const std::string path = temp_file("empty.yaml", "");
  try {
    load_scene_file(path);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.message(), "the scene is empty (expected a mapping with `objects`)");
    EXPECT_EQ(std::string(e.what()),
              path + ": the scene is empty (expected a mapping with `objects`)");
  }
  expect_error("# only a comment\n", 0, 0,
               "the scene is empty (expected a mapping with `objects`)");
  std::filesystem::remove(path);
}

TEST(Loader, UnreadableFile_IsNamed) {
  try {
    load_scene_file("/nonexistent/raycast/scene.yaml");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/raycast/scene.yaml: cannot open the scene file");
  }
  try {
    load_scene_file(std::filesystem::temp_directory_path().string());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.message(), "is a directory, not a scene file");
  }
}

TEST(Loader, HundredThousandNestedLists_CleanErrorNoStackOverflow) {
  // yaml-cpp 0.7 recurses per level; the loader's pre-scan stops at kMaxNesting.
  const std::string deep(100000, '[');
  expect_error(deep, 1, kMaxNesting, "the YAML is nested deeper than 256 levels");
  expect_error("objects: " + std::string(100000, '[') + std::string(100000, ']'), 1,
               10 + kMaxNesting - 1, "the YAML is nested deeper than 256 levels");
  std::string block = "objects:\n";
  for (int i = 0; i < 300; ++i) block += std::string(i, ' ') + "a:\n";
  expect_error(block, 258, 257, "the YAML is nested deeper than 256 levels");
  std::string dashes = "objects:\n";
  for (int i = 0; i < 300; ++i) dashes += "- ";
  expect_error(dashes + "x\n", 2, 2 * kMaxNesting - 1, "the YAML is nested deeper than 256 levels");
}

TEST(Loader, NestingWithinLimit_AndBracketsInStrings_AreFine) {
  // Brackets inside quotes and comments do not count.
  const Scene s = load_scene_text(
      "# [[[[[[[[\nobjects:\n  - sphere: {radius: 1}  # ]]]][[[[\n    name: \"[[[[{{{{\"\n");
  EXPECT_EQ(s.objects.size(), 1u);
  // Block scalars are text, whatever brackets they hold.
  std::string text = "objects:\n  - sphere: {radius: 1}\n    name: |\n";
  for (int i = 0; i < 100; ++i) text += "      [[[[ {{{{ - - - -\n";
  text += "\n      more text\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\n";
  EXPECT_EQ(load_scene_text(text).objects.size(), 2u);
  // 200 levels of flow lists are parsed (and then rejected as an object, not as nesting).
  expect_error("objects: " + std::string(200, '[') + std::string(200, ']'), 1, 11,
               "an object must be a mapping with one shape key, got a list of 1");
}

TEST(Loader, EveryBasicShape_ParsedWithItsParameters) {
  const Scene s = load_scene_text(R"(objects:
  - box: {min: [-1, -2, -3], max: [1, 2, 3]}
  - triangle: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], normals: [[0, 0, 1], [0, 1, 1], [1, 0, 1]]}
  - parallelogram: {origin: [1, 2, 3], u: [1, 0, 0], v: [0, 2, 0]}
  - disk: {radius: 2, inner_radius: 0.5, height: 1, phi_max: 90}
  - disk: {center: [1, 1, 1], normal: [0, 1, 0], radius: 1}
  - sphere: {radius: 1}
    transform: [{translate: [5, 0, 0]}]
)");
  ASSERT_EQ(s.objects.size(), 6u);
  const Box& b = std::get<Box>(s.objects[0].shape);
  EXPECT_EQ(b.lo, Vec3(-1, -2, -3));
  EXPECT_EQ(b.hi, Vec3(1, 2, 3));
  const Triangle& t = std::get<Triangle>(s.objects[1].shape);
  EXPECT_TRUE(t.has_normals);
  EXPECT_EQ(t.n, Vec3(0, 0, 1));
  const Parallelogram& q = std::get<Parallelogram>(s.objects[2].shape);
  EXPECT_EQ(q.origin, Vec3(1, 2, 3));
  EXPECT_EQ(q.v, Vec3(0, 2, 0));
  const Disk& d = std::get<Disk>(s.objects[3].shape);
  EXPECT_EQ(d.radius, 2);
  EXPECT_EQ(d.inner_radius, 0.5);
  EXPECT_EQ(d.center.z, 1);
  EXPECT_NEAR(d.phi_max, 3.14159265358979323846 / 2, 1e-15);
  const Disk& dc = std::get<Disk>(s.objects[4].shape);
  EXPECT_EQ(dc.n, Vec3(0, 1, 0));
  EXPECT_FALSE(dc.canonical);
  EXPECT_STREQ(shape_name(s.objects[2]), "parallelogram");
  EXPECT_TRUE(s.objects[5].xf.has_value());
  EXPECT_EQ(s.entries, 6);
}

TEST(Loader, CameraLenses_TheirAnglesAndErrors) {
  const Scene s = load_scene_text(
      "camera: {type: spherical, position: [0, 0, 0], look_at: [0, 0, -1], angle: 300}\n"
      "objects:\n  - sphere: {radius: 1}\n",
      "s.yaml");
  ASSERT_TRUE(s.camera);
  EXPECT_EQ(s.camera->type, CameraType::kSpherical);
  EXPECT_EQ(s.camera->angle, 300);
  EXPECT_EQ(s.camera->vertical_angle, 150);
  const Scene c = load_scene_text(
      "camera: {type: cylinder, cylinder: 2, angle: 120}\nobjects:\n  - sphere: {radius: 1}\n",
      "s.yaml");
  EXPECT_EQ(c.camera->cylinder, 2);
  expect_error("camera: {type: fisheye, angle: 0}\nobjects: []\n", 1, 32,
               "camera.angle must be in (0, 360] degrees");
  expect_error("camera: {type: cylinder, cylinder: 5}\nobjects: []\n", 1, 36,
               "camera.cylinder must be a whole number in [1, 4], got 5");
  expect_error("camera: {type: fish}\nobjects: []\n", 1, 16,
               "camera.type must be perspective, orthographic, fisheye, ultra_wide_angle, "
               "omnimax, panoramic, cylinder or spherical, got fish");
}

TEST(Loader, CameraFrame_DirectionAndRightTogether) {
  const Scene s = load_scene_text(
      "camera: {direction: [0, 0, -2], right: [3, 0, 0], up: [0, 1, 0]}\n"
      "objects:\n  - sphere: {radius: 1}\n",
      "s.yaml");
  ASSERT_TRUE(s.camera && s.camera->frame);
  EXPECT_EQ(s.camera->frame->right, (Vec3{3, 0, 0}));
  EXPECT_EQ(s.camera->frame->direction, (Vec3{0, 0, -2}));
  expect_error("camera: {direction: [0, 0, -1]}\nobjects: []\n", 1, 9, "camera.right is required");
}

TEST(Loader, LightKinds_AreaCylinderFadeShadows) {
  const Scene s = load_scene_text(
      "lights:\n"
      "  - {type: area, position: [0, 5, 0], axis1: [1, 0, 0], axis2: [0, 0, 1], size1: 3, "
      "jitter: true, direction: [0, -1, 0], angle: 40, edge: cosine}\n"
      "  - {type: cylinder, position: [0, 5, 0], direction: [0, -1, 0], radius: 2, falloff: 1}\n"
      "  - {type: point, position: [0, 5, 0], attenuation: fade, fade_distance: 3, shadows: "
      "false}\n"
      "  - {type: directional, direction: [0, -1, 0], position: [0, 9, 0]}\n"
      "objects:\n  - sphere: {radius: 1}\n",
      "s.yaml");
  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_EQ(s.lights[0].type, LightType::kArea);
  EXPECT_EQ(s.lights[0].size1, 3);
  EXPECT_EQ(s.lights[0].size2, 2);
  EXPECT_TRUE(s.lights[0].jitter && s.lights[0].spot);
  EXPECT_EQ(s.lights[0].edge, SpotEdge::kCosine);
  EXPECT_EQ(s.lights[1].type, LightType::kCylinder);
  EXPECT_EQ(s.lights[1].angle, 2);
  EXPECT_EQ(s.lights[2].attenuation, Attenuation::kFade);
  EXPECT_EQ(s.lights[2].fade_distance, 3);
  EXPECT_EQ(s.lights[2].fade_power, 2);
  EXPECT_FALSE(s.lights[2].shadows);
  EXPECT_TRUE(s.lights[3].bounded);
  expect_error("lights:\n  - {type: laser}\nobjects: []\n", 2, 12,
               "light.type must be point, directional, spot, sphere, cylinder or area, got laser");
  expect_error(
      "lights:\n  - {type: cylinder, position: [0, 0, 0], direction: [0, -1, 0], radius: 1, "
      "falloff: 2}\nobjects: []\n",
      2, 86, "light.falloff must be at most radius");
}

TEST(Loader, ObjectShadowsFalse_AppliesToEveryPart) {
  const Scene s = load_scene_text(
      "objects:\n"
      "  - sphere: {radius: 1}\n"
      "  - group:\n      - sphere: {radius: 1}\n      - box: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "    shadows: false\n"
      "  - {sphere: {radius: 1}, shadows: true}\n",
      "s.yaml");
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_TRUE(s.objects[0].casts_shadow);
  EXPECT_FALSE(s.objects[1].casts_shadow);
  EXPECT_FALSE(s.objects[2].casts_shadow);
  EXPECT_TRUE(s.objects[3].casts_shadow);
  expect_error("objects:\n  - {sphere: {radius: 1}, shadows: maybe}\n", 2, 36,
               "shadows must be true or false, got maybe");
  expect_error(
      "objects:\n  - union:\n      - {sphere: {radius: 1}, shadows: false}\n"
      "      - sphere: {radius: 2}\n",
      3, 40, "shadows applies to whole objects, not to CSG operands");
}

}  // namespace
}  // namespace raycast
