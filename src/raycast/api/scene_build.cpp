// Loading and building raycast::api::Scene. Shapes built in code go through the scene format's
// own parsers (load/shape_parsers.h), so a shape means, and is checked, exactly as in a file.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "api/distance_index.h"
#include "api/impl.h"
#include "io/mesh_file.h"
#include "load/loader.h"
#include "load/shape_parsers.h"
#include "load/yaml_prescan.h"
#include "objects/csg_tree.h"
#include "volume/isosurface.h"
#include "volume/splat.h"

namespace raycast::api {

namespace {

// Numbers in generated YAML: 17 significant digits read back to the same double.
std::string num(double v) {
  if (std::isnan(v)) return ".nan";
  if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string vec(const Vec3d& v) {
  return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]";
}

// A YAML double-quoted scalar.
std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string bounds_fields(const Vec3d& lo, const Vec3d& hi) {
  return "bounds: {min: " + vec(lo) + ", max: " + vec(hi) + "}";
}

raycast::Color color(const Vec3d& c, const char* what) {
  if (!(c[0] >= 0 && c[1] >= 0 && c[2] >= 0) || !std::isfinite(c[0] + c[1] + c[2]))
    throw SceneError(std::string("add_material: ") + what + " must be finite and >= 0",
                     "add_material", 0, 0, std::string(what) + " must be finite and >= 0");
  return to_engine(c);
}

[[noreturn]] void bad(const std::string& call, const std::string& message) {
  throw SceneError(call + ": " + message, call, 0, 0, message);
}

}  // namespace

Scene::Impl::Impl() { scene.materials.emplace_back().name = "default"; }
Scene::Impl::~Impl() = default;

Scene::Scene() : impl_(std::make_unique<Impl>()) {}
Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

Scene Scene::load(const std::string& path) {
  auto impl = std::make_unique<Impl>();
  try {
    impl->scene = raycast::load_scene_file(path);
  } catch (const raycast::SceneError& e) {
    rethrow_scene_error(e);
  }
  impl->committed = true;
  return Scene(std::move(impl));
}

Scene Scene::from_string(const std::string& text, const std::string& name, const std::string& dir) {
  auto impl = std::make_unique<Impl>();
  try {
    impl->scene = raycast::load_scene_text(text, name, dir);
  } catch (const raycast::SceneError& e) {
    rethrow_scene_error(e);
  }
  impl->committed = true;
  return Scene(std::move(impl));
}

bool Scene::committed() const { return impl_ && impl_->committed; }

namespace {

void check_open(const Scene::Impl* impl, const char* call) {
  if (!impl) throw std::logic_error(std::string(call) + ": the scene was moved from");
  if (impl->committed)
    throw std::logic_error(std::string(call) + ": the scene is committed (immutable)");
}

ObjectId push(Scene::Impl& impl, raycast::ShapeVariant shape) {
  raycast::Object o;
  o.shape = std::move(shape);
  o.entry = static_cast<int>(impl.objects.size());
  impl.objects.push_back(std::move(o));
  impl.hidden.push_back(0);
  return static_cast<ObjectId>(impl.objects.size() - 1);
}

raycast::Object& object_at(Scene::Impl& impl, ObjectId id, const char* call) {
  if (id < 0 || static_cast<std::size_t>(id) >= impl.objects.size())
    bad(call, "no object " + std::to_string(id));
  if (impl.hidden[id]) bad(call, "object " + std::to_string(id) + " is part of another object");
  return impl.objects[id];
}

// Appends the solid `o` to `tree` as an operand (a leaf, or a CSG object's nodes and leaves,
// placed by o's transform) and returns its code.
std::int32_t append_operand(raycast::CsgTree& tree, const raycast::Object& o, const char* call) {
  if (const auto* csg = std::get_if<raycast::CsgShape>(&o.shape)) {
    const raycast::CsgTree& sub = *csg->tree;
    const auto node_base = static_cast<std::int32_t>(tree.nodes.size());
    const auto leaf_base = static_cast<std::int32_t>(tree.leaves.size());
    for (raycast::Object leaf : sub.leaves) {
      if (o.xf) leaf.xf = leaf.xf ? *o.xf * *leaf.xf : *o.xf;
      if (leaf.material < 0) leaf.material = o.material;
      tree.leaves.push_back(std::move(leaf));
    }
    for (const raycast::CsgNode& n : sub.nodes) {
      raycast::CsgNode copy;
      copy.op = n.op;
      for (const std::int32_t code : n.operands)
        copy.operands.push_back(code >= 0 ? code + node_base : code - leaf_base);
      tree.nodes.push_back(std::move(copy));
    }
    return node_base;
  }
  if (std::holds_alternative<raycast::InstanceShape>(o.shape))
    bad(call, "an instance cannot be a CSG operand");
  if (!raycast::is_closed(o))
    bad(call, std::string(raycast::shape_name(o)) +
                  " cannot be a CSG operand: it is not a closed "
                  "solid");
  tree.leaves.push_back(o);
  return raycast::csg_leaf_code(tree.leaves.size() - 1);
}

}  // namespace

ObjectId Scene::add_shape(std::string_view key, std::string_view fields) {
  check_open(impl_.get(), "add_shape");
  const std::string k(key);
  const std::string call = "add_" + k;
  const auto& parsers = raycast::shape_parsers();
  const auto it = parsers.find(k);
  if (it == parsers.end()) bad("add_shape", "unknown shape '" + k + "'");
  try {
    const raycast::SourceContext ctx{call, "."};
    const raycast::YamlDocument doc =
        raycast::parse_yaml(std::string(fields), call, raycast::kMaxNesting);
    const raycast::YamlNode node = doc.root();
    if (!node.IsMap()) raycast::fail_at(ctx, node, k + " needs a mapping of its fields");
    raycast::Fields f(ctx, node, k);
    raycast::ShapeVariant shape;
    try {
      shape = it->second(f);
    } catch (const std::invalid_argument& e) {
      raycast::fail_at(ctx, node, k + ": " + e.what());
    }
    f.finish();
    return push(*impl_, std::move(shape));
  } catch (const raycast::SceneError& e) {
    rethrow_scene_error(e);
  }
}

namespace {

template <class T>
ObjectId add_mesh_impl(Scene::Impl& impl, std::span<const T> vertices,
                       std::span<const std::uint32_t> triangles) {
  if (vertices.size() % 3 != 0) bad("add_mesh", "vertices must hold 3 numbers per vertex");
  if (triangles.size() % 3 != 0) bad("add_mesh", "triangles must hold 3 indices per triangle");
  std::vector<raycast::Vec3f> p(vertices.size() / 3);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p[i] = raycast::Vec3f(raycast::Vec3(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]));
    if (!raycast::is_finite(p[i]))
      bad("add_mesh", "vertex " + std::to_string(i) + " is not finite in float");
  }
  std::vector<std::array<std::uint32_t, 3>> t(triangles.size() / 3);
  for (std::size_t i = 0; i < t.size(); ++i)
    t[i] = {triangles[3 * i], triangles[3 * i + 1], triangles[3 * i + 2]};
  try {
    return push(impl, raycast::MeshShape{raycast::make_mesh(std::move(p), std::move(t))});
  } catch (const std::invalid_argument& e) {
    bad("add_mesh", e.what());
  }
}

}  // namespace

