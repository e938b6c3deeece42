// Ray queries of raycast::api::Scene: one ray, and batches over all cores (oneTBB).
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "api/impl.h"
#include "scene/ray_batch.h"

namespace raycast::api {

namespace {

constexpr std::size_t kRayGrain = 256;  // rays per task: enough to hide the scheduling cost
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Ray i of a strided array, in the engine's form.
template <class T>
raycast::Ray ray_at(const RayArray& a, std::size_t i) {
  const char* base =
      static_cast<const char*>(a.data) + static_cast<std::ptrdiff_t>(i) * a.ray_stride;
  double v[6];
  for (int k = 0; k < 6; ++k) {
    T x;
    std::memcpy(&x, base + k * a.component_stride, sizeof(T));
    v[k] = static_cast<double>(x);
  }
  return {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, a.tmin, a.tmax};
}

// Calls f(i, ray) for every ray of the array, in parallel.
template <class F>
void for_each_ray(const RayArray& rays, F&& f) {
  if (rays.count > 0 && rays.data == nullptr) throw std::invalid_argument("RayArray: data is null");
  auto run = [&](auto tag) {
    using T = decltype(tag);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.count, kRayGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) f(i, ray_at<T>(rays, i));
                      });
  };
  if (rays.type == RayArray::Type::kFloat32)
    run(float{});
  else
    run(double{});
}

// The public record of a nearest-hit query's result.
SurfaceInfo answer(const raycast::Scene& scene, const raycast::Ray& ray, bool found,
                   const raycast::SceneHit& hit) {
  SurfaceInfo out;
  if (!found) {
    out.point = out.normal = {kNaN, kNaN, kNaN};
    out.uv = {kNaN, kNaN};
    return out;
  }
  const raycast::SurfaceInfo s = scene.surface(ray, hit);
  out.t = hit.local.t;
  out.point = to_public(s.p);
  out.normal = to_public(s.n);
  out.uv = {s.u, s.v};
  out.object = scene.objects[hit.object].entry;
  out.primitive = hit.local.prim;
  return out;
}

SurfaceInfo answer(const raycast::Scene& scene, const raycast::Ray& ray) {
  raycast::SceneHit hit;
  const bool found = scene.intersect(ray, hit);
  return answer(scene, ray, found, hit);
}

// The nearest hits of rays [begin, end) of a batch, coherent runs as packets
// (scene/ray_batch.h): f(i, ray, found, hit) for each.
template <class RayAt, class F>
void nearest_hits(const raycast::Scene& scene, std::size_t begin, std::size_t end, RayAt&& ray_at,
                  F&& f) {
  const std::size_t n = end - begin;
  std::vector<raycast::Ray> rays(n);
  for (std::size_t k = 0; k < n; ++k) rays[k] = ray_at(begin + k);
  std::vector<raycast::SceneHit> hits(n);
  std::vector<std::uint8_t> found(n);
  raycast::intersect_batch(scene, rays, hits, found);
  for (std::size_t k = 0; k < n; ++k) f(begin + k, rays[k], found[k] != 0, hits[k]);
}

// Calls f(i, ray, found, hit) with the nearest hit of every ray of the array, in parallel,
// coherent runs as packets.
template <class F>
void for_each_ray_nearest(const raycast::Scene& scene, const RayArray& rays, F&& f) {
  if (rays.count > 0 && rays.data == nullptr) throw std::invalid_argument("RayArray: data is null");
  auto run = [&](auto tag) {
    using T = decltype(tag);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.count, kRayGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        nearest_hits(
                            scene, r.begin(), r.end(),
                            [&](std::size_t i) { return ray_at<T>(rays, i); }, f);
                      });
  };
  if (rays.type == RayArray::Type::kFloat32)
    run(float{});
  else
    run(double{});
}

}  // namespace

const Scene::Impl& Scene::ready() const {
  if (!impl_) throw std::logic_error("raycast::Scene: the scene was moved from");
  if (!impl_->committed) throw std::logic_error("raycast::Scene: call commit() before querying");
  return *impl_;
}

int Scene::object_count() const { return ready().scene.entries; }

std::string Scene::shape_name(ObjectId object) const {
  const Impl& impl = ready();
  if (!impl.objects.empty()) {  // built in code
    if (object >= 0 && static_cast<std::size_t>(object) < impl.objects.size())
      return raycast::shape_name(impl.objects[object]);
  } else {
    for (const raycast::Object& o : impl.scene.objects)
      if (o.entry == object) return raycast::shape_name(o);
  }
  throw std::out_of_range("raycast::Scene::shape_name: no object " + std::to_string(object));
}

std::array<Vec3d, 2> Scene::bounds() const {
  const raycast::Aabb& b = ready().scene.finite_bounds();
  return {to_public(b.lo), to_public(b.hi)};
}

SurfaceInfo Scene::intersect(const Ray& ray) const { return answer(ready().scene, to_engine(ray)); }

bool Scene::occluded(const Ray& ray) const { return ready().scene.occluded(to_engine(ray)); }

