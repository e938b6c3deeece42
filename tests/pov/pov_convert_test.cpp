// Every construct of the POV-Ray subset converts, loads and renders where it should: the depth
// of the centre pixel (a ray along the camera's axis) against the exact distance, under a
// left-handed POV-Ray camera (the import mirrors z) and a right-handed one (coordinates copied).
// Then: `convert` writes YAML that renders identical to the .pov, and loader errors point into
// the .pov file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "../support/cli_runner.h"
#include "io/scene_error.h"
#include "load/loader.h"
#include "load/pov_loader.h"
#include "render/renderer.h"

namespace raycast {
namespace {

constexpr int kW = 33, kH = 25;  // odd: the centre pixel's ray is the camera's axis

// The camera at the origin looking along +z (POV-Ray's default view), left- or right-handed.
std::string camera(bool right_handed) {
  return right_handed ? "camera { location 0 look_at z right -x * 4 / 3 }\n"
                      : "camera { location 0 look_at z }\n";
}

Image render_depth(const std::string& pov) {
  const Scene s = load_pov_scene_text(pov, "t.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes");
  RenderOptions o;
  o.width = kW;
  o.height = kH;
  o.spp = 1;
  o.integrator = RenderMode::kDepth;
  o.progress = false;
  return render(s, o);
}

struct Case {
  const char* name;
  const char* object;
  double depth;  // of the centre pixel
};

const Case kCases[] = {
    {"sphere", "sphere { <0, 0, 3>, 1 }", 2},
    {"box", "box { <1, 1, 4>, <-1, -1, 2> }", 2},
    {"plane", "plane { z, 3 }", 3},
    {"plane_behind_normal", "plane { -z, -3 }", 3},
    {"plane_distance_along_unit_normal", "plane { <0, 0, 2>, 3 }", 3},
    {"cylinder", "cylinder { <0, -1, 3>, <0, 1, 3>, 0.5 }", 2.5},
    {"cone", "cone { <0, -1, 3>, 1, <0, 1, 3>, 0 }", 2.5},
    {"disc", "disc { <0, 0, 3>, z, 1, 0.2 }", std::numeric_limits<double>::infinity()},
    {"disc_whole", "disc { <0, 0, 3>, -z, 1 }", 3},
    {"torus", "torus { 1, 0.25 translate <1, 0, 3> }", 2.25},
    {"quadric", "quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, -6>, 8 }", 2},  // |p - (0,0,3)| = 1
    {"poly", "intersection { poly { 2, <1,0,0,0,1,0,0,1,0,-1> } box { -2, 2 } translate 3*z }", 2},
    {"quartic_torus",
     "intersection { quartic { <1,0,0,0,2,0,0,2,0,-2.125, 0,0,0,0,0,0,0,0,0,0, "
     "1,0,0,2,0,1.875,0,0,0,0, 1,0,-2.125,0,0.87890625> } box { <-2,-1,-2>, <2,1,2> } "
     "translate <1, 0, 3> }",
     2.25},
    {"isosurface",
     "isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } "
     "translate 3*z }",
     2},
    {"isosurface_in_sphere",
     "isosurface { function { z + 0.5 } contained_by { sphere { 0, 1 } } translate 3*z }", 2},
    {"isosurface_threshold",
     "isosurface { function { sqrt(x*x + y*y + pow(z, 2)) } threshold 1.5 max_gradient 2 "
     "contained_by { box { -2, 2 } } translate 4*z }",
     2.5},
    {"lathe", "lathe { 4, <0, -1>, <1, -1>, <1, 1>, <0, 1> translate 3*z }", 2},
    // A radius below 0 draws as |r| (POV-Ray meets x^2 + z^2 = r^2).
    {"lathe_negative_radius", "lathe { 4, <0, -1>, <-1, -1>, <-1, 1>, <0, 1> translate 3*z }", 2},
    {"lathe_crossing_the_axis", "lathe { 3, <0.5, -1>, <-1.5, 1>, <0, 1> translate 3*z }", 2.5},
    {"lathe_bezier", "lathe { bezier_spline 4, <0, -1>, <1, -1>, <1, 1>, <0, 1> translate 3*z }",
     2.25},
    {"sor", "sor { 4, <1, -2>, <1, -1>, <1, 1>, <1, 2> translate 3*z }", 2},
    // The contour's second coordinate is z: mirrored the wrong way the prism would be behind.
    {"prism", "prism { -1, 1, 4, <-1, 3>, <1, 3>, <0, 6>, <-1, 3> }", 3},
    // From <-1, 3> to <1, 3> after the control point <0, 5>: q(s) = (-1 + s / 2 + 3 s^2 / 2,
    // 3 - s + s^2) meets x = 0 at s = 2/3, z = 25/9.
    {"prism_quadratic",
     "prism { quadratic_spline -1, 1, 5, <0, 5>, <-1, 3>, <1, 3>, <0, 5>, <-1, 3> }", 25.0 / 9},
    // The square swept to the apex, turned so the apex is at z = 3 and the base cap at z = 2.
    {"prism_conic",
     "prism { conic_sweep linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> "
     "rotate -90*x translate 3*z }",
     2},
    // timrom.ttf from the library path: the I's stem is about x in [0.12, 0.22] around 0.171,
    // its front face at z = 0 (the letters run from z = 0 to the thickness).
    {"text", "text { ttf \"timrom.ttf\", \"I\", 1, 0 translate <-0.171, -0.34, 3> }", 3},
    {"text_between_letters", "text { ttf \"timrom.ttf\" \"II\" 1, 0 translate <-0.4, -0.34, 3> }",
     std::numeric_limits<double>::infinity()},
    // A lone component's surface: 2 (1 - r^2 / 4)^2 = 1, r = 2 sqrt(1 - sqrt(1 / 2)).
    {"blob", "blob { threshold 1 sphere { <0, 0, 4>, 2, 2 } }", 2.9176077997},
    {"blob_old_component_syntax", "blob { component 2, 2, <0, 0, 4> }", 2.9176077997},
    {"blob_cylinder", "blob { cylinder { <0, -1, 4>, <0, 1, 4>, 2, strength 2 } sturm }",
     2.9176077997},
    {"blob_scaled_component",
     "blob { threshold 1 sphere { 0, 2, 2 scale <1, 1, 2> } hierarchy off translate 4*z }",
     1.8352155994},
    {"mesh", "mesh { triangle { <-1, -1, 3>, <1, -1, 3>, <0, 1, 3> } }", 3},
    {"triangle", "triangle { <-1, -1, 2>, <1, -1, 4>, <0, 1, 3> }", 3},
    {"smooth_triangle",
     "smooth_triangle { <-1, -1, 3>, <0, 0, -1>, <1, -1, 3>, z, <0, 1, 3>, x translate z }", 4},
    {"mesh_smooth", "mesh { smooth_triangle { <-1, -1, 3>, -z, <1, -1, 3>, -z, <0, 1, 3>, -z } }",
     3},
    {"mesh2",
     "mesh2 { vertex_vectors { 3, <-1, -1, 3>, <1, -1, 3>, <0, 1, 3> } "
     "face_indices { 1, <0, 1, 2> } }",
     3},
    {"mesh2_trailing_commas",
     "mesh2 { vertex_vectors { 3 <-1, -1, 3>, <1, -1, 3>, <0, 1, 3>, } "
     "face_indices { 1, <0, 1, 2>, } }",
     3},
    {"union", "union { sphere { <0, 0, 3>, 1 } sphere { <0, 0, 3.5>, 1 } }", 2},
    // A declared object's name alone stands for object { Name } (in CSG and as a scene item).
    {"bare_declared_object",
     "#declare S = sphere { <0, 0, 3>, 1 }\n#declare B = box { -1, 1 translate 4 * z }\n"
     "union { S B }\nB",
     2},
    {"merge", "merge { sphere { <0, 0, 3>, 1 } sphere { <0, 0, 3.5>, 1 } }", 2},
    {"intersection", "intersection { sphere { <0, 0, 3>, 1 } sphere { <0, 0, 3.5>, 1 } }", 2.5},
    {"difference", "difference { sphere { <0, 0, 3>, 1 } box { <-2, -2, 0>, <2, 2, 2.5> } }", 2.5},
    {"declared_object", "#declare S = sphere { 0, 1 }\nobject { S translate 3*z }", 2},
    {"declared_csg",
     "#declare S = difference { sphere { 0, 1 } sphere { <0, 0, -1>, 0.5 } }\n"
     "object { S translate 3*z }",
     2.5},
    {"scale_translate", "sphere { 0, 1 scale 2 translate 5*z }", 3},
    // POV-Ray's rotate -90 about y takes +x to +z: the box [0, 1] in x spans z in [3, 4].
    {"rotate", "box { <0, -0.5, -0.5>, <1, 0.5, 0.5> rotate -90*y translate 3*z }", 3},
    {"rotate_x", "box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> rotate 90*x translate 3*z }", 3},
    {"matrix", "box { <0, -0.5, -0.5>, <1, 0.5, 0.5> matrix <0,0,1, 0,1,0, -1,0,0, 0,0,3> }", 3},
    {"include", "#include \"pyramid.inc\"\nobject { Pyramid rotate 90*x translate 3*z }", 3},
};

class PovConstruct : public ::testing::TestWithParam<std::tuple<Case, bool>> {};

TEST_P(PovConstruct, CentreDepthIsExact) {
  const auto& [c, right_handed] = GetParam();
  const std::string pov = camera(right_handed) + "light_source { <0, 5, -5> rgb 1 }\n" + c.object;
  const Image img = render_depth(pov);
  const double d = img.at(kW / 2, kH / 2).x;
  if (std::isinf(c.depth)) {
    EXPECT_TRUE(std::isinf(d)) << d;
  } else {
    EXPECT_NEAR(d, c.depth, 1e-5) << pov;
  }
}

INSTANTIATE_TEST_SUITE_P(Subset, PovConstruct,
                         ::testing::Combine(::testing::ValuesIn(kCases), ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param).name) +
                                  (std::get<1>(info.param) ? "_right_handed" : "_left_handed");
                         });

