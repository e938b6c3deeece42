// sky_sphere and fog read from POV-Ray scenes: the blocks as written (declared, layered,
// transformed), and the rendered pixel against POV-Ray 3.7's own for the same 1x1 scene
// (rendered once with `povray +W1 +H1 -GA File_Gamma=1.0 +FP16`; POV-Ray is not needed to run
// these tests).
#include <gtest/gtest.h>

#include <string>

#include "io/scene_error.h"
#include "load/pov_loader.h"
#include "pov/interpreter.h"
#include "render/renderer.h"

namespace raycast {
namespace {

pov::PovScene interpret(const std::string& text) {
  pov::Options o;
  o.system_library_path = false;
  return pov::interpret_pov(text, "t.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes", o);
}

Vec3 pixel(const std::string& text) {
  const Scene s = load_pov_scene_text(text, "t.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes");
  RenderOptions o;
  o.width = 1;
  o.height = 1;
  o.spp = 1;
  o.progress = false;
  const Vec3f c = render(s, o).at(0, 0);
  return {c.x, c.y, c.z};
}

void expect_color(const Vec3& got, const Vec3& want, double tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

TEST(PovAtmosphere, SkySphereDeclaredLayeredAndMoved) {
  const pov::PovScene s = interpret(R"(
#declare Sky = sky_sphere { pigment { rgb <0, 0, 1> } rotate 30*y }
sky_sphere { Sky pigment { bozo color_map { [0 rgbt 1] [1 rgb 1] } } emission 2 }
)");
  ASSERT_TRUE(s.sky_sphere);
  ASSERT_EQ(s.sky_sphere->pigments.size(), 2u);
  EXPECT_EQ(s.sky_sphere->pigments[0].color.rgb.z, 1);
  EXPECT_EQ(s.sky_sphere->pigments[1].kind, texture::Pigment::Kind::kColorMap);
  EXPECT_EQ(s.sky_sphere->emission.g, 2);
  ASSERT_EQ(s.sky_sphere->xforms.size(), 1u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(PovAtmosphere, FogItems) {
  const pov::PovScene s = interpret(R"(
#declare F = fog { fog_type 2 distance 5 fog_offset 1 fog_alt 2 }
fog { F colour rgbft <0.3, 0.5, 0.2, 0.4, 0.1> turbulence 0.2 octaves 3 omega 0.4 lambda 3
      turb_depth 0.3 up <0, 0, 2> rotate 10*x }
fog { distance 0 color rgb 1 }  // POV-Ray's "fog is off"
)");
  ASSERT_EQ(s.fogs.size(), 1u);
  const pov::Fog& f = s.fogs[0];
  EXPECT_EQ(f.type, 2);
  EXPECT_EQ(f.distance, 5);
  EXPECT_EQ(f.offset, 1);
  EXPECT_EQ(f.alt, 2);
  EXPECT_EQ(f.colour.filter, 0.4);
  EXPECT_EQ(f.colour.transmit, 0.1);
  EXPECT_EQ(f.turbulence.amount.y, 0.2);
  EXPECT_EQ(f.turbulence.octaves, 3);
  EXPECT_EQ(f.turbulence.omega, 0.4);
  EXPECT_EQ(f.turbulence.lambda, 3);
  EXPECT_EQ(f.turb_depth, 0.3);
  EXPECT_EQ(f.up.z, 2);
  EXPECT_EQ(f.xforms.size(), 1u);
  EXPECT_THROW(interpret("fog { fog_type 3 distance 1 }"), SceneError);
}

const char* const kHeader = R"(#version 3.7;
global_settings { assumed_gamma 1 }
background { rgb <0.8, 0.8, 0.8> }
)";

TEST(PovAtmosphere, SkyPixelsAsPovRay) {
  // POV-Ray: 0.1464 0 0.4268 (gradient sky 45 degrees up, emission halving blue).
  expect_color(pixel(std::string(kHeader) + R"(
camera { location 0 direction z look_at <0, 1, 1> }
sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }
                       scale 2 translate -1 } emission <1, 1, 0.5> }
)"),
               {0.1464, 0, 0.4268}, 2e-4);
  // POV-Ray: 0.6250 0.4250 0.1750 (two layers and the background through them).
  expect_color(pixel(std::string(kHeader) + R"(
camera { location 0 direction z look_at z }
sky_sphere { pigment { rgbt <0.2, 0.4, 0.6, 0.5> } pigment { rgbft <1, 0.5, 0, 0.5, 0.25> } }
)"),
               {0.625, 0.425, 0.175}, 2e-4);
}

TEST(PovAtmosphere, FogPixelsAsPovRay) {
  const std::string glow =
      "sphere { <0, 5, 10>, 1 pigment { rgb <0.2, 0.6, 1> } finish { ambient 1 diffuse 0 } }\n";
  const std::string camera = "camera { location 0 direction z look_at <0, 5, 10> }\n";
  // Ground fog over a rising segment that hits (POV-Ray: 0.3804 0.2392 0.8196) and that misses
  // (0.4046 0.2137 0.7863).
  const std::string ground =
      "fog { fog_type 2 colour rgb <0.4, 0.2, 0.8> distance 3 fog_offset 1 fog_alt 2 }\n";
  const std::string grey = "background { rgb 0.5 }\n";
  expect_color(pixel(std::string(kHeader) + grey + camera + ground + glow),
               {0.3804, 0.2392, 0.8196}, 2e-4);
  expect_color(pixel(std::string(kHeader) + grey + camera + ground), {0.4046, 0.2137, 0.7863},
               2e-4);
  // Two constant fogs, one filtering, one with a minimum translucency (POV-Ray: 0.6382 0.5609
  // 0.7459).
  expect_color(pixel(std::string(kHeader) + grey + "camera { location 0 direction z look_at z }\n" +
                     "fog { colour rgbft <0.4, 0.2, 0.8, 0.5, 0> distance 10 }\n"
                     "fog { colour rgbft <0.9, 0.9, 0.1, 0, 0.2> distance 20 }\n"
                     "sphere { <0, 0, 11>, 1 pigment { rgb <0.2, 0.6, 1> } "
                     "finish { ambient 1 diffuse 0 } }\n"),
               {0.6382, 0.5609, 0.7459}, 2e-4);
}

TEST(PovAtmosphere, RainbowPixelsAsPovRay) {
  const std::string rainbow =
      "rainbow { angle 42.5 width 10 direction z arc_angle 120 falloff_angle 60 "
      "color_map { [0 rgbft <1, 0, 0, 0.2, 0.3>] [1 rgbft <0, 0, 1, 0.2, 0.3>] } }\n";
  const std::string white = "background { rgb 1 }\n";
  // POV-Ray: 0.6291 0.2580 0.6289 at the ring's top.
  expect_color(pixel(std::string(kHeader) + white +
                     "camera { location 0 direction z look_at <0, 0.9163, 1> }\n" + rainbow),
               {0.6291, 0.2580, 0.6289}, 5e-4);
  // 90 degrees around from up, outside the 120 degree arc: the background.
  expect_color(pixel(std::string(kHeader) + white +
                     "camera { location 0 direction z look_at <0.9163, 0, 1> }\n" + rainbow),
               {1, 1, 1}, 1e-6);
}

}  // namespace
}  // namespace raycast
