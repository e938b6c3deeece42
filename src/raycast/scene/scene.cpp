#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "mesh/mesh.h"
#include "mesh/wide_kernels.h"

namespace raycast {

namespace {

// Whether the ray starts inside the box (faces included) with tmin <= 0 <= tmax: then it passes
// intersect_slabs, whose divisions it can skip. On each axis its near distance is <= 0 and its far
// one >= 0 (or NaN, an origin on a face and a zero component, which the test ignores), so t0 <= 0
// <= t1.
bool starts_inside(const Aabb& box, const Ray& ray) {
  return ray.tmin <= 0 && ray.tmax >= 0 && box.contains(ray.o);
}

}  // namespace

void Scene::build(bool direction_lists) {
  const auto start = std::chrono::steady_clock::now();
  set_.build(objects);
  // Direction lists around the camera's position (rays that start exactly there use them) and
  // the point and spot lights (shadow segments that end there: the integrator walks a light's
  // lists when it has them; docs/rendering.md "Direction lists").
  if (direction_lists) {
    const CameraDesc view = camera_or_default(*this);
    if (rays_share_origin(view)) set_.set_view(objects, view.position);
    std::vector<std::optional<Vec3>> light_points(lights.size());
    for (std::size_t k = 0; k < lights.size(); ++k)
      if (lights[k].type == LightType::kPoint || lights[k].type == LightType::kSpot)
        light_points[k] = lights[k].position;
    set_.set_lights(objects, light_points);
  }
  // The direct path's condition is ObjectSet's own for its sole-mesh path: one object with
  // non-empty, bounded bounds, an untransformed mesh; every other object has empty bounds.
  mesh_ = nullptr;
  mesh_object_ = set_.sole_mesh();
  if (mesh_object_ >= 0) {
    const Object& object = objects[std::size_t(mesh_object_)];
    mesh_ = std::get<MeshShape>(object.shape).mesh.get();
    mesh_occluded_ = kernels_in_use().occluded_if_valid;
    mesh_box_ = raycast::bounds(object);
  }
  build_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool Scene::intersect(const Ray& ray, SceneHit& hit) const {
  if (mesh_) {
    // The box first: most rays that miss it (a camera's around the mesh) stop here, cheaper
    // than the mesh's own root test. The box test is arithmetic only, whatever the ray, and a
    // ray that is not is_valid answers "nothing" either way, so the validity check is paid by
    // the rays that reach the mesh only. A ray from inside the box with tmin <= 0 <= tmax meets
    // it (as in occluded below) and skips the test's three divisions: rays that start in the
    // scene (secondary rays, the bench's incoherent ones) never miss the box.
    double t_enter;
    if ((!starts_inside(mesh_box_, ray) &&
         !intersect_slabs(mesh_box_, ray.o, reciprocal(ray.d), ray.tmin, ray.tmax, t_enter)) ||
        !is_valid(ray) || !raycast::intersect(*mesh_, ray, hit.local))
      return false;
    hit.object = mesh_object_;
    return true;
  }
  if (!is_valid(ray)) return false;
  return set_.intersect(objects, ray, hit.local, hit.object);
}

bool Scene::occluded(const Ray& ray) const {
  if (mesh_) {
    // The mesh first and its box only when the mesh is hit: the answer is the general path's
    // (box and mesh), but shadow rays start on the mesh, inside its box, so the box test is
    // paid only by the few rays that are blocked. The kernel checks is_valid itself.
    if (!mesh_occluded_(mesh_->bvh, ray)) return false;
    if (starts_inside(mesh_box_, ray)) return true;
    double t_enter;
    return intersect_slabs(mesh_box_, ray.o, reciprocal(ray.d), ray.tmin, ray.tmax, t_enter);
  }
  if (!is_valid(ray)) return false;
  return set_.occluded(objects, ray);
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
  set_.all(ray, collect);
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
