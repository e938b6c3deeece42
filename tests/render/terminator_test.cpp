// The smooth-mesh shadow terminator (render/terminator.h, Hanika 2021): a smooth-shaded sphere of
// 2,304 triangles lit from the side. Set RAYCAST_UPDATE_GOLDEN=1 to regenerate
// tests/golden/terminator_64x64.png.
#include "render/terminator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>

#include "io/image.h"
#include "load/loader.h"
#include "render/renderer.h"

namespace raycast {
namespace {

const std::string kGolden = std::string(RAYCAST_SOURCE_DIR) + "/tests/golden/terminator_64x64.png";

/// A unit sphere of 48 longitudes x 25 latitude bands: fans of 48 triangles at the poles and
/// 23 bands of 96, 2,304 triangles, with exact unit vertex normals.
std::string sphere_mesh_yaml() {
  constexpr int kSeg = 48, kBands = 25;
  std::ostringstream v, n, t;
  v.precision(17);
  n.precision(17);
  v << "[[0, 1, 0]";
  n << "[[0, 1, 0]";
  for (int i = 1; i < kBands; ++i) {
    const double theta = std::numbers::pi * i / kBands;
    for (int j = 0; j < kSeg; ++j) {
      const double phi = 2 * std::numbers::pi * j / kSeg;
      const double x = std::sin(theta) * std::cos(phi), y = std::cos(theta);
      const double z = std::sin(theta) * std::sin(phi);
      v << ", [" << x << ", " << y << ", " << z << "]";
      n << ", [" << x << ", " << y << ", " << z << "]";
    }
  }
  v << ", [0, -1, 0]]";
  n << ", [0, -1, 0]]";
  const int south = 1 + (kBands - 1) * kSeg;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * kSeg + j % kSeg; };
  t << "[";
  for (int j = 0; j < kSeg; ++j) {
    t << "[0, " << ring(1, j + 1) << ", " << ring(1, j) << "], ";
    t << "[" << south << ", " << ring(kBands - 1, j) << ", " << ring(kBands - 1, j + 1) << "], ";
  }
  for (int i = 1; i < kBands - 1; ++i)
    for (int j = 0; j < kSeg; ++j) {
      t << "[" << ring(i, j) << ", " << ring(i, j + 1) << ", " << ring(i + 1, j + 1) << "], ";
      t << "[" << ring(i, j) << ", " << ring(i + 1, j + 1) << ", " << ring(i + 1, j) << "], ";
    }
  std::string tris = t.str();
  tris.resize(tris.size() - 2);
  return "{vertices: " + v.str() + ", triangles: " + tris + "], normals: " + n.str() +
         ", smooth: true}";
}

/// The sphere (a mesh, or the exact sphere) seen from the front, lit by a point light far to
/// its right and slightly behind, no ambient: the terminator runs down the middle.
Scene side_lit(const std::string& shape) {
  return load_scene_text(R"(
camera: {position: [0, 0, 4], look_at: [0, 0, 0], fov: 35}
render: {ambient: [0, 0, 0], background: [0.02, 0, 0.3]}
materials:
  clay: {color: [0.9, 0.9, 0.9], diffuse: 1}
lights:
  - {type: point, position: [100, 10, -40], intensity: 1}
objects:
  - )" + shape + R"(
    material: clay
)");
}

Image render64(const Scene& scene) {
  RenderOptions options;
  options.width = 64;
  options.height = 64;
  options.spp = 1;
  options.progress = false;
  return render(scene, options);
}

TEST(Terminator, SmoothSphere_HasTheStatedTriangleCount) {
  const Scene scene = side_lit("mesh: " + sphere_mesh_yaml());
  const auto& mesh = std::get<MeshShape>(scene.objects[0].shape).mesh;
  EXPECT_EQ(mesh->triangle_count(), 2304u);
  EXPECT_FALSE(mesh->normals.empty());
}

TEST(Terminator, SmoothSphere_NoShadowedPixelWhereTheExactSphereIsLit) {
  // Where the exact sphere receives clearly more than nothing (n.l > 0.05), the smooth mesh must
  // not be black: before the fix its facets shadowed a staircase of such pixels.
  const Image mesh = render64(side_lit("mesh: " + sphere_mesh_yaml()));
  const Image exact = render64(side_lit("sphere: {radius: 1}"));
  int lit = 0, black = 0;
  for (std::size_t i = 0; i < mesh.rgb.size(); i += 3) {
    if (!(exact.rgb[i] > 0.05f)) continue;
    ++lit;
    if (mesh.rgb[i] == 0.f) ++black;
  }
  EXPECT_GT(lit, 400);
  EXPECT_EQ(black, 0);
}

TEST(Terminator, Render64x64_MatchesTheGoldenImage) {
  const Image image = render64(side_lit("mesh: " + sphere_mesh_yaml()));
  const char* update = std::getenv("RAYCAST_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    save_png(image, kGolden);
    GTEST_SKIP() << "regenerated " << kGolden;
  }
  const Image golden = load_png(kGolden);
  ASSERT_EQ(golden.width, 64);
  ASSERT_EQ(golden.height, 64);
  // 8-bit sRGB codes: the mean difference under half a code, no pixel off by more than 8.
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const double d =
        std::abs(255.0 * linear_to_srgb(image.rgb[i]) - 255.0 * linear_to_srgb(golden.rgb[i]));
    sum += d;
    worst = std::max(worst, d);
  }
  EXPECT_LT(sum / double(image.rgb.size()), 0.5);
  EXPECT_LE(worst, 8.0);
}

TEST(Terminator, NotASmoothMesh_RecordUnchanged) {
  const Scene scene = side_lit("sphere: {radius: 1}");
  SurfaceInfo si;
  si.p = {1, 2, 3};
  si.p_error = {1e-16, 1e-16, 1e-16};
  const SurfaceInfo out = terminator_origin(scene.objects[0], LocalHit{}, si);
  EXPECT_EQ(out.p, si.p);
  EXPECT_EQ(out.p_error, si.p_error);
}

}  // namespace
}  // namespace raycast
