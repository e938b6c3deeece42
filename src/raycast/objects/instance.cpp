#include "objects/instance.h"

#include <algorithm>
#include <stdexcept>

#include "objects/prototype.h"

namespace raycast {

std::size_t Prototype::memory_bytes() const {
  return sizeof(Prototype) + objects.capacity() * sizeof(Object) + set.memory_bytes();
}

std::shared_ptr<const Prototype> make_prototype(std::vector<Object> objects) {
  auto p = std::make_shared<Prototype>();
  p->objects = std::move(objects);
  for (const Object& o : p->objects)
    if (std::holds_alternative<InstanceShape>(o.shape))
      throw std::invalid_argument("a prototype cannot hold instances");
  p->set.build(p->objects);
  return p;
}

Aabb bounds(const InstanceShape& s) { return s.proto->set.bounds(); }

bool intersect(const InstanceShape& s, const Ray& ray, LocalHit& hit) {
  std::int32_t index = -1;
  if (!s.proto->set.intersect(s.proto->objects, ray, hit, index)) return false;
  hit.inner = index;
  return true;
}

bool occluded(const InstanceShape& s, const Ray& ray) {
  return s.proto->set.occluded(s.proto->objects, ray);
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
  return part_surface(s.proto->objects[static_cast<std::size_t>(hit.inner)], ray, hit,
                      SurfaceNeeds::kAll);
}

SurfaceInfo surface_geometry(const InstanceShape& s, const Ray& ray, const LocalHit& hit) {
  return part_surface(s.proto->objects[static_cast<std::size_t>(hit.inner)], ray, hit,
                      SurfaceNeeds::kGeometry);
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
