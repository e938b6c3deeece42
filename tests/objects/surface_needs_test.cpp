// surface() with SurfaceNeeds::kGeometry gives the same point, error bound and normals as the full
// record, bit for bit, for every kind of object the Whitted integrator shades without (u, v):
// plain shapes, transformed ones, CSG leaves and instances of a library entry (objects/object.h).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <variant>

#include "load/loader.h"
#include "render/camera.h"

namespace raycast {
namespace {

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(SurfaceNeeds, GeometryOnlyEqualsTheFullRecordOnCsgAndInstances) {
  const Scene scene = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/scenes/csg.yaml");
  const int width = 160, height = 120;
  const Camera camera(*scene.camera, width, height);
  int csg_hits = 0, instance_hits = 0, with_uv = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Ray ray = camera.ray(x + 0.5, y + 0.5);
      SceneHit hit;
      if (!scene.intersect(ray, hit)) continue;
      const SurfaceInfo all = scene.surface(ray, hit, SurfaceNeeds::kAll);
      const SurfaceInfo geometry = scene.surface(ray, hit, SurfaceNeeds::kGeometry);
      ASSERT_TRUE(same_bits(all.p, geometry.p)) << x << ", " << y;
      ASSERT_TRUE(same_bits(all.p_error, geometry.p_error)) << x << ", " << y;
      ASSERT_TRUE(same_bits(all.n, geometry.n)) << x << ", " << y;
      ASSERT_TRUE(same_bits(all.shading_n, geometry.shading_n)) << x << ", " << y;
      const ShapeVariant& shape = scene.objects[std::size_t(hit.object)].shape;
      const bool csg = std::holds_alternative<CsgShape>(shape);
      const bool instance = std::holds_alternative<InstanceShape>(shape);
      csg_hits += csg;
      instance_hits += instance;
      // The full record of a composite's sphere or torus part has its (u, v); the geometric
      // one may leave them 0 (what the integrator skips).
      with_uv += (csg || instance) && (all.u != geometry.u || all.v != geometry.v);
    }
  }
  EXPECT_GT(csg_hits, 1000);
  EXPECT_GT(instance_hits, 100);
  EXPECT_GT(with_uv, 100);  // the composites' parts did leave out (u, v)
}

}  // namespace
}  // namespace raycast