// +x is on the right of POV-Ray's default (left-handed) image and on the left under right -x.
TEST(PovImport, HandednessKeepsPovRaysPicture) {
  const std::string object = "sphere { <1.2, 0, 5>, 0.5 }";
  for (bool right_handed : {false, true}) {
    const Image img = render_depth(camera(right_handed) + object);
    const int near = right_handed ? kW / 2 - 5 : kW / 2 + 5;
    const int far = right_handed ? kW / 2 + 5 : kW / 2 - 5;
    EXPECT_TRUE(std::isfinite(img.at(near, kH / 2).x)) << right_handed;
    EXPECT_TRUE(std::isinf(img.at(far, kH / 2).x)) << right_handed;
  }
  // +y is up in both.
  const Image img = render_depth(camera(false) + "sphere { <0, 1.2, 5>, 0.5 }");
  EXPECT_TRUE(std::isfinite(img.at(kW / 2, kH / 2 - 5).x));
  EXPECT_TRUE(std::isinf(img.at(kW / 2, kH / 2 + 5).x));
}

TEST(PovImport, CameraAngleIsHorizontal) {
  // angle 90 with POV-Ray's default right (1.33): direction's length becomes 0.665, so the
  // vertical field of view is 2 atan(0.5 / 0.665).
  const Scene s = load_pov_scene_text("camera { location 0 look_at z angle 90 }\nsphere { 0, 1 }",
                                      "t.pov", ".");
  ASSERT_TRUE(s.camera);
  ASSERT_EQ(s.camera->type, CameraType::kPerspective);
  EXPECT_NEAR(s.camera->fov, 2 * std::atan(0.5 / 0.665) * 180 / 3.14159265358979323846, 1e-9);
}

