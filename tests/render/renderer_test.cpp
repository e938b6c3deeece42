#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <vector>

#include "io/scene_error.h"
#include "load/demo_scene.h"
#include "load/loader.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "render/renderer.h"

namespace raycast {
namespace {

TEST(SampleOffset, EverySampleFallsInItsOwnStratum) {
  for (int n : {2, 3, 4, 6, 9, 12, 16, 17}) {
    std::set<std::pair<int, int>> strata;
    int sx = 1;
    for (int d = 1; d * d <= n; ++d)
      if (n % d == 0) sx = d;
    const int sy = n / sx;
    for (int k = 0; k < n; ++k) {
      for (double j : {0.0, 0.999}) {
        double x, y;
        sample_offset(k, n, j, j, x, y);
        ASSERT_GE(x, 0);
        ASSERT_LT(x, 1);
        ASSERT_GE(y, 0);
        ASSERT_LT(y, 1);
        if (j == 0) strata.insert({int(x * sx), int(y * sy)});
      }
    }
    EXPECT_EQ(int(strata.size()), n) << n;
  }
  double x, y;
  sample_offset(0, 1, 0.1, 0.9, x, y);
  EXPECT_EQ(x, 0.5);
  EXPECT_EQ(y, 0.5);
}

TEST(Render, Determinism_OneAndTwoThreadsGiveIdenticalImages) {
  const Scene scene = load_demo_scene();
  RenderOptions options;
  options.width = 40;
  options.height = 30;
  options.spp = 3;
  options.progress = false;
  options.threads = 1;
  RenderStats one, two;
  const Image a = render(scene, options, &one);
  options.threads = 2;
  const Image b = render(scene, options, &two);
  EXPECT_EQ(a.rgb, b.rgb);  // bit-identical
  EXPECT_EQ(one.rays, two.rays);
  EXPECT_EQ(one.threads, 1);
  EXPECT_GE(one.rays, 40u * 30u * 3u);  // at least the primary rays
}

// One sample per pixel takes a shorter path in the pixel loop: it must give, bit for bit, the
// general rule's sample (the pixel centre, the pixel's own generator) traced by the integrator.
TEST(Render, OneSample_IsTheIntegratorsValueAtEachPixelCentre) {
  const Scene scene = load_demo_scene();
  RenderOptions options;
  options.width = 24;
  options.height = 18;
  options.spp = 1;
  options.progress = false;
  const Image image = render(scene, options);
  const Camera camera(camera_or_default(scene), options.width, options.height);
  const Integrator integrator(scene, render_mode(scene, options));
  double x_offset, y_offset;
  sample_offset(0, 1, 0.5, 0.5, x_offset, y_offset);
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) {
      SampleState state{Rng::for_pixel(x, y, scene.render.seed), 0};
      const Vec3f expected(integrator.li(camera.ray(x + x_offset, y + y_offset), state));
      const std::size_t i = 3 * (std::size_t(y) * options.width + x);
      ASSERT_EQ(image.rgb[i], expected.x) << x << "," << y;
      ASSERT_EQ(image.rgb[i + 1], expected.y) << x << "," << y;
      ASSERT_EQ(image.rgb[i + 2], expected.z) << x << "," << y;
    }
}

TEST(Render, Overrides_SetSizeAndSamples) {
  const Scene scene = load_demo_scene();
  RenderOptions options;
  options.width = 9;
  options.height = 7;
  options.spp = 2;
  options.progress = false;
  RenderStats stats;
  const Image image = render(scene, options, &stats);
  EXPECT_EQ(image.width, 9);
  EXPECT_EQ(image.height, 7);
  EXPECT_EQ(stats.spp, 2);
  EXPECT_GT(stats.mrays_per_second(), 0);
  EXPECT_NE(format_summary(stats).find("Mrays/s"), std::string::npos);
  options.width = -1;
  EXPECT_THROW(render(scene, options), std::invalid_argument);
}

TEST(Render, DiagnosticIntegrators_OnASphere) {
  // Orthographic view of a unit sphere along -z: the centre pixel sees p = (0, 0, 1).
  const Scene scene = load_scene_text(R"(
camera: {type: orthographic, position: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], height: 4}
image: {width: 5, height: 5, samples: 1}
render: {background: [0.1, 0.2, 0.3]}
objects:
  - sphere: {center: [0, 0, 0], radius: 1}
    material: {color: [0.5, 0.25, 1]}
)");
  RenderOptions options;
  options.progress = false;
  auto centre_and_corner = [&](RenderMode type) {
    options.integrator = type;
    const Image image = render(scene, options);
    return std::pair{Vec3(image.at(2, 2)), Vec3(image.at(0, 0))};
  };
  auto [depth, depth_miss] = centre_and_corner(RenderMode::kDepth);
  EXPECT_NEAR(depth.x, 4, 1e-6);
  EXPECT_TRUE(std::isinf(depth_miss.x));
  auto [normal, normal_miss] = centre_and_corner(RenderMode::kNormal);
  EXPECT_NEAR(normal.x, 0.5, 1e-6);
  EXPECT_NEAR(normal.y, 0.5, 1e-6);
  EXPECT_NEAR(normal.z, 1.0, 1e-6);
  EXPECT_EQ(normal_miss, (Vec3{0, 0, 0}));
  auto [shade, shade_miss] = centre_and_corner(RenderMode::kRaycast);
  EXPECT_NEAR(shade.x, 0.5, 1e-6);  // albedo * |n.v| with n.v = 1
  EXPECT_NEAR(shade.z, 1, 1e-6);
  EXPECT_NEAR(shade_miss.x, 0.1, 1e-6);
  auto [id, id_miss] = centre_and_corner(RenderMode::kId);
  const Vec3 want = id_color(0);
  EXPECT_NEAR(id.x, want.x, 1e-6);
  EXPECT_NEAR(id.y, want.y, 1e-6);
  EXPECT_EQ(id_miss, (Vec3{0, 0, 0}));
  options.integrator.reset();
  options.aov = RenderMode::kAlbedo;
  EXPECT_NEAR(render(scene, options).at(2, 2).y, 0.25f, 1e-6f);
}

TEST(Render, IdColours_AreStableAndDistinct) {
  EXPECT_EQ(id_color(3), id_color(3));
  std::set<std::tuple<double, double, double>> seen;
  for (int i = 0; i < 100; ++i) {
    const Vec3 c = id_color(i);
    EXPECT_GE(c.x, 0.15);
    EXPECT_LE(c.x, 1.0);
    seen.insert({c.x, c.y, c.z});
  }
  EXPECT_EQ(seen.size(), 100u);
}

TEST(Render, MissingImageTexture_IsASceneErrorAtLoad_NotAtRender) {
  // Every file a scene names is read when it loads (so `info` and `cast` see the error too).
  EXPECT_THROW(load_scene_text(R"(
materials:
  t: {texture: {image: {file: no_such_texture.png}}}
objects:
  - sphere: {radius: 1}
    material: t
)"),
               SceneError);
}

}  // namespace
}  // namespace raycast
