#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "accel/bvh_traverse.h"

namespace raycast {

void Scene::build() {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Aabb> boxes;
  std::vector<Vec3> centres;
  bounded_.clear();
  unbounded_.clear();
  bounds_ = finite_bounds_ = Aabb{};
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Aabb b = raycast::bounds(objects[i]);
    bounds_.grow(b);
    if (b.is_empty()) continue;  // nothing to hit
    if (b.is_bounded()) {
      boxes.push_back(b);
      centres.push_back(b.centre());
      bounded_.push_back(static_cast<std::uint32_t>(i));
      finite_bounds_.grow(b);
    } else {
      unbounded_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  BvhBuildConfig config;
  config.max_leaf_size = 4;
  bvh_ = build_bvh(boxes, centres, config);
  build_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool Scene::intersect(const Ray& ray, SceneHit& hit) const {
  if (!is_valid(ray)) return false;
  Ray r = ray;
  bool found = false;
  auto test = [&](std::uint32_t index, double& tmax) {
    r.tmax = tmax;
    LocalHit h;
    if (raycast::intersect(objects[index], r, h) && h.t <= tmax) {
      tmax = h.t;
      hit.local = h;
      hit.object = static_cast<std::int32_t>(index);
      found = true;
    }
  };
  double tmax = ray.tmax;
  for (std::uint32_t index : unbounded_) test(index, tmax);
  traverse_nearest(bvh_, ray.o, ray.d, ray.tmin, tmax,
                   [&](std::uint32_t prim, double& t) { test(bounded_[prim], t); });
  return found;
}

bool Scene::occluded(const Ray& ray) const {
  if (!is_valid(ray)) return false;
  for (std::uint32_t index : unbounded_)
    if (raycast::occluded(objects[index], ray)) return true;
  return traverse_any(bvh_, ray.o, ray.d, ray.tmin, ray.tmax, [&](std::uint32_t prim) {
    return raycast::occluded(objects[bounded_[prim]], ray);
  });
}

bool Scene::any_object(const Ray& ray, const std::function<bool(std::uint32_t)>& visit) const {
  if (!is_valid(ray)) return false;
  for (std::uint32_t index : unbounded_)
    if (visit(index)) return true;
  return traverse_any(bvh_, ray.o, ray.d, ray.tmin, ray.tmax,
                      [&](std::uint32_t prim) { return visit(bounded_[prim]); });
}

void Scene::intersect_all(const Ray& ray, std::vector<Crossing>& out) const {
  out.clear();
  if (!is_valid(ray)) return;
  SpanList spans;
  auto collect = [&](std::uint32_t index) {
    spans.clear();
    raycast::spans(objects[index], ray, spans);
    // An open surface's crossing is a zero-length span reported once; a closed solid's tangent
    // touch is a zero-length span too, but its entry and exit are both reported, so that the
    // crossings of a solid always alternate in / out.
    const bool open = !is_closed(objects[index]);
    for (const Span& s : spans) {
      const bool point = open && s.in.t == s.out.t && s.in.part == s.out.part &&
                         s.in.prim == s.out.prim && s.in.leaf == s.out.leaf;
      for (const LocalHit* end : {&s.in, &s.out}) {
        if (end->part == kNoSurface) continue;
        if (end->t >= ray.tmin && end->t <= ray.tmax)
          out.push_back({end->t, static_cast<std::int32_t>(index), *end});
        if (point) break;  // an open surface's crossing is reported once
      }
    }
  };
  for (std::uint32_t index : unbounded_) collect(index);
  traverse_all(bvh_, ray.o, ray.d, ray.tmin, ray.tmax,
               [&](std::uint32_t prim) { collect(bounded_[prim]); });
  std::stable_sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) {
    return a.t < b.t || (a.t == b.t && a.object < b.object);
  });
}

SurfaceInfo Scene::surface(const Ray& ray, const SceneHit& hit, SurfaceNeeds needs) const {
  return raycast::surface(objects[hit.object], ray, hit.local, needs);
}

const Material& Scene::material_of(const SceneHit& hit) const {
  const int m = raycast::material_of(objects[hit.object], hit.local);
  return materials[m >= 0 ? m : 0];
}

CameraDesc camera_or_default(const Scene& scene) {
  if (scene.camera) return *scene.camera;
  CameraDesc c;
  Aabb b = scene.finite_bounds();
  if (b.is_empty()) b = {{-1, -1, -1}, {1, 1, 1}};
  const Vec3 centre = b.centre();
  const double radius = std::max(0.5 * length(b.extent()), 1e-6);
  const double half_fov = 0.5 * c.fov * std::numbers::pi / 180;
  c.look_at = centre;
  c.position = centre + Vec3{0, 0, radius / std::sin(half_fov)};
  c.up = {0, 1, 0};
  return c;
}

}  // namespace raycast
