// scenes/csg.yaml: loads, and every camera ray's hit faces the camera with the solid behind its
// normal (a speckle of CSG, an inner or cancelled surface showing through, would break either).
// Also `raycast cast --all` on it, end to end.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "load/loader.h"

namespace raycast {
namespace {

const std::string kScene = std::string(RAYCAST_SOURCE_DIR) + "/scenes/csg.yaml";

TEST(CsgExampleScene, CameraRays_HitOutsideFacingSurfacesOnly) {
  const Scene scene = load_scene_file(kScene);
  ASSERT_TRUE(scene.camera.has_value());
  const CameraDesc& c = *scene.camera;
  const Vec3 w = normalize(c.look_at - c.position);
  const Vec3 u = normalize(cross(w, c.up));
  const Vec3 v = cross(u, w);
  const int width = 160, height = 120;
  const double half_h = std::tan(c.fov * std::numbers::pi / 360), half_w = half_h * width / height;
  int hits = 0;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double x = (2 * (i + 0.5) / width - 1) * half_w,
                   y = (1 - 2 * (j + 0.5) / height) * half_h;
      const Ray ray{c.position, w + x * u + y * v};
      SceneHit hit;
      if (!scene.intersect(ray, hit)) continue;
      ++hits;
      const SurfaceInfo si = scene.surface(ray, hit);
      SCOPED_TRACE(testing::Message() << "pixel " << i << ", " << j << " object " << hit.object);
      EXPECT_LT(dot(si.n, ray.d), 0);
      const Object& obj = scene.objects[static_cast<std::size_t>(hit.object)];
      const double step = 1e-6 * (1 + length(si.p));
      EXPECT_TRUE(contains(obj, si.p - step * si.n));
      EXPECT_FALSE(contains(obj, si.p + step * si.n));
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(hits, width * height / 2);
}

TEST(CsgExampleScene, CastAll_ListsTheFinalSolidsCrossings) {
  // Through the seed's cube minus sphere (entry 1) along the cube's turned x axis, off centre so
  // that the ray meets the cube's faces and the sphere's cavity: 4 crossings, all of entry 1.
  const std::string rays = "/tmp/raycast_csg_cast_all_rays.txt";
  std::FILE* f = std::fopen(rays.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fprintf(f, "-2.6 1.9 -5 0 0 1\n");
  std::fclose(f);
  const std::string command =
      std::string(RAYCAST_BINARY) + " cast " + kScene + " --all --rays " + rays;
  std::FILE* p = popen(command.c_str(), "r");
  ASSERT_NE(p, nullptr);
  char line[4096] = {};
  ASSERT_NE(std::fgets(line, sizeof line, p), nullptr);
  EXPECT_EQ(pclose(p), 0);
  int n = 0, consumed = 0;
  ASSERT_EQ(std::sscanf(line, "%d%n", &n, &consumed), 1);
  ASSERT_EQ(n, 4) << line;
  const char* rest = line + consumed;
  for (int k = 0; k < n; ++k) {
    double t, nx, ny, nz;
    int object;
    ASSERT_EQ(std::sscanf(rest, "%lf %lf %lf %lf %d%n", &t, &nx, &ny, &nz, &object, &consumed), 5);
    rest += consumed;
    EXPECT_EQ(object, 1);
    EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1, 1e-12);
  }
}

}  // namespace
}  // namespace raycast
