#include "scene/ray_batch.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "math/float_error.h"
#include "math/isa.h"
#include "math/lane_array.h"
#include "mesh/mesh.h"
#include "mesh/mesh_packet16.h"

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

namespace {

// The lanes l < n (n <= 16) whose ray Scene::intersect's one-mesh path passes to the mesh:
// is_valid and intersect_slabs(box, o, reciprocal(d), tmin, tmax) (geometry/aabb.h). The slab
// test runs on four lanes at once with the same IEEE double operations in the same order, so its
// answers are the scalar test's (the scalar test's early exit changes nothing: t0 only grows and
// t1 only shrinks). In double rather than float: a float test would need a double re-test of
// its uncertain lanes to stay exact, and the four-lane double test is already branch-free.
int box_lanes(const Aabb& box, const Ray* rays, int n) {
  using D4 = double __attribute__((vector_size(32)));
  using I4 = std::int64_t __attribute__((vector_size(32)));
  constexpr double kWiden = 1 + 2 * gamma(3);
  int mask = 0;
  for (int h = 0; h < n; h += 4) {
    D4 o[3], d[3], t0, t1;
    for (int j = 0; j < 4; ++j) {
      const Ray& r = rays[std::min(h + j, n - 1)];
      for (int a = 0; a < 3; ++a) {
        o[a][j] = r.o[a];
        d[a][j] = r.d[a];
      }
      t0[j] = r.tmin;
      t1[j] = r.tmax;
    }
    for (int a = 0; a < 3; ++a) {
      const D4 inv = 1.0 / d[a];
      const I4 negative = __builtin_bit_cast(I4, inv) < 0;  // std::signbit
      const D4 lo = {box.lo[a], box.lo[a], box.lo[a], box.lo[a]};
      const D4 hi = {box.hi[a], box.hi[a], box.hi[a], box.hi[a]};
      const D4 near = ((negative ? hi : lo) - o[a]) * inv;
      const D4 far = ((negative ? lo : hi) - o[a]) * inv * kWiden;
      t0 = near > t0 ? near : t0;
      t1 = far < t1 ? far : t1;
    }
    const I4 meets = t0 > t1;
    for (int j = 0; j < 4 && h + j < n; ++j)
      if (!meets[j] && is_valid(rays[h + j])) mask |= 1 << (h + j);
  }
  return mask;
}

}  // namespace

void intersect_batch(const Scene& scene, std::span<const Ray> rays, std::span<SceneHit> hits,
                     std::span<std::uint8_t> found) {
  // Packets where Scene::intersect takes its one-mesh path (the object's box, then the mesh),
  // as wide as the kernels' widest (mesh/mesh_packet16.h).
  const std::int32_t object = scene.sole_mesh();
  const MeshShape* mesh =
      object < 0 ? nullptr : std::get_if<MeshShape>(&scene.objects[object].shape);
  const double extent = mesh ? max_component(mesh->mesh->box.extent()) : 0;
  const Aabb box = mesh ? bounds(scene.objects[object]) : Aabb{};
  const int width = packet_width(active_isa());
  std::size_t i = 0;
  while (i < rays.size()) {
    int n = static_cast<int>(std::min<std::size_t>(width, rays.size() - i));
    // Sixteen that are not coherent may still be eight that are.
    if (mesh && n > 8 && !coherent_rays(&rays[i], n, extent)) n = 8;
    if (!mesh || n < 2 || !coherent_rays(&rays[i], n, extent)) {
      // One ray alone (the next run starts at the following ray).
      hits[i] = SceneHit{};
      found[i] = scene.intersect(rays[i], hits[i]);
      ++i;
      continue;
    }
    const int mask = box_lanes(box, &rays[i], n);
    // The lanes without zero-fill, and a miss copied from a constant rather than built on the
    // stack (as bench --packets' loop).
    static const SceneHit kMiss{};
    LaneArray<LocalHit, 16> local;
    const int hit = !mask   ? 0
                    : n > 8 ? intersect16(*mesh, &rays[i], mask, local.data())
                            : intersect8(*mesh, &rays[i], mask, local.data());
    for (int l = 0; l < n; ++l) {
      found[i + l] = hit >> l & 1;
      if (found[i + l]) {
        hits[i + l].local = local[l];
        hits[i + l].object = object;
      } else {
        hits[i + l] = kMiss;
      }
    }
    i += static_cast<std::size_t>(n);
  }
}

}  // namespace raycast
