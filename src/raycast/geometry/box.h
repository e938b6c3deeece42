#pragma once
// Axis-aligned boxes as closed solids, in object space (rotate them with `transform`).
#include "geometry/shape.h"

namespace raycast {

/// The closed solid lo <= p <= hi (per component, lo < hi on every axis). Its six faces are
/// numbered 2 * axis + side (side 0 at lo, 1 at hi): 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z; the face
/// index is LocalHit::part. On the face of axis a, with b = (a + 1) % 3 and c = (a + 2) % 3,
/// u = (p[b] - lo[b]) / (hi[b] - lo[b]) and v = (p[c] - lo[c]) / (hi[c] - lo[c]), both in [0, 1].
struct Box {
  static constexpr const char* kName = "box";
  Vec3 lo{-1, -1, -1};
  Vec3 hi{1, 1, 1};
};

/// A validated box (finite corners, lo < hi on every axis); throws std::invalid_argument.
Box make_box(const Vec3& lo, const Vec3& hi);

/// The whole line's interval inside the box, with the faces it enters and leaves by; false when
/// the line misses (or only grazes along a face plane it does not enter). A direction component of
/// exactly 0 leaves that axis unconstrained when the origin lies within [lo, hi] on it.
bool box_line_interval(const Box& b, const Ray& ray, double& t0, int& face0, double& t1,
                       int& face1);

Aabb bounds(const Box& b);
bool intersect(const Box& b, const Ray& ray, LocalHit& hit);
void spans(const Box& b, const Ray& ray, SpanList& out);
SurfaceInfo surface(const Box& b, const Ray& ray, const LocalHit& hit);
/// surface() without (u, v) (left 0) (objects/object.h, SurfaceNeeds).
SurfaceInfo surface_geometry(const Box& b, const Ray& ray, const LocalHit& hit);
bool contains(const Box& b, const Vec3& p);
inline bool is_closed(const Box&) { return true; }

}  // namespace raycast
