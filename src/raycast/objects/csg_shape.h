#pragma once
// CSG objects: a shared, immutable tree of boolean operations over closed solids, evaluated on the
// ray's span lists. The tree's leaves are ordinary objects placed in the CSG object's space.
#include <memory>

#include "geometry/shape.h"

namespace raycast {

struct CsgTree;  // objects/csg_tree.h

/// union, intersection or difference (a - b - c ...) of closed solids, nested to any depth.
/// Hits carry the leaf that made them in LocalHit::leaf, and LocalHit::flip when the surface is
/// a subtracted solid's (its normal is reversed by the enclosing Object).
struct CsgShape {
  static constexpr const char* kName = "csg";
  std::shared_ptr<const CsgTree> tree;
};

Aabb bounds(const CsgShape& s);
/// The nearest boundary of the final solid in [tmin, tmax]; subtrees whose boxes miss the segment
/// (or the part of it where an intersection or difference can still be non-empty) are skipped.
bool intersect(const CsgShape& s, const Ray& ray, LocalHit& hit);
bool occluded(const CsgShape& s, const Ray& ray);
/// intersect() by the span lists combined node by node (the first end of the final list in
/// [tmin, tmax]), which intersect() itself uses only for trees its walk does not take (more than
/// 64 leaves or ends); the reference its walk is tested against.
bool intersect_by_spans(const CsgShape& s, const Ray& ray, LocalHit& hit);
/// intersect() without the interval walk (csg/interval_crossing.h) that it takes for trees of
/// one-interval leaves: the gathered leaf ends walked by first_crossing (or the span lists, as
/// intersect() falls back); the reference the interval walk is tested against.
bool intersect_by_gather(const CsgShape& s, const Ray& ray, LocalHit& hit);
/// The final solid's spans over the whole line (so rays starting inside are right).
void spans(const CsgShape& s, const Ray& ray, SpanList& out);
/// The leaf's surface record, its normal not yet flipped (the enclosing Object flips by hit.flip).
SurfaceInfo surface(const CsgShape& s, const Ray& ray, const LocalHit& hit);
/// The same without (u, v) (the leaf's surface with SurfaceNeeds::kGeometry, objects/object.h).
SurfaceInfo surface_geometry(const CsgShape& s, const Ray& ray, const LocalHit& hit);
bool contains(const CsgShape& s, const Vec3& p);
inline bool is_closed(const CsgShape&) { return true; }

}  // namespace raycast