// `raycast convert` output loads and renders to the same pixels as the .pov itself.
class PovConvertRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(PovConvertRoundTrip, ConvertedYamlRendersIdentically) {
  const std::string dir = RAYCAST_SOURCE_DIR "/tests/pov/scenes";
  const std::string path = dir + "/" + GetParam() + ".pov";
  RenderOptions o;
  o.width = 40;
  o.height = 30;
  o.spp = 1;
  o.progress = false;
  const Image direct = render(load_scene_file(path), o);
  const Image converted = render(load_scene_text(convert_pov_file(path), "c.yaml", dir), o);
  EXPECT_EQ(direct.rgb, converted.rgb);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovConvertRoundTrip,
                         ::testing::Values("basic", "csg", "surfaces", "glass", "transmit", "lens",
                                           "blob"));

TEST(PovImport, DegenerateShapesAreLeftOutWithTheirPosition) {
  // POV-Ray draws nothing for a sphere of negative radius; raycast says so and goes on.
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text("camera { location <0, 0, -5> }\n\n  sphere { 0, -1 }",
                                      "t.pov", ".", -1, {}, &warnings);
  EXPECT_TRUE(s.objects.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("t.pov:3:3: warning: raycast does not render degenerate shapes", 0),
            0u)
      << warnings[0];
  EXPECT_NE(warnings[0].find("radius"), std::string::npos) << warnings[0];
}

