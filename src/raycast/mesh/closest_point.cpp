#include "mesh/closest_point.h"

#include <algorithm>

#include "geometry/distance.h"

namespace raycast {

double distance2(const Aabb& box, const Vec3& p) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({box.lo[a] - p[a], 0.0, p[a] - box.hi[a]});
    d2 += d * d;
  }
  return d2;
}

MeshDistance::MeshDistance(const Mesh& mesh, const std::optional<Transform>& xf) {
  const std::size_t n = mesh.triangles.size();
  std::vector<Tri> tris(n);
  std::vector<Aabb> boxes(n);
  std::vector<Vec3> centres(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = mesh.triangles[i];
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = Vec3(mesh.positions[t[k]]);
      if (xf) v[k] = xf->point(v[k]);
      boxes[i].grow(v[k]);
    }
    tris[i] = {v[0], v[1], v[2], static_cast<std::int32_t>(mesh.source[i])};
    centres[i] = boxes[i].centre();
    box_.grow(boxes[i]);
  }
  BvhBuildConfig config;
  config.max_leaf_size = 4;
  bvh_ = build_bvh(boxes, centres, config);
  tris_.resize(n);
  for (std::size_t i = 0; i < bvh_.prims.size(); ++i) tris_[i] = tris[bvh_.prims[i]];
}

bool MeshDistance::closest(const Vec3& p, Result& best) const {
  if (bvh_.empty()) return false;
  bool improved = false;
  // Depth-first, the nearer child first; a node farther than the best so far is skipped. Each
  // stack entry carries its box distance, computed once when its parent is opened.
  struct Entry {
    std::uint32_t node;
    double d2;
  };
  Entry stack[256];  // a tree is at most 96 levels deep (accel/bvh.cpp): 2 per level
  int top = 0;
  stack[top++] = {0, distance2(bvh_.nodes[0].box, p)};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.d2 > best.distance2) continue;
    const BvhNode& node = bvh_.nodes[e.node];
    if (node.is_leaf()) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Tri& t = tris_[i];
        const Vec3 q = closest_point_on_triangle(p, t.a, t.b, t.c);
        const double d2 = length_squared(q - p);
        if (d2 < best.distance2 || (d2 == best.distance2 && t.prim < best.prim)) {
          best = {q, d2, t.prim};
          improved = true;
        }
      }
      continue;
    }
    const std::uint32_t a = node.first, b = node.first + 1;
    const double da = distance2(bvh_.nodes[a].box, p), db = distance2(bvh_.nodes[b].box, p);
    if (top + 2 > 256) continue;  // unreachable: see the stack's size
    if (da <= db) {
      if (db <= best.distance2) stack[top++] = {b, db};
      if (da <= best.distance2) stack[top++] = {a, da};
    } else {
      if (da <= best.distance2) stack[top++] = {a, da};
      if (db <= best.distance2) stack[top++] = {b, db};
    }
  }
  return improved;
}

}  // namespace raycast