ObjectId Scene::add_mesh(std::span<const double> vertices,
                         std::span<const std::uint32_t> triangles) {
  check_open(impl_.get(), "add_mesh");
  return add_mesh_impl(*impl_, vertices, triangles);
}

ObjectId Scene::add_mesh(std::span<const float> vertices,
                         std::span<const std::uint32_t> triangles) {
  check_open(impl_.get(), "add_mesh");
  return add_mesh_impl(*impl_, vertices, triangles);
}

ObjectId Scene::add_mesh_file(const std::string& path) {
  return add_shape("mesh", "{file: " + quoted(path) + "}");
}

ObjectId Scene::add_plane(const Vec3d& normal, const Vec3d& point) {
  return add_shape("plane", "{normal: " + vec(normal) + ", point: " + vec(point) + "}");
}

ObjectId Scene::add_sphere(const Vec3d& center, double radius) {
  return add_shape("sphere", "{center: " + vec(center) + ", radius: " + num(radius) + "}");
}

ObjectId Scene::add_box(const Vec3d& min, const Vec3d& max) {
  return add_shape("box", "{min: " + vec(min) + ", max: " + vec(max) + "}");
}

ObjectId Scene::add_triangle(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return add_shape("triangle", "{vertices: [" + vec(a) + ", " + vec(b) + ", " + vec(c) + "]}");
}

