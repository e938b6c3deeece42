// Loading the quadric family and the planar solids: every shape of scenes/quadrics.yaml loads,
// and bad input is a SceneError at the offending field.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

// The position and message of the error that loading `yaml` throws.
struct Failure {
  int line = 0, column = 0;
  std::string message;
};
Failure load_error(const std::string& yaml) {
  try {
    load_scene_text(yaml, "s.yaml");
  } catch (const SceneError& e) {
    return {e.line(), e.column(), e.message()};
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return {};
}

TEST(QuadricParse, ExampleScene_LoadsEveryShape) {
  const Scene s = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/scenes/quadrics.yaml");
  EXPECT_EQ(s.objects.size(), 11u);
}

TEST(QuadricParse, AllForms_Load) {
  const Scene s = load_scene_text(R"(objects:
  - ellipsoid: {radii: [1, 2, 3]}
  - quadric: {coefficients: [1, 1, -1, 0, 0, 0, 0, 0, 0, 0]}
  - quadric: {matrix: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, -0.5], [0, 0, -0.5, 0]], bounds: {min: [-1, -1, 0], max: [1, 1, 1]}}
  - quadric: {kind: hyperboloid2, a: 2, c: 3, open: true, bounds: {min: [-5, -5, -5], max: [5, 5, 5]}}
  - cylinder: {radius: 1, z_min: 0, z_max: 2, phi_max: 120, capped: false}
  - cylinder: {from: [0, 0, 0], to: [1, 1, 1], radius: 0.2}
  - cone: {radius: 1, height: 2, phi_max: 270}
  - cone: {from: [0, 0, 0], to: [0, 1, 0], radius_from: 1, radius_to: 0.5, capped: false}
  - polygon: {vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.5, 0.2, 0], [0, 1, 0]]}
  - slab: {normal: [1, 1, 0], offsets: [-1, 1]}
  - polyhedron: {planes: [[1, 0, 0, -1], [-1, 0, 0, -1], [0, 1, 0, -1], [0, -1, 0, -1], [0, 0, 1, -1], [0, 0, -1, -1]]}
)");
  EXPECT_EQ(s.objects.size(), 11u);
}

TEST(QuadricParse, NonPlanarPolygon_IsAnErrorAtTheVertex) {
  const Failure f = load_error(R"(objects:
  - polygon:
      vertices:
        - [0, 0, 0]
        - [1, 0, 0]
        - [1, 1, 0.5]
        - [0, 1, 0]
)");
  // The best-fit plane spreads a twist over all four vertices: any of them may be named.
  EXPECT_GE(f.line, 4) << f.message;
  EXPECT_LE(f.line, 7) << f.message;
  EXPECT_NE(f.message.find("polygon.vertices["), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("planar"), std::string::npos) << f.message;
}

TEST(QuadricParse, TwoVertexPolygonAndZeroArea_AreErrors) {
  Failure f = load_error("objects:\n  - polygon: {vertices: [[0, 0, 0], [1, 0, 0]]}\n");
  EXPECT_EQ(f.line, 2);
  EXPECT_NE(f.message.find("at least 3"), std::string::npos) << f.message;
  f = load_error("objects:\n  - polygon: {vertices: [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}\n");
  EXPECT_NE(f.message.find("zero area"), std::string::npos) << f.message;
}

TEST(QuadricParse, EmptyPolyhedron_IsAnError) {
  const Failure f =
      load_error("objects:\n  - polyhedron: {planes: [[0, 0, 1, -1], [0, 0, -1, 2]]}\n");
  EXPECT_EQ(f.line, 2);
  EXPECT_NE(f.message.find("empty"), std::string::npos) << f.message;
}

TEST(QuadricParse, BadFields_AreErrorsAtTheirPosition) {
  Failure f = load_error("objects:\n  - quadric: {kind: torus}\n");
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.column, 21);
  EXPECT_NE(f.message.find("quadric.kind"), std::string::npos) << f.message;
  f = load_error(
      "objects:\n  - quadric: {kind: cone, coefficients: [1, 1, 1, 0, 0, 0, 0, 0, 0, 0]}\n");
  EXPECT_NE(f.message.find("exactly one"), std::string::npos) << f.message;
  f = load_error(
      "objects:\n  - quadric: {matrix: [[1, 2, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "
      "-1]]}\n");
  EXPECT_NE(f.message.find("symmetric"), std::string::npos) << f.message;
  f = load_error("objects:\n  - quadric: {coefficients: [1, 1, 1, 0, 0, 0, 0, 0, 0]}\n");
  EXPECT_NE(f.message.find("10 numbers"), std::string::npos) << f.message;
  f = load_error("objects:\n  - quadric: {kind: cone, bounds: {min: [0, 0, 0], max: [1, 0, 1]}}\n");
  EXPECT_NE(f.message.find("bounds"), std::string::npos) << f.message;
  f = load_error("objects:\n  - slab: {normal: [0, 0, 1], offsets: [1, 0]}\n");
  EXPECT_NE(f.message.find("d0 < d1"), std::string::npos) << f.message;
  f = load_error("objects:\n  - cylinder: {radius: 1, phi_max: 400}\n");
  EXPECT_NE(f.message.find("phi_max"), std::string::npos) << f.message;
  f = load_error("objects:\n  - cylinder: {from: [0, 0, 0], to: [0, 0, 1], radius: 1, z_min: 0}\n");
  EXPECT_NE(f.message.find("z_min"), std::string::npos) << f.message;  // not a field of this form
  f = load_error("objects:\n  - cone: {from: [0, 0, 0], to: [0, 0, 1]}\n");
  EXPECT_NE(f.message.find("radius_from"), std::string::npos) << f.message;
  f = load_error("objects:\n  - ellipsoid: {radii: [1, .nan, 1]}\n");
  EXPECT_EQ(f.line, 2);
  f = load_error("objects:\n  - ellipsoid: {radii: [1, 0, 1]}\n");
  EXPECT_NE(f.message.find("radii"), std::string::npos) << f.message;
}

}  // namespace
}  // namespace raycast