TEST(PovImport, OpenSurfacesInCsgAreAWarningOrAnErrorWhenStrict) {
  const std::string text = "difference {\n  sphere { 0, 1 }\n  disc { 0, y, 2 }\n}";
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text(text, "t.pov", ".", -1, {}, &warnings);
  EXPECT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(
      warnings[0].rfind("t.pov:3:3: warning: raycast does not render open surfaces in CSG", 0), 0u)
      << warnings[0];
  pov::Options strict;
  strict.strict = true;
  try {
    load_pov_scene_text(text, "t.pov", ".", -1, strict);
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_NE(e.message().find("open surfaces in CSG"), std::string::npos) << e.what();
  }
}

TEST(PovImport, MaterialsMapFinishAndPigment) {
  const Scene s = load_pov_scene_text(
      "global_settings { max_trace_level 7 ambient_light rgb 0.5 }\n"
      "background { rgb <0.1, 0.2, 0.3> }\n"
      "sphere { 0, 1 pigment { rgbf <1, 0.5, 0.25, 0.6> } finish { ambient 0.3 diffuse 0.4 "
      "phong 0.7 phong_size 20 reflection 0.25 } interior { ior 1.33 } }\n"
      "sphere { 0, 1 pigment { rgbt <1, 1, 1, 0.9> } finish { specular 0.5 roughness 0.025 "
      "reflection { 0, 1 fresnel on } } }\n"
      "sphere { 0, 1 }",
      "t.pov", ".");
  EXPECT_EQ(s.render.max_depth, 6);
  EXPECT_EQ(s.render.ambient.x, 0.5);
  EXPECT_EQ(s.render.background.z, 0.3);
  const Material& a = s.materials[static_cast<std::size_t>(s.objects[0].material)];
  EXPECT_EQ(a.color.y, 0.5);
  EXPECT_DOUBLE_EQ(a.ambient, 0.3 * (1 - 0.6));  // weighed by the opacity, as POV-Ray does
  EXPECT_DOUBLE_EQ(a.diffuse, 0.4 * (1 - 0.6));
  EXPECT_EQ(a.specular, 0.7);
  EXPECT_EQ(a.shininess, 20);
  EXPECT_EQ(a.reflection, 0.25);
  EXPECT_EQ(a.transmission, 0.6);
  EXPECT_EQ(a.ior, 1.33);
  const Material& b = s.materials[static_cast<std::size_t>(s.objects[1].material)];
  EXPECT_TRUE(b.fresnel);
  EXPECT_EQ(b.transmission, 0.9);
  EXPECT_EQ(b.specular, 0.5);
  EXPECT_EQ(b.shininess, 10);  // Blinn's 1/roughness = 40, a quarter as a Phong exponent
  const Material& c = s.materials[static_cast<std::size_t>(s.objects[2].material)];
  EXPECT_EQ(c.color.x, 0);  // POV-Ray's default texture: black, ambient 0.1, diffuse 0.6
  EXPECT_EQ(c.ambient, 0.1);
  EXPECT_EQ(c.diffuse, 0.6);
}