ObjectId Scene::add_disk(const Vec3d& center, const Vec3d& normal, double radius,
                         double inner_radius) {
  return add_shape("disk", "{center: " + vec(center) + ", normal: " + vec(normal) + ", radius: " +
                               num(radius) + ", inner_radius: " + num(inner_radius) + "}");
}

ObjectId Scene::add_cylinder(const Vec3d& from, const Vec3d& to, double radius, bool capped) {
  return add_shape("cylinder", "{from: " + vec(from) + ", to: " + vec(to) + ", radius: " +
                                   num(radius) + ", capped: " + (capped ? "true" : "false") + "}");
}

ObjectId Scene::add_cone(const Vec3d& from, const Vec3d& to, double radius_from, double radius_to,
                         bool capped) {
  return add_shape("cone", "{from: " + vec(from) + ", to: " + vec(to) + ", radius_from: " +
                               num(radius_from) + ", radius_to: " + num(radius_to) +
                               ", capped: " + (capped ? "true" : "false") + "}");
}

ObjectId Scene::add_ellipsoid(const Vec3d& center, const Vec3d& radii) {
  return add_shape("ellipsoid", "{center: " + vec(center) + ", radii: " + vec(radii) + "}");
}

ObjectId Scene::add_torus(double major_radius, double minor_radius) {
  return add_shape("torus", "{major_radius: " + num(major_radius) +
                                ", minor_radius: " + num(minor_radius) + "}");
}

ObjectId Scene::add_quadric(const std::array<double, 10>& c, const Vec3d& lo, const Vec3d& hi) {
  std::string list = "[";
  for (int i = 0; i < 10; ++i) list += (i ? ", " : "") + num(c[i]);
  return add_shape("quadric", "{coefficients: " + list + "], " + bounds_fields(lo, hi) + "}");
}

ObjectId Scene::add_algebraic(std::string_view equation, const Vec3d& lo, const Vec3d& hi) {
  return add_shape("algebraic",
                   "{equation: " + quoted(equation) + ", " + bounds_fields(lo, hi) + "}");
}

ObjectId Scene::add_implicit(std::string_view function, const Vec3d& lo, const Vec3d& hi) {
  return add_shape("implicit",
                   "{function: " + quoted(function) + ", " + bounds_fields(lo, hi) + "}");
}

