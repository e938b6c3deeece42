// `raycast validate`: exit 0 when clean, 1 with warnings only, 2 with errors; every finding with
// its position.
#include <gtest/gtest.h>

#include <string>

#include "../support/cli_runner.h"

namespace {

using raycast::test::Outcome;
using raycast::test::run;
using raycast::test::write;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Validate, CleanScene_ExitsZero) {
  const std::string scene = write("clean.yaml",
                                  "lights:\n  - {type: point, position: [0, 5, -5]}\n"
                                  "objects:\n  - sphere: {radius: 1}\n");
  const Outcome r = run("validate '" + scene + "'");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_TRUE(has(r.out, "0 errors, 0 warnings")) << r.out;
}

TEST(Validate, NoLights_IsAWarning) {
  const std::string scene = write("dark.yaml", "objects:\n  - sphere: {radius: 1}\n");
  const Outcome r = run("validate '" + scene + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.out, "warning: the scene has no lights")) << r.out;
}

TEST(Validate, CameraInsideASolid_WarnsAtTheCamera) {
  const std::string scene = write("inside.yaml",
                                  "camera: {position: [0, 0, 0], look_at: [0, 0, 1]}\n"
                                  "lights:\n  - {type: directional, direction: [0, -1, 0]}\n"
                                  "objects:\n  - sphere: {radius: 3}\n");
  const Outcome r = run("validate '" + scene + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.out,
                  "inside.yaml:1:9: warning: the camera at (0, 0, 0) is inside the sphere "
                  "of objects entry 1 (line 5)"))
      << r.out;
}

TEST(Validate, LightInsideAnOpaqueSolid_WarnsAtTheLight_ButNotInsideGlass) {
  const std::string scene = write("buried.yaml",
                                  "camera: {position: [0, 0, -10], look_at: [0, 0, 0]}\n"
                                  "materials:\n  glass: {transmission: 0.9, ior: 1.5}\n"
                                  "lights:\n"
                                  "  - {type: point, position: [0, 0, 0]}\n"
                                  "  - {type: point, position: [5, 0, 0]}\n"
                                  "objects:\n  - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
                                  "  - sphere: {center: [5, 0, 0], radius: 1}\n"
                                  "    material: glass\n");
  const Outcome r = run("validate '" + scene + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.out, "buried.yaml:5:5: warning: light 1 at (0, 0, 0) is inside the box"))
      << r.out;
  EXPECT_FALSE(has(r.out, "light 2")) << r.out;
}

TEST(Validate, DegenerateTrianglesAndUnboundedShapes_AreReported) {
  const std::string scene = write("mesh.yaml",
                                  "lights:\n  - {type: point, position: [0, 5, -5]}\n"
                                  "objects:\n  - plane: {normal: [0, 1, 0], point: [0, -1, 0]}\n"
                                  "  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
                                  "triangles: [[0, 1, 2], [0, 0, 1]]}\n");
  const Outcome r = run("validate '" + scene + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.out, "mesh.yaml:5:5: warning: 1 degenerate triangles")) << r.out;
  EXPECT_TRUE(has(r.out, "mesh.yaml:4:5: note: the plane is unbounded")) << r.out;
}

TEST(Validate, SceneThatDoesNotLoad_IsAnErrorWithPosition_ExitsTwo) {
  const std::string scene = write("bad.yaml", "objects:\n  - sphere: {radius: -1}\n");
  const Outcome r = run("validate '" + scene + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.out, "bad.yaml:2:22: error: sphere.radius must be > 0")) << r.out;
}

TEST(Validate, Json_ListsFindingsWithSeverityAndPosition) {
  const std::string scene = write("dark2.yaml", "objects:\n  - sphere: {radius: 1}\n");
  const Outcome r = run("validate --json '" + scene + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.out, "\"errors\": 0, \"warnings\": 1")) << r.out;
  EXPECT_TRUE(has(r.out, "\"severity\": \"warning\"")) << r.out;
  EXPECT_TRUE(has(r.out, "\"line\": 0, \"column\": 0")) << r.out;
}

}  // namespace
