// POV-Ray light_source as the import builds it: spotlight and cylinder cones, parallel,
// shadowless, fading and area lights (with their transformations).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "load/pov_loader.h"
#include "render/integrator.h"

namespace raycast {
namespace {

Light light(const std::string& text) {
  std::vector<std::string> warnings;
  const Scene s = load_pov_scene_text("sphere { 0, 1 }\n" + text, "t.pov", ".", -1, {}, &warnings);
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return s.lights.empty() ? Light{} : s.lights[0];
}

TEST(PovLightImport, Spotlight_CosineEdgeAndTightness) {
  const Light l = light(
      "light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 20 falloff 40 tightness 3 }");
  EXPECT_EQ(l.type, LightType::kSpot);
  EXPECT_EQ(l.angle, 40);
  EXPECT_EQ(l.falloff, 20);
  EXPECT_EQ(l.tightness, 3);
  EXPECT_EQ(l.edge, SpotEdge::kCosine);
  EXPECT_EQ(l.direction, (Vec3{0, -1, 0}));
}

TEST(PovLightImport, Cylinder_DefaultsAreDistances) {
  const Light l = light("light_source { <0, 5, 0> rgb 1 cylinder point_at 0 }");
  EXPECT_EQ(l.type, LightType::kCylinder);
  EXPECT_EQ(l.angle, 1);       // falloff 1
  EXPECT_EQ(l.falloff, 0.25);  // minus radius 0.75
}

TEST(PovLightImport, ParallelShadowlessAndFade) {
  const Light p = light("light_source { <0, 5, 0> rgb 1 parallel point_at <0, 0, 0> }");
  EXPECT_EQ(p.type, LightType::kDirectional);
  EXPECT_TRUE(p.bounded);
  EXPECT_EQ(p.position, (Vec3{0, 5, 0}));
  EXPECT_EQ(p.direction, (Vec3{0, -1, 0}));
  const Light s = light("light_source { <1, 2, 3> rgb 1 shadowless fade_distance 4 fade_power 2 }");
  EXPECT_FALSE(s.shadows);
  EXPECT_EQ(s.attenuation, Attenuation::kFade);
  EXPECT_EQ(s.fade_distance, 4);
  EXPECT_EQ(s.fade_power, 2);
}

TEST(PovLightImport, AreaLight_GridAxesTurnedWithTheLight) {
  const Light l = light(
      "light_source { <0, 5, 0> rgb 1 area_light <2, 0, 0>, <0, 0, 4>, 3, 5 adaptive 1 jitter "
      "circular orient rotate 90 * y }");
  EXPECT_EQ(l.type, LightType::kArea);
  EXPECT_EQ(l.size1, 3);
  EXPECT_EQ(l.size2, 5);
  EXPECT_TRUE(l.jitter && l.circular && l.orient);
  EXPECT_EQ(l.adaptive, 1);
  EXPECT_FALSE(l.spot);
  // rotate 90 about y turns x to -z (POV-Ray's), mirrored to +z in raycast's frame.
  EXPECT_NEAR(l.axis1.x, 0, 1e-12);
  EXPECT_NEAR(l.axis1.z, 2, 1e-12);
  EXPECT_NEAR(l.axis2.x, 4, 1e-12);
  const Light spot =
      light("light_source { <0, 5, 0> rgb 1 spotlight point_at 0 area_light x, z, 2, 2 }");
  EXPECT_EQ(spot.type, LightType::kArea);
  EXPECT_EQ(spot.adaptive, -1);  // absent: every grid point sampled
  EXPECT_TRUE(spot.spot);
  EXPECT_EQ(spot.angle, 45);  // POV-Ray's default falloff
}

// The light reaching the floor's origin under a light at <0, 5, 0>, past `blocker` (which stands
// over the origin), seen from the side.
double floor_light(const std::string& blocker) {
  const Scene s =
      load_pov_scene_text("plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" +
                              blocker + "\nlight_source { <0, 5, 0> rgb 1 }",
                          "t.pov", ".");
  const Integrator integrator(s, RenderMode::kWhitted);
  SampleState state{Rng(1), 0};
  return integrator.li({{8, 8, 0}, normalize(Vec3{-1, -1, 0}), 0, kInfinity}, state).x;
}

TEST(PovLightImport, NoShadow_ObjectsAndTheirUnionsCastNone) {
  EXPECT_EQ(floor_light("sphere { <0, 2, 0>, 1 }"), 0);
  EXPECT_NEAR(floor_light("sphere { <0, 2, 0>, 1 no_shadow }"), 1, 1e-12);
  EXPECT_NEAR(floor_light("union { sphere { <0, 2, 0>, 1 } box { -0.5, 0.5 translate 3 * y } "
                          "no_shadow }"),
              1, 1e-12);
  EXPECT_EQ(
      floor_light("union { sphere { <0, 2, 0>, 1 no_shadow } box { -0.5, 0.5 translate 3 * y } }"),
      0);
}

}  // namespace
}  // namespace raycast
