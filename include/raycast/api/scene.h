#pragma once
// raycast::Scene: build or load a scene, commit it, then query it from any number of threads
// (docs/library.md). The engine stays behind a pointer: no internal header leaks through here.
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raycast/api/types.h"

namespace raycast::api {

enum class CsgOp { kUnion, kIntersection, kDifference };

class Scene {
 public:
  /// An empty scene to build in code (add_*, then commit()).
  Scene();
  ~Scene();
  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// Loads and commits a scene file (YAML or JSON, docs/scene-format.md). Throws SceneError
  /// with file:line:column on a mistake, and SceneError with line 0 when it cannot be read.
  static Scene load(const std::string& path);
  /// Loads and commits a scene from text; `name` is used in errors, `dir` resolves mesh files.
  static Scene from_string(const std::string& text, const std::string& name = "<string>",
                           const std::string& dir = ".");

  // Building. Every add_* returns the new object's id (ids count up from 0 in call order) and
  // throws SceneError (file = the call's name) for bad parameters, or std::logic_error after
  // commit(). Shapes are in the object's own space; set_transform places them.

  /// Any shape of the scene format by its key ("sphere", "revolution", ...) and its fields as
  /// YAML or JSON flow text, e.g. add_shape("sphere", "{center: [0, 0, 0], radius: 1}").
  ObjectId add_shape(std::string_view key, std::string_view fields);
  /// A triangle mesh: `vertices` holds x, y, z per vertex, `triangles` three vertex indices per
  /// triangle (counter-clockwise seen from outside). Degenerate triangles are dropped.
  ObjectId add_mesh(std::span<const double> vertices, std::span<const std::uint32_t> triangles);
  ObjectId add_mesh(std::span<const float> vertices, std::span<const std::uint32_t> triangles);
  /// The mesh of a file (OBJ, PLY, STL, glTF).
  ObjectId add_mesh_file(const std::string& path);
  ObjectId add_plane(const Vec3d& normal, const Vec3d& point = {0, 0, 0});
  ObjectId add_sphere(const Vec3d& center, double radius);
  ObjectId add_box(const Vec3d& min, const Vec3d& max);
  ObjectId add_triangle(const Vec3d& a, const Vec3d& b, const Vec3d& c);
  ObjectId add_disk(const Vec3d& center, const Vec3d& normal, double radius,
                    double inner_radius = 0);
  /// A solid cylinder (capped) or its side only, from `from` to `to`.
  ObjectId add_cylinder(const Vec3d& from, const Vec3d& to, double radius, bool capped = true);
  /// A cone frustum from radius_from at `from` to radius_to at `to`.
  ObjectId add_cone(const Vec3d& from, const Vec3d& to, double radius_from, double radius_to,
                    bool capped = true);
  ObjectId add_ellipsoid(const Vec3d& center, const Vec3d& radii);
  /// A torus around the z axis through the origin.
  ObjectId add_torus(double major_radius, double minor_radius);
  /// The quadric x^T A x + b . x + c = 0 from its ten coefficients [a b c d e f g h i j] of
  /// a x^2 + b y^2 + c z^2 + d xy + e yz + f xz + g x + h y + i z + j, clipped to a box.
  ObjectId add_quadric(const std::array<double, 10>& coefficients, const Vec3d& bounds_min,
                       const Vec3d& bounds_max);
  /// The algebraic surface f(x, y, z) = 0 of a polynomial written as a formula, in a box.
  ObjectId add_algebraic(std::string_view equation, const Vec3d& bounds_min,
                         const Vec3d& bounds_max);
  /// The implicit surface f(x, y, z) = 0 of any formula, in a box.
  ObjectId add_implicit(std::string_view function, const Vec3d& bounds_min,
                        const Vec3d& bounds_max);
  /// The iso-surface of SPH particles (x, y, z per particle). Throws SceneError for bad
  /// parameters, and for a grid too large for memory (before allocating, with the bytes needed).
  ObjectId add_isosurface(std::span<const double> particles, const ParticleSurface& params);
  /// The iso-surface of a grid of values (counts[0] * counts[1] * counts[2] of them, x fastest).
  ObjectId add_isosurface(std::span<const float> values, const GridSurface& grid);
  /// A set operation over closed solids (shapes or CSG objects) that were added before; they
  /// become parts of the new object and stop being objects of their own.
  ObjectId add_csg(CsgOp op, std::span<const ObjectId> operands);
  /// Objects added before become one shared prototype (and stop being objects of their own);
  /// returns its id for add_instance.
  int add_prototype(std::span<const ObjectId> objects);
  /// A copy of a prototype placed by `transform`.
  ObjectId add_instance(int prototype, const Transform& transform);
  /// Places an object (object-to-world); replaces any earlier transform.
  void set_transform(ObjectId object, const Transform& transform);
  MaterialId add_material(const Material& material);
  void set_material(ObjectId object, MaterialId material);
  void add_light(const Light& light);
  void set_camera(const Camera& camera);
  /// Builds the acceleration structures. Afterwards the scene is immutable and every const
  /// member may be called from any number of threads at once.
  void commit();
  bool committed() const;

