#include "scene/instance.h"

#include <algorithm>
#include <stdexcept>

#include "accel/bvh_traverse.h"
#include "scene/prototype.h"

namespace raycast {

std::size_t Prototype::memory_bytes() const {
  return sizeof(Prototype) + objects.capacity() * sizeof(Object) + bvh.memory_bytes() +
         (bounded.capacity() + unbounded.capacity()) * sizeof(std::uint32_t);
}

std::shared_ptr<const Prototype> make_prototype(std::vector<Object> objects) {
  auto p = std::make_shared<Prototype>();
  p->objects = std::move(objects);
  std::vector<Aabb> boxes;
  std::vector<Vec3> centres;
  for (std::size_t i = 0; i < p->objects.size(); ++i) {
    if (std::holds_alternative<InstanceShape>(p->objects[i].shape))
      throw std::invalid_argument("a prototype cannot hold instances");
    const Aabb b = bounds(p->objects[i]);
    p->box.grow(b);
    if (b.is_empty()) continue;
    if (b.is_bounded()) {
      boxes.push_back(b);
      centres.push_back(b.centre());
      p->bounded.push_back(static_cast<std::uint32_t>(i));
    } else {
      p->unbounded.push_back(static_cast<std::uint32_t>(i));
    }
  }
  BvhBuildConfig config;
  config.max_leaf_size = 4;
  p->bvh = build_bvh(boxes, centres, config);
  return p;
}

Aabb bounds(const InstanceShape& s) { return s.proto->box; }

bool intersect(const InstanceShape& s, const Ray& ray, LocalHit& hit) {
  const Prototype& p = *s.proto;
  Ray r = ray;
  bool found = false;
  auto test = [&](std::uint32_t index, double& tmax) {
    r.tmax = tmax;
    LocalHit h;
    if (intersect(p.objects[index], r, h) && h.t <= tmax) {
      tmax = h.t;
      h.inner = static_cast<std::int32_t>(index);
      hit = h;
      found = true;
    }
  };
  double tmax = ray.tmax;
  for (std::uint32_t index : p.unbounded) test(index, tmax);
  traverse_nearest(p.bvh, ray.o, ray.d, ray.tmin, tmax,
                   [&](std::uint32_t prim, double& t) { test(p.bounded[prim], t); });
  return found;
}

bool occluded(const InstanceShape& s, const Ray& ray) {
  const Prototype& p = *s.proto;
  for (std::uint32_t index : p.unbounded)
    if (occluded(p.objects[index], ray)) return true;
  return traverse_any(p.bvh, ray.o, ray.d, ray.tmin, ray.tmax, [&](std::uint32_t prim) {
    return occluded(p.objects[p.bounded[prim]], ray);
  });
}

void spans(const InstanceShape& s, const Ray& ray, SpanList& out) {
  const Prototype& p = *s.proto;
  const std::size_t first = out.size();
  for (std::size_t i = 0; i < p.objects.size(); ++i) {
    const std::size_t before = out.size();
    spans(p.objects[i], ray, out);
    for (std::size_t k = before; k < out.size(); ++k)
      out[k].in.inner = out[k].out.inner = static_cast<std::int32_t>(i);
  }
  // std::sort, not stable_sort: no buffer to allocate; ties are broken by object, so the order
  // is still deterministic.
  std::sort(out.begin() + first, out.end(), [](const Span& a, const Span& b) {
    return a.in.t < b.in.t || (a.in.t == b.in.t && a.in.inner < b.in.inner);
  });
}

SurfaceInfo surface(const InstanceShape& s, const Ray& ray, const LocalHit& hit) {
  LocalHit h = hit;
  h.flip = false;
  return surface(s.proto->objects[static_cast<std::size_t>(hit.inner)], ray, h);
}

bool contains(const InstanceShape& s, const Vec3& p) {
  for (const Object& o : s.proto->objects)
    if (contains(o, p)) return true;
  return false;
}

bool is_closed(const InstanceShape& s) {
  return s.proto->objects.size() == 1 && is_closed(s.proto->objects[0]);
}

int instance_material(const InstanceShape& s, const LocalHit& hit) {
  if (hit.inner < 0 || static_cast<std::size_t>(hit.inner) >= s.proto->objects.size()) return -1;
  return material_of(s.proto->objects[static_cast<std::size_t>(hit.inner)], hit);
}

}  // namespace raycast