namespace {

void crossings(const raycast::Scene& scene, const raycast::Ray& ray,
               std::vector<raycast::Crossing>& tmp, std::vector<Crossing>& out) {
  scene.intersect_all(ray, tmp);
  for (const raycast::Crossing& c : tmp) {
    const raycast::SurfaceInfo s = scene.surface(ray, raycast::SceneHit{c.local, c.object});
    out.push_back({c.t, to_public(s.n), scene.objects[c.object].entry});
  }
}

}  // namespace

std::vector<Crossing> Scene::intersect_all(const Ray& ray) const {
  std::vector<raycast::Crossing> tmp;
  std::vector<Crossing> out;
  crossings(ready().scene, to_engine(ray), tmp, out);
  return out;
}

void Scene::intersect(std::span<const Ray> rays, std::span<SurfaceInfo> out) const {
  const raycast::Scene& scene = ready().scene;
  if (out.size() != rays.size())
    throw std::invalid_argument("raycast::Scene::intersect: out must have one entry per ray");
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, rays.size(), kRayGrain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        nearest_hits(
            scene, r.begin(), r.end(), [&](std::size_t i) { return to_engine(rays[i]); },
            [&](std::size_t i, const raycast::Ray& ray, bool found, const raycast::SceneHit& hit) {
              out[i] = answer(scene, ray, found, hit);
            });
      });
}

void Scene::intersect(const RayArray& rays, const HitColumns& out) const {
  const raycast::Scene& scene = ready().scene;
  const bool need_surface = out.point || out.normal || out.uv;
  for_each_ray_nearest(
      scene, rays,
      [&](std::size_t i, const raycast::Ray& ray, bool found, const raycast::SceneHit& hit) {
        if (out.t) out.t[i] = found ? hit.local.t : std::numeric_limits<double>::infinity();
        if (out.object) out.object[i] = found ? scene.objects[hit.object].entry : kNoObject;
        if (out.primitive) out.primitive[i] = found ? hit.local.prim : -1;
        if (!need_surface) return;
        raycast::SurfaceInfo s;
        if (found) {
          s = scene.surface(ray, hit);
        } else {
          s.p = s.n = {kNaN, kNaN, kNaN};
          s.u = s.v = kNaN;
        }
        if (out.point)
          for (int k = 0; k < 3; ++k) out.point[3 * i + k] = s.p[k];
        if (out.normal)
          for (int k = 0; k < 3; ++k) out.normal[3 * i + k] = s.n[k];
        if (out.uv) {
          out.uv[2 * i] = s.u;
          out.uv[2 * i + 1] = s.v;
        }
      });
}

void Scene::occluded(std::span<const Ray> rays, std::span<std::uint8_t> out) const {
  const raycast::Scene& scene = ready().scene;
  if (out.size() != rays.size())
    throw std::invalid_argument("raycast::Scene::occluded: out must have one entry per ray");
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kRayGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        out[i] = scene.occluded(to_engine(rays[i])) ? 1 : 0;
                    });
}

void Scene::occluded(const RayArray& rays, std::span<std::uint8_t> out) const {
  const raycast::Scene& scene = ready().scene;
  if (out.size() != rays.count)
    throw std::invalid_argument("raycast::Scene::occluded: out must have one entry per ray");
  for_each_ray(
      rays, [&](std::size_t i, const raycast::Ray& ray) { out[i] = scene.occluded(ray) ? 1 : 0; });
}

void Scene::count_intersections(const RayArray& rays, std::span<std::int32_t> out) const {
  const raycast::Scene& scene = ready().scene;
  if (out.size() != rays.count)
    throw std::invalid_argument(
        "raycast::Scene::count_intersections: out must have one entry per ray");
  for_each_ray(rays, [&](std::size_t i, const raycast::Ray& ray) {
    thread_local std::vector<raycast::Crossing> tmp;
    scene.intersect_all(ray, tmp);
    out[i] = static_cast<std::int32_t>(tmp.size());
  });
}

void Scene::intersect_all(const RayArray& rays, std::vector<std::int64_t>& offsets,
                          std::vector<Crossing>& out) const {
  const raycast::Scene& scene = ready().scene;
  // Each ray's crossings into its own slot, then one prefix sum and a parallel copy.
  std::vector<std::vector<Crossing>> per_ray(rays.count);
  for_each_ray(rays, [&](std::size_t i, const raycast::Ray& ray) {
    thread_local std::vector<raycast::Crossing> tmp;
    crossings(scene, ray, tmp, per_ray[i]);
  });
  offsets.assign(rays.count + 1, 0);
  for (std::size_t i = 0; i < rays.count; ++i)
    offsets[i + 1] = offsets[i] + static_cast<std::int64_t>(per_ray[i].size());
  out.resize(static_cast<std::size_t>(offsets.back()));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.count, kRayGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        std::copy(per_ray[i].begin(), per_ray[i].end(), out.begin() + offsets[i]);
                    });
}

}  // namespace raycast::api