ObjectId Scene::add_isosurface(std::span<const double> particles, const ParticleSurface& params) {
  const char* call = "add_isosurface";
  check_open(impl_.get(), call);
  if (particles.size() % 3 != 0) bad(call, "particles must hold x, y, z per particle");
  std::vector<raycast::Vec3> points(particles.size() / 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = {particles[3 * i], particles[3 * i + 1], particles[3 * i + 2]};
  raycast::SplatParams p;
  p.h = params.smoothing_length;
  p.rest_density = params.rest_density;
  p.particle_volume = params.particle_volume;
  if (params.domain)
    p.domain = raycast::Aabb{to_engine((*params.domain)[0]), to_engine((*params.domain)[1])};
  p.resolution = params.resolution;
  p.cell_size = params.cell_size;
  const double iso = params.iso.value_or(params.rest_density / 2);
  raycast::ScalarGrid grid;
  try {
    grid = raycast::splat_particles(points, p);
    return push(*impl_, raycast::make_isosurface(std::move(grid), iso));
  } catch (const std::invalid_argument& e) {
    bad(call, e.what());
  } catch (const std::length_error& e) {
    bad(call, e.what());
  }
}

ObjectId Scene::add_isosurface(std::span<const float> values, const GridSurface& g) {
  const char* call = "add_isosurface";
  check_open(impl_.get(), call);
  std::array<std::uint64_t, 3> n{};
  for (int a = 0; a < 3; ++a) {
    if (g.counts[a] < 2) bad(call, "a grid needs at least 2 nodes per axis");
    n[a] = static_cast<std::uint64_t>(g.counts[a]);
  }
  if (values.size() / n[0] / n[1] != n[2] || values.size() % (n[0] * n[1]) != 0)
    bad(call, "the grid holds " + std::to_string(values.size()) + " values, its counts need " +
                  std::to_string(n[0] * n[1] * n[2]));
  try {
    raycast::check_grid_fits(n);  // the iso-surface's tables besides the copy of the values
    raycast::ScalarGrid grid;
    grid.n = g.counts;
    grid.lo = to_engine(g.origin);
    grid.cell = to_engine(g.spacing);
    grid.v.assign(values.begin(), values.end());
    return push(*impl_, raycast::make_isosurface(std::move(grid), g.iso));
  } catch (const std::invalid_argument& e) {
    bad(call, e.what());
  } catch (const std::length_error& e) {
    bad(call, e.what());
  }
}

ObjectId Scene::add_csg(CsgOp op, std::span<const ObjectId> operands) {
  check_open(impl_.get(), "add_csg");
  if (operands.empty()) bad("add_csg", "needs at least one operand");
  raycast::CsgTree tree;
  tree.nodes.emplace_back();
  tree.nodes[0].op = op == CsgOp::kIntersection ? raycast::CsgOp::kIntersection
                     : op == CsgOp::kDifference ? raycast::CsgOp::kDifference
                                                : raycast::CsgOp::kUnion;
  for (const ObjectId id : operands) {
    const raycast::Object& o = object_at(*impl_, id, "add_csg");
    const std::int32_t code = append_operand(tree, o, "add_csg");
    tree.nodes[0].operands.push_back(code);
  }
  std::vector<char> seen(impl_->objects.size(), 0);
  for (const ObjectId id : operands) {
    if (seen[id]) bad("add_csg", "object " + std::to_string(id) + " is given twice");
    seen[id] = 1;
  }
  std::shared_ptr<const raycast::CsgTree> frozen;
  try {
    frozen = raycast::finish_csg_tree(std::move(tree));
  } catch (const std::invalid_argument& e) {
    bad("add_csg", e.what());
  }
  for (const ObjectId id : operands) impl_->hidden[id] = 1;
  return push(*impl_, raycast::CsgShape{std::move(frozen)});
}

int Scene::add_prototype(std::span<const ObjectId> objects) {
  check_open(impl_.get(), "add_prototype");
  if (objects.empty()) bad("add_prototype", "needs at least one object");
  std::vector<raycast::Object> parts;
  for (const ObjectId id : objects) {
    const raycast::Object& o = object_at(*impl_, id, "add_prototype");
    if (std::holds_alternative<raycast::InstanceShape>(o.shape))
      bad("add_prototype", "an instance cannot be part of a prototype");
    parts.push_back(o);
  }
  std::shared_ptr<const raycast::Prototype> proto;
  try {
    proto = raycast::make_prototype(std::move(parts));
  } catch (const std::invalid_argument& e) {
    bad("add_prototype", e.what());
  }
  for (const ObjectId id : objects) impl_->hidden[id] = 1;
  impl_->prototypes.push_back(std::move(proto));
  return static_cast<int>(impl_->prototypes.size() - 1);
}

ObjectId Scene::add_instance(int prototype, const Transform& transform) {
  check_open(impl_.get(), "add_instance");
  if (prototype < 0 || static_cast<std::size_t>(prototype) >= impl_->prototypes.size())
    bad("add_instance", "no prototype " + std::to_string(prototype));
  const raycast::Transform xf = to_engine(transform, "add_instance");
  const ObjectId id = push(*impl_, raycast::InstanceShape{impl_->prototypes[prototype]});
  if (!xf.is_identity()) impl_->objects[id].xf = xf;
  return id;
}

void Scene::set_transform(ObjectId object, const Transform& transform) {
  check_open(impl_.get(), "set_transform");
  raycast::Object& o = object_at(*impl_, object, "set_transform");
  const raycast::Transform xf = to_engine(transform, "set_transform");
  if (xf.is_identity())
    o.xf.reset();
  else
    o.xf = xf;
}

MaterialId Scene::add_material(const Material& m) {
  check_open(impl_.get(), "add_material");
  raycast::Material e;
  e.name = "material " + std::to_string(impl_->scene.materials.size());
  e.color = color(m.color, "color");
  e.has_checker = m.checker;
  e.checker.c0 = color(m.checker_colors[0], "checker_colors[0]");
  e.checker.c1 = color(m.checker_colors[1], "checker_colors[1]");
  if (!(m.checker_scale > 0) || !std::isfinite(m.checker_scale))
    bad("add_material", "checker_scale must be finite and > 0");
  e.checker.scale = m.checker_scale;
  for (const double v : {m.ambient, m.diffuse, m.specular, m.shininess})
    if (!(v >= 0) || !std::isfinite(v))
      bad("add_material", "ambient, diffuse, specular and shininess must be finite and >= 0");
  for (const double v : {m.reflection, m.transmission})
    if (!(v >= 0 && v <= 1)) bad("add_material", "reflection and transmission must be in [0, 1]");
  if (!(m.ior > 0) || !std::isfinite(m.ior)) bad("add_material", "ior must be finite and > 0");
  e.ambient = m.ambient;
  e.diffuse = m.diffuse;
  e.specular = m.specular;
  e.shininess = m.shininess;
  e.reflection = m.reflection;
  e.transmission = m.transmission;
  e.ior = m.ior;
  e.fresnel = m.fresnel;
  impl_->scene.materials.push_back(std::move(e));
  return static_cast<MaterialId>(impl_->scene.materials.size() - 1);
}

void Scene::set_material(ObjectId object, MaterialId material) {
  check_open(impl_.get(), "set_material");
  raycast::Object& o = object_at(*impl_, object, "set_material");
  if (material < 0 || static_cast<std::size_t>(material) >= impl_->scene.materials.size())
    bad("set_material", "no material " + std::to_string(material));
  o.material = material;
}

void Scene::add_light(const Light& l) {
  check_open(impl_.get(), "add_light");
  raycast::Light e;
  e.type = static_cast<raycast::LightType>(static_cast<int>(l.type));
  e.color = color(l.color, "light color");
  if (!(l.intensity >= 0) || !std::isfinite(l.intensity))
    bad("add_light", "intensity must be finite and >= 0");
  e.intensity = l.intensity;
  e.position = to_engine(l.position);
  if (!raycast::is_finite(e.position)) bad("add_light", "position must be finite");
  const raycast::Vec3 d = to_engine(l.direction);
  if (!raycast::is_finite(d) || raycast::length_squared(d) == 0)
    bad("add_light", "direction must be finite and non-zero");
  e.direction = raycast::normalize(d);
  if (!(l.angle > 0 && l.angle < 180)) bad("add_light", "angle must be in (0, 180)");
  e.angle = l.angle;
  e.falloff = l.falloff;
  if (l.type == Light::Type::kSphere && !(l.radius > 0 && std::isfinite(l.radius)))
    bad("add_light", "a sphere light needs a finite radius > 0");
  e.radius = l.radius;
  if (l.samples < 1 || l.samples > 4096) bad("add_light", "samples must be in [1, 4096]");
  e.samples = l.samples;
  e.attenuation =
      l.inverse_square ? raycast::Attenuation::kInverseSquare : raycast::Attenuation::kNone;
  impl_->scene.lights.push_back(e);
}

void Scene::set_camera(const Camera& c) {
  check_open(impl_.get(), "set_camera");
  raycast::CameraDesc e;
  e.type = c.orthographic ? raycast::CameraType::kOrthographic : raycast::CameraType::kPerspective;
  e.position = to_engine(c.position);
  e.look_at = to_engine(c.look_at);
  e.up = to_engine(c.up);
  if (!raycast::is_finite(e.position) || !raycast::is_finite(e.look_at) ||
      !raycast::is_finite(e.up))
    bad("set_camera", "position, look_at and up must be finite");
  if (raycast::length_squared(e.look_at - e.position) == 0)
    bad("set_camera", "look_at must differ from position");
  if (raycast::length_squared(raycast::cross(e.look_at - e.position, e.up)) == 0)
    bad("set_camera", "up must not be parallel to the viewing direction");
  if (!c.orthographic && !(c.fov > 0 && c.fov < 180)) bad("set_camera", "fov must be in (0, 180)");
  if (c.orthographic && !(c.height > 0 && std::isfinite(c.height)))
    bad("set_camera", "height must be finite and > 0");
  e.fov = c.fov;
  e.height = c.height;
  impl_->scene.camera = e;
}

void Scene::commit() {
  check_open(impl_.get(), "commit");
  Impl& impl = *impl_;
  impl.scene.source = "<code>";
  impl.scene.entries = static_cast<int>(impl.objects.size());
  impl.scene.objects.clear();
  for (std::size_t i = 0; i < impl.objects.size(); ++i) {
    if (impl.hidden[i]) continue;
    raycast::Object o = impl.objects[i];
    if (o.material < 0) o.material = 0;
    impl.scene.objects.push_back(std::move(o));
  }
  impl.scene.build();
  impl.committed = true;
}

}  // namespace raycast::api
