// The lights POV-Ray has: area lights as a grid of shadow rays shaded towards the centre,
// shadowless lights, parallel lights bounded by their plane, cylinder lights, fading, spot cones
// with a cosine edge and tightness. Each case: the light reaching one point of a white floor
// (diffuse 1, no ambient, no highlight), against its exact value.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "load/loader.h"
#include "render/integrator.h"
#include "render/light_falloff.h"

namespace raycast {
namespace {

// The floor y = 0 and, optionally, a blocking sphere; the light(s) as YAML list items.
Scene scene(const std::string& lights, const std::string& blocker = "") {
  return load_scene_text(
      "materials:\n  white: {color: [1, 1, 1], ambient: 0, diffuse: 1, specular: 0}\n"
      "lights:\n" +
      lights + "objects:\n  - {plane: {normal: [0, 1, 0], point: [0, 0, 0]}, material: white}\n" +
      (blocker.empty() ? "" : "  - {sphere: " + blocker + ", material: white}\n"));
}

// The red channel seen at the floor point (x, 0, z), looking down at 45 degrees from +x (past
// the blockers, which stand above the origin).
double floor_light(const Scene& s, double x, double z) {
  const Integrator integrator(s, RenderMode::kWhitted);
  SampleState state{Rng(7), 0};
  return integrator.li({{x + 8, 8, z}, normalize(Vec3{-1, -1, 0}), 0, kInfinity}, state).x;
}

TEST(PovLights, AreaLight_EachGridPointCarriesItsShare_ShadedTowardsTheCentre) {
  const std::string area =
      "  - {type: area, position: [0, 5, 0], axis1: [4, 0, 0], axis2: [0, 0, 4], size1: 2, "
      "size2: 2}\n";
  EXPECT_NEAR(floor_light(scene(area), 0, 0), 1, 1e-12);
  // A small sphere on the way to the corner (2, 5, 2) only: three quarters of the light.
  EXPECT_NEAR(floor_light(scene(area, "{center: [1, 2.5, 1], radius: 0.3}"), 0, 0), 0.75, 1e-12);
  // Off the centre the light comes from the centre's direction (POV-Ray: the grid is for shadows).
  EXPECT_NEAR(floor_light(scene(area), 1, 0), 5 / std::sqrt(26.0), 1e-12);
}

TEST(PovLights, AreaLightPoints_GridCircularAndOrient) {
  Light l;
  l.type = LightType::kArea;
  l.position = {0, 5, 0};
  l.axis1 = {4, 0, 0};
  l.axis2 = {0, 0, 2};
  l.size1 = 3;
  l.size2 = 1;
  Rng rng(1);
  std::vector<Vec3> points;
  area_light_points(l, {0, 0, 0}, rng, [&](const Vec3& p) { points.push_back(p); });
  ASSERT_EQ(points.size(), 3u);  // one column: the centre line along axis1
  EXPECT_EQ(points[0], (Vec3{-2, 5, 0}));
  EXPECT_EQ(points[1], (Vec3{0, 5, 0}));
  EXPECT_EQ(points[2], (Vec3{2, 5, 0}));
  l.size2 = 3;
  l.axis2 = {0, 0, 4};
  l.circular = true;
  points.clear();
  area_light_points(l, {0, 0, 0}, rng, [&](const Vec3& p) { points.push_back(p); });
  for (const Vec3& p : points) EXPECT_LE(length(p - l.position), 2 + 1e-12);  // inside the disc
  EXPECT_NEAR(length(points[0] - l.position), 2, 1e-12);  // a corner lands on the circle
  l.orient = true;
  points.clear();
  area_light_points(l, {3, 0, 4}, rng, [&](const Vec3& p) { points.push_back(p); });
  const Vec3 w = normalize(Vec3{3, -5, 4});
  for (const Vec3& p : points) EXPECT_NEAR(dot(p - l.position, w), 0, 1e-12);  // faces the point
}

TEST(PovLights, Shadowless_IsNeverBlocked) {
  const std::string blocker = "{center: [0, 2, 0], radius: 1}";
  EXPECT_EQ(floor_light(scene("  - {type: point, position: [0, 5, 0]}\n", blocker), 0, 0), 0);
  EXPECT_NEAR(
      floor_light(scene("  - {type: point, position: [0, 5, 0], shadows: false}\n", blocker), 0, 0),
      1, 1e-12);
}

TEST(PovLights, Parallel_ShadowsOnlyFromBelowItsPlane) {
  const std::string blocker = "{center: [0, 2, 0], radius: 0.5}";
  const auto light = [](double height) {
    return "  - {type: directional, direction: [0, -1, 0], position: [0, " +
           std::to_string(height) + ", 0]}\n";
  };
  EXPECT_EQ(floor_light(scene(light(5), blocker), 0, 0), 0);
  EXPECT_NEAR(floor_light(scene(light(5), blocker), 3, 0), 1, 1e-12);  // parallel: nl = 1
  EXPECT_NEAR(floor_light(scene(light(1), blocker), 0, 0), 1, 1e-12);  // the sphere is above
}

TEST(PovLights, Cylinder_LitWithinItsRadius_SmoothEdge) {
  const Scene s = scene(
      "  - {type: cylinder, position: [0, 5, 0], direction: [0, -1, 0], radius: 2, "
      "falloff: 1}\n");
  EXPECT_NEAR(floor_light(s, 0.5, 0), 1, 1e-12);
  EXPECT_NEAR(floor_light(s, 0, 1.5), 0.5, 1e-12);  // halfway through the edge: smoothstep 1/2
  EXPECT_EQ(floor_light(s, 2.5, 0), 0);
}

TEST(PovLights, Fade_FullAtFadeDistance) {
  const auto light = [](double d, double p) {
    return "  - {type: point, position: [0, 5, 0], attenuation: fade, fade_distance: " +
           std::to_string(d) + ", fade_power: " + std::to_string(p) + "}\n";
  };
  EXPECT_NEAR(floor_light(scene(light(5, 2)), 0, 0), 1, 1e-12);
  EXPECT_NEAR(floor_light(scene(light(2.5, 2)), 0, 0), 2.0 / 5, 1e-12);
  EXPECT_NEAR(floor_light(scene(light(10, 1)), 0, 0), 2.0 / 1.5, 1e-12);
}

TEST(PovLights, SpotCone_CosineEdgeAndTightness) {
  Light l;
  l.type = LightType::kSpot;
  l.direction = {0, -1, 0};
  l.angle = 40;
  l.falloff = 20;  // POV-Ray's radius 20, falloff 40
  l.edge = SpotEdge::kCosine;
  const double a = 30 * std::numbers::pi / 180;
  const Vec3 at30{std::sin(a), -std::cos(a), 0};
  const double c20 = std::cos(20 * std::numbers::pi / 180),
               c40 = std::cos(40 * std::numbers::pi / 180);
  const double t = (std::cos(a) - c40) / (c20 - c40);
  EXPECT_NEAR(spot_cone(l, at30), t * t * (3 - 2 * t), 1e-12);
  EXPECT_EQ(spot_cone(l, {0, -1, 0}), 1);
  EXPECT_EQ(spot_cone(l, {1, 0, 0}), 0);
  l.tightness = 10;
  EXPECT_NEAR(spot_cone(l, at30), t * t * (3 - 2 * t) * std::pow(std::cos(a), 10), 1e-12);
}

TEST(PovLights, Shadowless_GivesNoHighlight) {
  // The light mirrors into the view at the origin: highlight 1 unless the light is shadowless.
  const auto shiny = [](const std::string& shadows) {
    return load_scene_text(
        "materials:\n  shiny: {color: [1, 1, 1], ambient: 0, diffuse: 0.5, specular: 1, "
        "shininess: 1}\n"
        "lights:\n  - {type: point, position: [-8, 8, 0], shadows: " +
        shadows +
        "}\n"
        "objects:\n  - {plane: {normal: [0, 1, 0], point: [0, 0, 0]}, material: shiny}\n");
  };
  EXPECT_NEAR(floor_light(shiny("true"), 0, 0), 0.5 * std::sqrt(0.5) + 1, 1e-12);
  EXPECT_NEAR(floor_light(shiny("false"), 0, 0), 0.5 * std::sqrt(0.5), 1e-12);
}

}  // namespace
}  // namespace raycast
