// Dispersion (render/dispersion.h, POV-Ray's interior `dispersion`): the bands' indices and
// shares, white light through a dispersive slab, colour fringes through a dispersive sphere,
// the POV-Ray reader's items, and `raycast explain` and the term outputs against the render.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scene_error.h"
#include "load/loader.h"
#include "load/pov_loader.h"
#include "render/dispersion.h"
#include "render/explain.h"
#include "render/pixel_record.h"
#include "render/renderer.h"

namespace raycast {
namespace {

TEST(Dispersion, BandShares_SumToWhite) {
  for (int n = 2; n <= kMaxDispersionSamples; ++n) {
    const auto w = band_weights(n);
    Color sum{0, 0, 0};
    for (int k = 0; k < n; ++k) {
      for (std::size_t c = 0; c < 3; ++c) EXPECT_GE(w[std::size_t(k)][c], 0) << n;
      sum += w[std::size_t(k)];
    }
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1, 1e-12) << n << " bands";
  }
  // Red first, violet (blue with some red) last.
  const auto w = band_weights(7);
  EXPECT_GT(w[0].x, w[0].z);
  EXPECT_GT(w[6].z, w[6].y);
}

TEST(Dispersion, BandIndices_SpanTheRatioAroundTheIor) {
  const double ior = 1.5, d = 1.15;
  EXPECT_NEAR(band_ior(ior, d, 1) / band_ior(ior, d, 0), d, 1e-15);
  EXPECT_DOUBLE_EQ(band_ior(ior, d, 0.5), ior);
  EXPECT_LT(band_ior(ior, d, 0.2), band_ior(ior, d, 0.8));  // violet bends more
  EXPECT_EQ(band_ior(ior, 1, 0.3), ior);
}

// A glass sphere in front of a black and white checker wall that gives off its own light.
std::string sphere_scene(const std::string& glass) {
  return R"(
camera: {position: [0, 0, -6], look_at: [0, 0, 0], up: [0, 1, 0], fov: 40}
image: {width: 40, height: 30, samples: 1}
render: {max_depth: 6, background: [0, 0, 0], ambient: [1, 1, 1]}
materials:
  wall: {ambient: 1, diffuse: 0, texture: {checker: {colors: [[1, 1, 1], [0, 0, 0]], scale: 0.5}}}
  glass: {color: [1, 1, 1], ambient: 0, diffuse: 0, specular: 0, transmission: 1, ior: 1.5, )" +
         glass + R"(}
objects:
  - plane: {normal: [0, 0, -1], point: [0, 0, 3]}
    material: wall
  - sphere: {center: [0, 0, 0], radius: 1.3}
    material: glass
)";
}

RenderOptions quiet() {
  RenderOptions o;
  o.spp = 1;
  o.progress = false;
  return o;
}

double most_colourful(const Image& image) {
  double most = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Vec3f c = image.at(x, y);
      most = std::max({most, double(std::abs(c.x - c.y)), double(std::abs(c.y - c.z)),
                       double(std::abs(c.x - c.z))});
    }
  return most;
}

TEST(Dispersion, DispersionOne_IsTheRenderWithout) {
  const Image plain = render(load_scene_text(sphere_scene("")), quiet());
  const Image one = render(load_scene_text(sphere_scene("dispersion: 1")), quiet());
  EXPECT_EQ(plain.rgb, one.rgb);
  EXPECT_EQ(most_colourful(plain), 0) << "a grey scene shows colour without dispersion";
}

TEST(Dispersion, SphereOverAChecker_SplitsWhiteIntoColours) {
  const Image image =
      render(load_scene_text(sphere_scene("dispersion: 1.1, dispersion_samples: 9")), quiet());
  EXPECT_GT(most_colourful(image), 0.2);
}

TEST(Dispersion, SlabWithParallelFaces_LetsWhiteThroughWhite) {
  // Every band leaves parallel to the ray that entered (only shifted) and sees the same white
  // background: the shares add up to white again.
  const std::string scene = R"(
camera: {position: [0, 0, -5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 10}
image: {width: 3, height: 3, samples: 1}
render: {background: [1, 1, 1], max_depth: 5, bailout: 0}
materials:
  glass: {color: [1, 1, 1], ambient: 0, diffuse: 0, specular: 0, transmission: 1, ior: 1.5, dispersion: 1.2}
objects:
  - box: {min: [-50, -50, 0], max: [50, 50, 1]}
    material: glass
)";
  const Image image = render(load_scene_text(scene), quiet());
  for (const float v : image.rgb) EXPECT_NEAR(v, 1, 1e-6);
}

TEST(Dispersion, PovInterior_ReadsDispersionAndItsSamples) {
  const std::string pov = R"(
camera { location <0, 0, -6> look_at 0 }
sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 dispersion 1.02 dispersion_samples 12 } }
)";
  const Scene scene = load_pov_scene_text(pov, "dispersion.pov", ".");
  bool found = false;
  for (const Material& m : scene.materials)
    if (m.dispersion != 1) {
      EXPECT_DOUBLE_EQ(m.dispersion, 1.02);
      EXPECT_EQ(m.dispersion_samples, 12);
      found = true;
    }
  EXPECT_TRUE(found);
  EXPECT_THROW(
      load_pov_scene_text("sphere { 0, 1 interior { dispersion_samples 1 } }", "bad.pov", "."),
      SceneError);
}

TEST(Dispersion, YamlKeys_OutOfRangeArePositionedErrors) {
  EXPECT_THROW(load_scene_text(sphere_scene("dispersion: 0")), SceneError);
  EXPECT_THROW(load_scene_text(sphere_scene("dispersion: 1.1, dispersion_samples: 1")), SceneError);
  EXPECT_THROW(load_scene_text(sphere_scene("dispersion: 1.1, dispersion_samples: 65")),
               SceneError);
}

TEST(Dispersion, ExplainedPixels_EqualTheRender) {
  const Scene scene = load_scene_text(sphere_scene("dispersion: 1.1, dispersion_samples: 5"));
  const Image image = render(scene, quiet());
  for (int y = 8; y < 22; y += 3)
    for (int x = 10; x < 30; x += 3) {
      ExplainOptions o;
      o.x = x;
      o.y = y;
      o.width = 40;
      o.height = 30;
      o.spp = 1;
      const Explanation e = explain_pixel(scene, o);
      const Vec3f got(e.color), want = image.at(x, y);
      EXPECT_EQ(got.x, want.x) << x << " " << y;
      EXPECT_EQ(got.y, want.y) << x << " " << y;
      EXPECT_EQ(got.z, want.z) << x << " " << y;
    }
}

TEST(Dispersion, WhittedTerms_SumToTheImage) {
  const Scene scene = load_scene_text(sphere_scene("dispersion: 1.1, dispersion_samples: 5"));
  const std::vector<RecordedOutput> terms = {RecordedOutput::kAmbient, RecordedOutput::kDiffuse,
                                             RecordedOutput::kSpecular, RecordedOutput::kReflection,
                                             RecordedOutput::kRefraction};
  const RecordedRender r = render_recorded(scene, quiet(), terms);
  for (std::size_t i = 0; i < r.image.rgb.size(); ++i) {
    double sum = 0;
    for (std::size_t k = 0; k < 5; ++k) sum += r.outputs[k].rgb[i];
    EXPECT_NEAR(sum, r.image.rgb[i], 4e-7 * (1 + std::abs(sum))) << i;
  }
}

}  // namespace
}  // namespace raycast
