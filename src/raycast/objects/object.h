#pragma once
// An object of the scene: one shape of the closed set, placed by an optional transform.
// Dispatch over the set happens in object.cpp and nowhere else.
#include <optional>
#include <string>
#include <variant>

#include "geometry/algebraic.h"
#include "geometry/basic_shapes.h"
#include "geometry/blob.h"
#include "geometry/cone.h"
#include "geometry/cylinder.h"
#include "geometry/ellipsoid.h"
#include "geometry/implicit.h"
#include "geometry/plane.h"
#include "geometry/polygon.h"
#include "geometry/polyhedron.h"
#include "geometry/prism.h"
#include "geometry/quadric.h"
#include "geometry/revolution.h"
#include "geometry/shape.h"
#include "geometry/slab.h"
#include "geometry/sphere.h"
#include "geometry/text.h"
#include "geometry/torus.h"
#include "math/transform.h"
#include "mesh/mesh.h"
#include "objects/csg_shape.h"
#include "objects/instance.h"
#include "volume/isosurface.h"

namespace raycast {

/// The closed set of shape types. Adding one here makes the compiler point at every place that
/// must handle it (object.cpp's dispatch, the loader's table).
using ShapeVariant =
    std::variant<Plane, Sphere, Box, Triangle, Parallelogram, Disk, Ellipsoid, Quadric, Cylinder,
                 Cone, Polygon, Slab, Polyhedron, Torus, Algebraic, Implicit, Revolution, MeshShape,
                 CsgShape, InstanceShape, Isosurface, Prism, Text, Blob>;

struct Object {
  ShapeVariant shape;
  std::optional<Transform> xf;      // object -> world; absent means the identity
  int material = -1;                // index into Scene::materials
  int entry = -1;                   // index of the top-level `objects` entry it came from
  bool casts_shadow = true;         // false: shadow rays pass through it (POV-Ray's no_shadow)
  bool seen_by_camera = true;       // false: camera rays pass through it (POV-Ray's no_image)
  bool seen_in_reflections = true;  // false: mirrored rays pass through it (no_reflection)
};

// World-space versions of the shape functions (geometry/shape.h): the ray goes to object space
// through the inverse transform (t unchanged), results come back to world space.
Aabb bounds(const Object& o);
bool intersect(const Object& o, const Ray& ray, LocalHit& hit);
bool occluded(const Object& o, const Ray& ray);
void spans(const Object& o, const Ray& ray, SpanList& out);
/// What a caller of surface() needs: everything, or the geometry only (p, its error, the
/// normals; u and v may be left 0), which spares shapes with a `surface_geometry` function their
/// atan2/acos parameterisation (the Whitted integrator asks for (u, v) only for image textures).
enum class SurfaceNeeds { kAll, kGeometry };
SurfaceInfo surface(const Object& o, const Ray& ray, const LocalHit& hit,
                    SurfaceNeeds needs = SurfaceNeeds::kAll);
/// surface() of a composite's part (a CSG leaf, an instance's prototype object) hit as `hit`,
/// its normal not flipped: the composite's own object flips it by hit.flip.
inline SurfaceInfo part_surface(const Object& part, const Ray& ray, const LocalHit& hit,
                                SurfaceNeeds needs) {
  LocalHit h = hit;
  h.flip = false;
  return surface(part, ray, h, needs);
}
bool contains(const Object& o, const Vec3& p);
bool is_closed(const Object& o);
/// The material index for a hit on o: the CSG leaf's or prototype object's own when it has one,
/// else o.material (which may be -1: the default material).
int material_of(const Object& o, const LocalHit& hit);
/// The scene-format key of the object's shape ("sphere", "mesh", ...).
const char* shape_name(const Object& o);

/// The ray in the object's own space (t is preserved: the direction is not renormalised).
inline Ray to_object_space(const Object& o, const Ray& ray) {
  if (!o.xf) return ray;
  return {o.xf->inverse_point(ray.o), o.xf->inverse_vector(ray.d), ray.tmin, ray.tmax};
}

}  // namespace raycast
