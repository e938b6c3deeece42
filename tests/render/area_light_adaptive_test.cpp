// POV-Ray's `adaptive N` area-light sampling (render/area_light_adaptive.h): where the corners
// agree (a point fully lit or fully shadowed) only the corners' shadow rays are cast; where they
// differ the cells are split, and a grid split down to single steps gives the full grid's answer.
#include <gtest/gtest.h>

#include <string>

#include "load/loader.h"
#include "render/integrator.h"
#include "render/ray_recorder.h"

namespace raycast {
namespace {

// Counts only (events false: no hook is called).
class CountingRecorder final : public RayRecorder {
 public:
  CountingRecorder() { events = false; }
  void child(RayKind, double, const Color&) override {}
  void begin_ray(const Ray&, int) override {}
  void miss(const Color&) override {}
  void hit(const SceneHit&, const SurfaceInfo&, std::size_t, bool, const Vec3&) override {}
  void ambient(const Color&) override {}
  void light(const LightSample&) override {}
  void split(double, double, bool, double, double) override {}
  void stop(RayStop) override {}
  void end_ray(const Color&) override {}
};

// A white floor (diffuse 1, no ambient) under a 5 x 5 area light 5 above the origin spanning
// x, z in [-2, 2]; `adaptive` appended to the light's fields; `blocker_x`: a thin slab at
// height 2.5 covering x < blocker_x (the shadow rays from the origin cross it at half the light
// point's x; none: nothing).
Scene scene(const std::string& adaptive, const std::string& blocker_x = "") {
  return load_scene_text(
      "materials:\n  white: {color: [1, 1, 1], ambient: 0, diffuse: 1, specular: 0}\n"
      "lights:\n  - {type: area, position: [0, 5, 0], axis1: [4, 0, 0], axis2: [0, 0, 4], "
      "size1: 5, size2: 5" +
      adaptive +
      "}\nobjects:\n  - {plane: {normal: [0, 1, 0], point: [0, 0, 0]}, material: white}\n" +
      (blocker_x.empty() ? ""
                         : "  - {box: {min: [-10, 2.4, -10], max: [" + blocker_x +
                               ", 2.6, 10]}, material: white}\n"));
}

struct Seen {
  double red = 0, red_recorded = 0;
  std::uint64_t shadow_rays = 0;
};

// The floor's origin seen at a grazing angle (under the slab), rendered and recorded.
Seen origin_seen(const Scene& s) {
  const Integrator integrator(s, RenderMode::kWhitted);
  const Ray ray{{8, 1, 0}, normalize(Vec3{-8, -1, 0}), 0, kInfinity};
  SampleState plain{Rng(7), 0};
  CountingRecorder recorder;
  SampleState counted{Rng(7), 0, &recorder};
  Seen seen;
  seen.red = integrator.li(ray, plain).x;
  seen.red_recorded = integrator.li(ray, counted).x;
  seen.shadow_rays = recorder.counts.shadow;
  return seen;
}

TEST(AreaLightAdaptive, FullyLitOrShadowed_OnlyTheCornersRays) {
  for (const char* level : {", adaptive: 0", ", adaptive: 1"}) {
    SCOPED_TRACE(level);
    const Seen lit = origin_seen(scene(level));
    EXPECT_DOUBLE_EQ(lit.red, 1);
    EXPECT_EQ(lit.red_recorded, lit.red);
    // adaptive 0: the 4 corners; adaptive 1: the 3 x 3 coarse grid's points.
    const std::uint64_t coarse = std::string(level).back() == '0' ? 4 : 9;
    EXPECT_EQ(lit.shadow_rays, coarse);
    const Seen dark = origin_seen(scene(level, "10"));
    EXPECT_EQ(dark.red, 0);
    EXPECT_EQ(dark.red_recorded, 0);
    EXPECT_EQ(dark.shadow_rays, coarse);
  }
  // Without adaptive, every grid point's ray.
  EXPECT_EQ(origin_seen(scene("")).shadow_rays, 25u);
}

TEST(AreaLightAdaptive, HalfShadowed_SplitWhereTheCornersDiffer_TheFullGridsAnswer) {
  // The slab covers the light's columns x = -2 and -1 (crossings at -1 and -0.5; x = 0 crosses
  // at 0, past the slab's edge -0.3): 15 of 25 points lit.
  const Seen full = origin_seen(scene("", "-0.3"));
  EXPECT_NEAR(full.red, 0.6, 1e-12);
  const Seen adaptive = origin_seen(scene(", adaptive: 0", "-0.3"));
  EXPECT_NEAR(adaptive.red, 0.6, 1e-12);
  EXPECT_EQ(adaptive.red_recorded, adaptive.red);
  // Corners differ: split at column and row 2; the cells of columns 0-2 differ again and are
  // split to single steps (columns 0, 1, 2 at every row: 15), those of columns 2-4 agree and
  // add only column 4 at rows 0, 2, 4: 18 rays.
  EXPECT_EQ(adaptive.shadow_rays, 18u);
}

}  // namespace
}  // namespace raycast
