#include <gtest/gtest.h>

#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

void expect_error_at(const std::string& yaml, int line, int column, const std::string& fragment) {
  try {
    load_scene_text(yaml, "s.yaml");
    ADD_FAILURE() << "no error for\n" << yaml;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(AlgebraicParse, ValidShapes_Load) {
  const Scene s = load_scene_text(
      "objects:\n"
      "  - torus: {major_radius: 1, minor_radius: 0.25}\n"
      "  - algebraic: {equation: \"x^2 + y^2 + z^2 - 1\", bounds: {min: [-1, -1, -1], max: [1, 1, "
      "1]}}\n"
      "  - algebraic: {equation: x^2 - y, bounds: {min: [-1, -1, -1], max: [1, 1, 1]}, open: "
      "true}\n");
  EXPECT_EQ(s.objects.size(), 3u);
}

TEST(AlgebraicParse, EquationErrors_PlainAndQuotedColumns) {
  // Plain scalar: the '*' at offset 11 of the text, which starts at column 28.
  expect_error_at(
      "objects:\n"
      "  - algebraic: {equation: x^2 + y^2 +* z^2, bounds: {min: [-1, -1, -1], max: [1, 1, 1]}}\n",
      2, 27 + 11, "algebraic.equation");
  // Double-quoted: the text starts one column after the quote at 28.
  expect_error_at(
      "objects:\n"
      "  - algebraic: {equation: \"x^2 - sin(x)\", bounds: {min: [-1, -1, -1], max: [1, 1, 1]}}\n",
      2, 28 + 6, "functions are not allowed");
  // Single-quoted, in block style.
  expect_error_at(
      "objects:\n"
      "  - algebraic:\n"
      "      equation: '(x + 1'\n"
      "      bounds: {min: [-1, -1, -1], max: [1, 1, 1]}\n",
      3, 17 + 1 + 6, "expected ')'");
}

TEST(AlgebraicParse, ImplicitFunctionErrors_Positioned) {
  expect_error_at(
      "objects:\n"
      "  - implicit:\n"
      "      function: sin(x) + cosh(y)\n"
      "      bounds: {min: [-1, -1, -1], max: [1, 1, 1]}\n",
      3, 17 + 9, "unknown name 'cosh'");
  const Scene s = load_scene_text(
      "objects:\n"
      "  - implicit: {function: \"x^2 + y^2 + z^2 - 1\", bounds: {min: [-1, -1, -1], max: [1, 1, "
      "1]}}\n");
  EXPECT_EQ(s.objects.size(), 1u);
}

TEST(AlgebraicParse, RevolutionErrors_Positioned) {
  expect_error_at("objects:\n  - revolution: {profile: [[1, 0], [-1, 2]]}\n", 2, 36,
                  "r must be >= 0");
  expect_error_at("objects:\n  - revolution: {profile: [[1, 0], [1, 2]], curve: nurbs}\n", 2, 52,
                  "linear or bspline");
  expect_error_at("objects:\n  - revolution: {profile: [[1, 0], [1, 2]], curve: bspline}\n", 2, 27,
                  "at least 4");
  expect_error_at("objects:\n  - revolution: {profile: [[1, 0, 3], [1, 2]]}\n", 2, 28, "[r, z]");
  const Scene s = load_scene_text(
      "objects:\n  - revolution: {profile: [[0, 0], [1, 0], [1, 1], [0, 2]], curve: linear, "
      "capped: false}\n");
  EXPECT_EQ(s.objects.size(), 1u);
}

TEST(AlgebraicParse, FieldErrors_Positioned) {
  expect_error_at("objects:\n  - algebraic: {equation: x^2 - 1}\n", 2, 16, "bounds is required");
  expect_error_at(
      "objects:\n"
      "  - algebraic: {equation: x - 1, bounds: {min: [1, -1, -1], max: [1, 1, 1]}}\n",
      2, 42, "min must be < max");
  expect_error_at("objects:\n  - torus: {major_radius: -1, minor_radius: 0.25}\n", 2, 27, "> 0");
  expect_error_at("objects:\n  - torus: {major_radius: 1, minor: 0.25}\n", 2, 12,
                  "minor_radius is required");
}

}  // namespace
}  // namespace raycast

namespace raycast {
namespace {

// The example scenes load, and a ray at each shape hits it with a unit normal facing the ray.
TEST(AlgebraicScenes, ExampleScenes_LoadAndHit) {
  const std::string dir = std::string(RAYCAST_SOURCE_DIR) + "/scenes/";
  struct Case {
    const char* file;
    Ray ray;
  };
  const Case cases[] = {
      {"torus.yaml", {{0, 2.2, -4.5}, {1, -1.7, 4.5}}},
      {"heart.yaml", {{0, -5, 0.6}, {0, 1, -0.12}}},
      {"implicit.yaml", {{9, -11, 7}, {-9, 11, -7}}},
      {"revolution.yaml", {{0, -9, 4}, {-1.3, 9, -2}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const Scene s = load_scene_file(dir + c.file);
    bool hit_shape = false;
    for (const Object& o : s.objects) {
      LocalHit h;
      if (std::string(shape_name(o)) == "plane" || !intersect(o, c.ray, h)) continue;
      const SurfaceInfo si = surface(o, c.ray, h);
      EXPECT_NEAR(length(si.n), 1, 1e-9);
      EXPECT_LT(dot(si.n, c.ray.d), 0);
      hit_shape = true;
    }
    EXPECT_TRUE(hit_shape);
  }
}

}  // namespace
}  // namespace raycast
