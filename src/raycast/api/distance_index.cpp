#include "api/distance_index.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "api/impl.h"
#include "geometry/distance.h"
#include "scene/scene.h"

namespace raycast::api {

namespace {

// A transform maps closest points to closest points when its linear part is a rotation times a
// uniform scale. Rotations built from degrees are orthonormal only to rounding: columns may
// differ from orthogonal, equal-length ones by a few ulps of the matrix entries.
constexpr double kSimilarityTolerance = 64 * std::numeric_limits<double>::epsilon();

// Operations on one coordinate's path through the closest-point computations (transforms in and
// out, the triangle's dot products and barycentric combination).
constexpr int kClosestPointOps = 32;
// The event resolution of mesh spans in float ulps of the coordinates (mesh/mesh.cpp `tol`),
// doubled to cover the origin's own float rounding.
constexpr double kMeshEventUlps = 16;

bool is_similarity(const raycast::Transform& xf) {
  const auto& m = xf.matrix().m;
  double g[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) g[i][j] = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
  const double s2 = g[0][0];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(g[i][j] - (i == j ? s2 : 0)) > kSimilarityTolerance * s2) return false;
  return true;
}

// The nearest surface point of an analytic shape in its own space; false when it has none.
bool shape_point(const raycast::ShapeVariant& shape, const raycast::Vec3& p, raycast::Vec3& q) {
  using namespace raycast;
  if (const auto* s = std::get_if<Plane>(&shape)) return q = closest_point(*s, p), true;
  if (const auto* s = std::get_if<Sphere>(&shape)) return closest_point(*s, p, q);
  if (const auto* s = std::get_if<Box>(&shape)) return q = closest_point(*s, p), true;
  if (const auto* s = std::get_if<Ellipsoid>(&shape)) return q = closest_point(*s, p), true;
  if (const auto* s = std::get_if<Cylinder>(&shape)) return closest_point(*s, p, q);
  if (const auto* s = std::get_if<Cone>(&shape)) return closest_point(*s, p, q);
  if (const auto* s = std::get_if<Torus>(&shape)) return q = closest_point(*s, p), true;
  if (const auto* s = std::get_if<Triangle>(&shape))
    return q = closest_point_on_triangle(p, s->p0, s->p1, s->p2), true;
  return false;
}

bool has_closed_form(const raycast::Object& o) {
  raycast::Vec3 q;
  return shape_point(o.shape, raycast::Vec3(0.5, 0.25, 0.125), q);
}

}  // namespace

DistanceIndex::DistanceIndex(const raycast::Scene& scene) {
  for (const raycast::Object& o : scene.objects) {
    Entry e{&o, raycast::bounds(o), raycast::is_closed(o), nullptr};
    if (const auto* m = std::get_if<raycast::MeshShape>(&o.shape)) {
      e.mesh = std::make_unique<raycast::MeshDistance>(*m->mesh, o.xf);
    } else if (unsupported_.empty()) {
      const bool partial = !has_closed_form(o);
      const bool skewed = !partial && o.xf && !is_similarity(*o.xf);
      if (partial || skewed)
        unsupported_ = std::string("no distance query for '") + raycast::shape_name(o) +
                       "' (object " + std::to_string(o.entry) + ")" +
                       (skewed ? " under a non-uniform transform" : "") +
                       ": distances cover meshes, plane, full sphere, box, ellipsoid, full "
                       "cylinder and cone, torus and triangle (docs/library.md)";
    }
    if (e.closed)
      for (int a = 0; a < 3; ++a)
        magnitude_ = std::max({magnitude_, std::abs(e.box.lo[a]), std::abs(e.box.hi[a])});
    entries_.push_back(std::move(e));
  }
}

DistanceIndex::Nearest DistanceIndex::nearest(const raycast::Vec3& p) const {
  if (!unsupported_.empty()) throw NotImplementedError(unsupported_);
  Nearest best;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (raycast::distance2(e.box, p) > best.distance2) continue;
    if (e.mesh) {
      raycast::MeshDistance::Result r{best.point, best.distance2, -1};
      if (e.mesh->closest(p, r)) best = {r.point, r.distance2, static_cast<int>(i), r.prim};
      continue;
    }
    const raycast::Object& o = *e.object;
    raycast::Vec3 q;
    shape_point(o.shape, o.xf ? o.xf->inverse_point(p) : p, q);
    if (o.xf) q = o.xf->point(q);
    const double d2 = raycast::length_squared(q - p);
    if (d2 < best.distance2) best = {q, d2, static_cast<int>(i), -1};
  }
  return best;
}

bool DistanceIndex::inside(const raycast::Vec3& p, double distance2) const {
  for (const Entry& e : entries_) {
    if (!e.closed || !e.box.contains(p)) continue;
    if (raycast::contains(*e.object, p) || on_surface(e, p, distance2)) return true;
  }
  return false;
}

bool DistanceIndex::on_surface(const Entry& e, const raycast::Vec3& p, double distance2) const {
  // The solid is closed: its surface belongs to it. A point counts as on the surface when its
  // computed distance is within the rounding error bound of the closest-point computation (a few
  // dozen operations on coordinates of magnitude `scale`, Higham's gamma).
  double scale = 0;
  for (int a = 0; a < 3; ++a)
    scale = std::max({scale, std::abs(p[a]), std::abs(e.box.lo[a]), std::abs(e.box.hi[a])});
  const double bound = raycast::gamma(kClosestPointOps) * scale;
  if (e.mesh) {
    // Mesh spans merge crossings closer than 8 float ulps of the mesh's coordinates into one
    // event (mesh/mesh.cpp): a point that near the surface has no parity, it is on the surface.
    const double resolution = kMeshEventUlps * std::numeric_limits<float>::epsilon() * scale;
    if (distance2 > resolution * resolution) return false;  // no surface is that near
    raycast::MeshDistance::Result r;
    r.distance2 = resolution * resolution;
    return e.mesh->closest(p, r) || r.distance2 == 0;
  }
  const raycast::Object& o = *e.object;
  if (!std::isfinite(scale) || (o.xf && !is_similarity(*o.xf))) return false;
  if (distance2 > bound * bound * (1 + 1e-9)) return false;  // no surface is that near
  raycast::Vec3 q;
  if (!shape_point(o.shape, o.xf ? o.xf->inverse_point(p) : p, q)) return false;
  if (o.xf) q = o.xf->point(q);
  return raycast::length(q - p) <= bound;
}

const DistanceIndex& Scene::Impl::distance_index() const {
  std::call_once(distance_once, [&] { distance = std::make_shared<DistanceIndex>(scene); });
  return *distance;
}

}  // namespace raycast::api
