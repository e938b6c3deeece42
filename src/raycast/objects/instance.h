#pragma once
// Instancing: one shared, immutable prototype (its objects and their BVH) placed many times; the
// instance's transform is its Object's. The scene's BVH over instances plus the prototype's BVH
// inside make the two-level structure.
#include <memory>

#include "geometry/shape.h"

namespace raycast {

struct Prototype;  // objects/prototype.h

/// A use of a library entry. Hits carry the prototype object that made them in LocalHit::inner.
struct InstanceShape {
  static constexpr const char* kName = "instance";
  std::shared_ptr<const Prototype> proto;
};

Aabb bounds(const InstanceShape& s);
bool intersect(const InstanceShape& s, const Ray& ray, LocalHit& hit);
bool occluded(const InstanceShape& s, const Ray& ray);
/// Every prototype object's spans, sorted by entry; objects of a group may overlap (a group is
/// not one solid), which is why instances are not CSG operands (`use` inside CSG is expanded).
void spans(const InstanceShape& s, const Ray& ray, SpanList& out);
/// The prototype object's surface record, its normal not yet flipped (the Object flips by
/// hit.flip).
SurfaceInfo surface(const InstanceShape& s, const Ray& ray, const LocalHit& hit);
/// The same without (u, v) (the part's surface with SurfaceNeeds::kGeometry, objects/object.h).
SurfaceInfo surface_geometry(const InstanceShape& s, const Ray& ray, const LocalHit& hit);
bool contains(const InstanceShape& s, const Vec3& p);
/// True when the prototype is a single closed solid.
bool is_closed(const InstanceShape& s);

}  // namespace raycast