  // Queries (after commit; before it they throw std::logic_error). Rays outside the usable range
  // (NaN, zero or huge directions, tmin > tmax) answer "nothing".

  /// The number of top-level objects (ids are 0 .. object_count() - 1).
  int object_count() const;
  /// The scene-format key of an object's shape ("sphere", "mesh", "csg", "instance", ...).
  std::string shape_name(ObjectId object) const;
  /// Bounds of the finite objects: min then max.
  std::array<Vec3d, 2> bounds() const;

  SurfaceInfo intersect(const Ray& ray) const;
  bool occluded(const Ray& ray) const;
  /// Every boundary crossing in [tmin, tmax], sorted by t.
  std::vector<Crossing> intersect_all(const Ray& ray) const;

  // Batches: all cores (oneTBB), answers in input order.
  void intersect(std::span<const Ray> rays, std::span<SurfaceInfo> out) const;
  void intersect(const RayArray& rays, const HitColumns& out) const;
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> out) const;
  void occluded(const RayArray& rays, std::span<std::uint8_t> out) const;
  /// Crossings per ray (out has rays.count entries).
  void count_intersections(const RayArray& rays, std::span<std::int32_t> out) const;
  /// Every crossing of every ray: offsets (rays.count + 1 entries, ray i's crossings are
  /// [offsets[i], offsets[i + 1])) and the crossings themselves.
  void intersect_all(const RayArray& rays, std::vector<std::int64_t>& offsets,
                     std::vector<Crossing>& crossings) const;

  // Geometric queries over points (x, y, z each, n points). See docs/library.md.

  /// 1 where the point is inside or on a closed solid of the scene, else 0 (exact span parity).
  void occupancy(std::span<const double> points, std::span<std::uint8_t> out) const;
  /// The closest surface point over the objects that support distances (meshes, plane, sphere,
  /// box, ellipsoid, cylinder, cone, torus): point (3n), its object and triangle (-1 when not a
  /// mesh), distance (n). Throws NotImplementedError naming the first object's shape that has no
  /// distance. Null outputs are skipped.
  void closest_points(std::span<const double> points, double* closest, ObjectId* object,
                      std::int32_t* primitive, double* distance) const;
  /// Distance to the closest surface, negative inside a closed solid (by occupancy).
  void signed_distance(std::span<const double> points, std::span<double> out) const;

  /// Renders the scene from `camera` (or the scene's camera when absent).
  Image render(const Camera* camera, const RenderOptions& options) const;
  /// The width and height render() uses for RenderOptions' zero width and height.
  std::array<int, 2> image_size() const;
  /// Pixel (x, y)'s ray tree (docs/explain.md) as the JSON text of `raycast explain --json`:
  /// sample `sample` of the pixel at the scene's camera, `options`' width, height and samples
  /// overriding the scene's (0: the scene's; the integrator option is not used). Throws
  /// std::invalid_argument for a pixel or sample outside the image.
  std::string explain_json(int x, int y, const RenderOptions& options, int sample = 0) const;

  struct Impl;  // the engine behind the wall (opaque to users)

 private:
  std::unique_ptr<Impl> impl_;
  explicit Scene(std::unique_ptr<Impl> impl);
  const Impl& ready() const;
};

}  // namespace raycast::api
