#include "scene/ray_batch.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "mesh/mesh.h"

namespace raycast {

bool coherent_rays(const Ray* rays, int n, double extent) {
  const Vec3 u0 = rays[0].d / length(rays[0].d);
  const double max_gap = extent / 32, max_turn = 1.0 / 16;
  for (int l = 1; l < n; ++l) {
    const Ray& r = rays[l];
    const Vec3 u = r.d / length(r.d);
    for (int a = 0; a < 3; ++a) {
      if ((r.d[a] < 0) != (rays[0].d[a] < 0)) return false;
      if (!(std::abs(r.o[a] - rays[0].o[a]) <= max_gap)) return false;
      if (!(std::abs(u[a] - u0[a]) <= max_turn)) return false;
    }
  }
  return true;
}

void intersect_batch(const Scene& scene, std::span<const Ray> rays, std::span<SceneHit> hits,
                     std::span<std::uint8_t> found) {
  // Packets where Scene::intersect takes its one-mesh path (the object's box, then the mesh).
  const std::int32_t object = scene.sole_mesh();
  const MeshShape* mesh =
      object < 0 ? nullptr : std::get_if<MeshShape>(&scene.objects[object].shape);
  const double extent = mesh ? max_component(mesh->mesh->box.extent()) : 0;
  std::size_t i = 0;
  while (i < rays.size()) {
    const int n = static_cast<int>(std::min<std::size_t>(8, rays.size() - i));
    if (!mesh || n < 2 || !coherent_rays(&rays[i], n, extent)) {
      // One ray alone (the next run of eight starts at the following ray).
      hits[i] = SceneHit{};
      found[i] = scene.intersect(rays[i], hits[i]);
      ++i;
      continue;
    }
    // Lanes whose ray Scene::intersect would pass to the mesh: valid, and meeting the object's
    // box on [tmin, tmax] (the test of the scene's object set).
    int mask = 0;
    for (int l = 0; l < n; ++l)
      if (scene.any_object(rays[i + l], [](std::uint32_t) { return true; })) mask |= 1 << l;
    LocalHit local[8];
    const int hit = mask ? intersect8(*mesh, &rays[i], mask, local) : 0;
    for (int l = 0; l < n; ++l) {
      found[i + l] = hit >> l & 1;
      hits[i + l] = found[i + l] ? SceneHit{local[l], object} : SceneHit{};
    }
    i += static_cast<std::size_t>(n);
  }
}

}  // namespace raycast
