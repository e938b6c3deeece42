#include "objects/object.h"

#include <cmath>
#include <cstring>

#include "objects/csg_tree.h"
#include "objects/prototype.h"

namespace raycast {

namespace {

template <class Variant>
struct AllShapes;
template <class... Ts>
struct AllShapes<std::variant<Ts...>> {
  static constexpr bool value = (Shape<Ts> && ...);
};
static_assert(AllShapes<ShapeVariant>::value, "every alternative of ShapeVariant must model Shape");

// std::visit over the shapes calls through a table of thunks that GCC 12 does not inline; the
// shapes of most scenes (plane, sphere, box) are dispatched first by direct tests of the index
// (fewer instructions on every scene of bench/render_instructions.sh), then the composites, whose
// queries and hits are a good share of a CSG scene's (their tests cost the other shapes two
// compares).
template <class F>
decltype(auto) visit_shape(const ShapeVariant& v, F&& f) {
  if (const auto* s = std::get_if<Plane>(&v)) return f(*s);
  if (const auto* s = std::get_if<Sphere>(&v)) return f(*s);
  if (const auto* s = std::get_if<Box>(&v)) return f(*s);
  if (const auto* s = std::get_if<CsgShape>(&v)) return f(*s);
  if (const auto* s = std::get_if<InstanceShape>(&v)) return f(*s);
  return std::visit(f, v);
}

// visit_shape for occluded(): meshes too, so that shadow rays into meshes do not go through the
// thunk. (Not for intersect(): the inlined mesh query makes intersect(Object) larger and costs
// the glass and whitted scenes of bench/render_instructions.sh 0.3-0.5 %.)
template <class F>
decltype(auto) visit_occluded_shape(const ShapeVariant& v, F&& f) {
  if (const auto* s = std::get_if<Plane>(&v)) return f(*s);
  if (const auto* s = std::get_if<Sphere>(&v)) return f(*s);
  if (const auto* s = std::get_if<Box>(&v)) return f(*s);
  if (const auto* s = std::get_if<MeshShape>(&v)) return f(*s);
  if (const auto* s = std::get_if<CsgShape>(&v)) return f(*s);
  if (const auto* s = std::get_if<InstanceShape>(&v)) return f(*s);
  return std::visit(f, v);
}

}  // namespace

Aabb bounds(const Object& o) {
  const Aabb b = std::visit([](const auto& s) { return bounds(s); }, o.shape);
  return o.xf ? transform_bounds(*o.xf, b) : b;
}

bool intersect(const Object& o, const Ray& ray, LocalHit& hit) {
  // Without a transform the ray is the object-space ray: no copy.
  if (!o.xf) return visit_shape(o.shape, [&](const auto& s) { return intersect(s, ray, hit); });
  const Ray r = to_object_space(o, ray);
  return visit_shape(o.shape, [&](const auto& s) { return intersect(s, r, hit); });
}

bool occluded(const Object& o, const Ray& ray) {
  if (!o.xf) return visit_occluded_shape(o.shape, [&](const auto& s) { return occluded(s, ray); });
  const Ray r = to_object_space(o, ray);
  return visit_occluded_shape(o.shape, [&](const auto& s) { return occluded(s, r); });
}

void spans(const Object& o, const Ray& ray, SpanList& out) {
  const Ray r = to_object_space(o, ray);
  std::visit([&](const auto& s) { spans(s, r, out); }, o.shape);
}

SurfaceInfo surface(const Object& o, const Ray& ray, const LocalHit& hit, SurfaceNeeds needs) {
  // The object-space ray only for a transformed object (a default Ray was stored on every call).
  std::optional<Ray> moved;
  if (o.xf) moved.emplace(to_object_space(o, ray));
  const Ray& r = moved ? *moved : ray;
  SurfaceInfo si = visit_shape(o.shape, [&](const auto& s) {
    if constexpr (requires { surface_geometry(s, r, hit); }) {
      if (needs == SurfaceNeeds::kGeometry) return surface_geometry(s, r, hit);
    }
    return surface(s, r, hit);
  });
  if (o.xf) {
    const Transform& xf = *o.xf;
    const Vec3 p = si.p;
    si.p = xf.point(p);
    // Error of the object-space point carried through the matrix (|M| e), plus the transform's
    // own.
    Vec3 e = xf.point_error(p);
    e += (1 + gamma(3)) * xf.abs_vector(si.p_error);
    // A ray spawned from p goes back through the inverse transform, which rounds its origin
    // again (pbrt-v4 tracks this as the ray's origin error): widen the bound by that rounding,
    // carried to world space, so the offset origin stays outside after the round trip.
    e += (1 + gamma(3)) * xf.abs_vector(xf.inverse_point_error(si.p));
    si.p_error = e;
    // Most shapes' shading normal is their geometric one, bit for bit: carried once.
    const bool same = std::memcmp(&si.shading_n, &si.n, sizeof si.n) == 0;
    si.n = normalize(xf.normal(si.n));
    si.shading_n = same ? si.n : normalize(xf.normal(si.shading_n));
  }
  if (hit.flip) {
    si.n = -si.n;
    si.shading_n = -si.shading_n;
  }
  return si;
}

bool contains(const Object& o, const Vec3& p) {
  const Vec3 q = o.xf ? o.xf->inverse_point(p) : p;
  return std::visit([&](const auto& s) { return contains(s, q); }, o.shape);
}

int material_of(const Object& o, const LocalHit& hit) {
  int m = -1;
  if (const auto* c = std::get_if<CsgShape>(&o.shape)) m = csg_material(*c, hit);
  if (const auto* i = std::get_if<InstanceShape>(&o.shape)) m = instance_material(*i, hit);
  if (const auto* b = std::get_if<Blob>(&o.shape)) m = blob_material(*b, hit);
  return m >= 0 ? m : o.material;
}

const char* shape_name(const Object& o) {
  return std::visit([](const auto& s) -> const char* { return std::decay_t<decltype(s)>::kName; },
                    o.shape);
}

bool is_closed(const Object& o) {
  return std::visit([](const auto& s) { return is_closed(s); }, o.shape);
}

}  // namespace raycast