TEST(PovImport, LightsMap) {
  const Scene s = load_pov_scene_text(
      "light_source { <1, 2, 3> color rgb <1, 0.5, 0.25> }\n"
      "light_source { <0, 5, 0> rgb 1 spotlight point_at <0, 0, 1> radius 10 falloff 25 }\n"
      "light_source { <0, 5, 0> rgb 1 area_light <2, 0, 0>, <0, 0, 1>, 3, 4 adaptive 1 jitter }\n"
      "sphere { 0, 1 }",
      "t.pov", ".");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].position.z, -3);  // the default camera is left-handed: z is negated
  EXPECT_EQ(s.lights[0].color.y, 0.5);
  EXPECT_EQ(s.lights[1].type, LightType::kSpot);
  EXPECT_EQ(s.lights[2].type, LightType::kArea);  // POV-Ray's grid of 3 x 4 points
  EXPECT_EQ(s.lights[2].size1 * s.lights[2].size2, 12);
  EXPECT_EQ(s.lights[2].adaptive, 1);
}

TEST(PovImport, CliConvertAndRender) {
  const std::string scene = RAYCAST_SOURCE_DIR "/tests/pov/scenes/basic.pov";
  const std::string yaml = (test::temp_dir() / "basic.yaml").string();
  const auto c = test::run("convert '" + scene + "' -o '" + yaml + "'");
  EXPECT_EQ(c.code, 0) << c.err;
  const auto r = test::run("render '" + yaml + "' -o '" + (test::temp_dir() / "b.png").string() +
                           "' --width 16 --height 12");
  EXPECT_EQ(r.code, 0) << r.err;
  const auto info = test::run("info '" + scene + "'");
  EXPECT_EQ(info.code, 0) << info.err;
  const std::string bad = test::write("bad.pov", "sphere { 0, 1 }\nsphere { 0, 1 invert }\n");
  const auto b = test::run("convert '" + bad + "'");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("bad.pov:2:15: unknown word 'invert'"), std::string::npos) << b.err;
  // -D declares before the scene (and stops at the SCENE); --library-path finds includes.
  const std::string inc_dir = (test::temp_dir() / "incs").string();
  std::filesystem::create_directories(inc_dir);
  test::write("incs/r.inc", "#declare R = 2;\n");
  const std::string uses = test::write("uses.pov", "#include \"r.inc\"\nsphere { 0, R * Q }\n");
  const auto d = test::run("render -D Q=0.5 --library-path '" + inc_dir + "' '" + uses + "' -o '" +
                           (test::temp_dir() / "d.png").string() + "' --width 8 --height 6");
  EXPECT_EQ(d.code, 0) << d.err;
  const std::string warned = test::write("warned.pov", "sphere { 0, 1 pigment { mandel 25 } }\n");
  const auto w = test::run("render '" + warned + "' --strict -o '" +
                           (test::temp_dir() / "w.png").string() + "' --width 8 --height 6");
  EXPECT_EQ(w.code, 2);
  EXPECT_NE(w.err.find("warned.pov:1:25: raycast does not render the mandel pattern"),
            std::string::npos)
      << w.err;
  const auto v =
      test::run("render '" + bad + "' -o '" + (test::temp_dir() / "x.png").string() + "'");
  EXPECT_EQ(v.code, 2);
}

}  // namespace
}  // namespace raycast
