#include "load/pov_loader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "geometry/prism_spline.h"
#include "io/scene_file.h"
#include "load/formula_noise_registration.h"
#include "load/pov_textures.h"
#include "load/text_shape.h"
#include "objects/csg_tree.h"
#include "pov/checker_grid.h"
#include "pov/ini_file.h"
#include "pov/interpreter.h"
#include "pov/pov_transform.h"
#include "pov/yaml_writer.h"

namespace raycast {

namespace {

using pov::Node;
using pov::XformOp;

PrismSpline prism_spline(const std::string& pov_name) {
  if (pov_name == "quadratic_spline") return PrismSpline::kQuadratic;
  if (pov_name == "cubic_spline") return PrismSpline::kCubic;
  if (pov_name == "bezier_spline") return PrismSpline::kBezier;
  return PrismSpline::kLinear;
}

// Builds the engine's scene from the interpreted description. POV-Ray's frame is left-handed
// when (up x direction) . right > 0 (the default camera): then z is negated everywhere, which
// shows the same picture in raycast's right-handed frame.
class Builder {
 public:
  // `in_pov_frame` builds objects in the scene's own (left-handed) coordinates, unmirrored:
  // for the answers of trace and the other functions of objects.
  Builder(const pov::PovScene& s, Scene& scene, bool strict, bool in_pov_frame = false)
      : s_(s), scene_(scene), strict_(strict) {
    const pov::Camera& c = s.camera;
    mirror_ = !in_pov_frame && dot(cross(c.up, c.direction), c.right) > 0;
    const double g = s.settings.assumed_gamma;
    gamma_ = s.settings.gamma_given && g != 1 ? (g == 0 ? -1 : g) : 1;
  }

  void run() {
    scene_.materials.push_back(Material{});  // materials[0]: the default
    camera();
    scene_.render.max_depth = std::max(0, s_.max_trace_level - 1);
    scene_.render.background = rgb(s_.background);
    atmosphere();
    scene_.render.ambient = rgb(s_.ambient_light);
    if (s_.adc_bailout) scene_.render.bailout = *s_.adc_bailout;
    if (s_.settings.width > 0) scene_.image.width = s_.settings.width;
    if (s_.settings.height > 0) scene_.image.height = s_.settings.height;
    if (s_.settings.antialias_depth > 0) {
      scene_.render.antialias.method = AntialiasMethod::kNeighbour;
      scene_.render.antialias.depth = s_.settings.antialias_depth;
      scene_.render.antialias.threshold = s_.settings.antialias_threshold;
    }
    scene_.objects.reserve(s_.objects.size());
    std::vector<Object> out;
    for (const Node& n : s_.objects) {
      const int entry = scene_.entries;
      out.clear();
      add(n, nullptr, Transform(), std::nullopt, entry, out);
      if (out.empty()) continue;
      ++scene_.entries;
      scene_.marks.entries.push_back({n.pos.file == 0 ? n.pos.line : 0, n.pos.column});
      if (!n.name.empty()) {
        scene_.marks.entry_names.resize(std::size_t(scene_.entries));
        scene_.marks.entry_names.back() = n.name;
      }
      for (Object& o : out) scene_.objects.push_back(std::move(o));
    }
  }

  /// The engine objects of one described object (lights dropped), for the functions of
  /// objects a scene calls while it is read.
  std::vector<Object> objects_of(const Node& n) {
    scene_.materials.assign(1, Material{});
    std::vector<Object> out;
    add(n, nullptr, Transform(), std::nullopt, 0, out);
    return out;
  }

 private:
  [[noreturn]] void fail_at(const pov::Pos& p, const std::string& m) const {
    pov::fail(s_.sources, p, m);
  }
  Vec3 m(const Vec3& v) const { return mirror_ ? Vec3{v.x, v.y, -v.z} : v; }
  // A point of a shape: mirrored, and moved by the checker offset of the shape being built.
  Vec3 pt(const Vec3& v) const { return m(v) + shift_; }

  // A colour of the scene in linear light: POV-Ray 3.7 with assumed_gamma G treats the scene's
  // colours as encoded with that gamma (srgb: the sRGB curve).
  double linear(double c) const {
    if (gamma_ == 1 || c <= 0) return c;
    if (gamma_ < 0) return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    return std::pow(c, gamma_);
  }
  Color rgb(const pov::Colour& c) const { return {linear(c.r), linear(c.g), linear(c.b)}; }

  // The sky sphere and the fogs: their transformations and the mirror map raycast's world to
  // the sky's and each fog's own space; colours made linear as every other colour.
  void atmosphere() {
    if (!s_.sky_sphere && s_.fogs.empty() && s_.rainbows.empty()) return;
    auto a = std::make_shared<Atmosphere>();
    const Transform world = mirror_ ? Transform::scale({1, 1, -1}) : Transform();
    if (s_.sky_sphere) {
      SkySphere sky;
      for (const texture::Pigment& p : s_.sky_sphere->pigments)
        sky.layers.push_back(*pov_textures_.pigment(p));
      const pov::Colour& e = s_.sky_sphere->emission;
      sky.emission = {e.r, e.g, e.b};
      sky.to_sky = own_space(s_.sky_sphere->xforms) * world;
      a->sky = std::move(sky);
    }
    for (const pov::Fog& f : s_.fogs) {
      Fog fog;
      fog.kind = f.type == 2 ? Fog::Kind::kGround : Fog::Kind::kConstant;
      fog.color = rgb(f.colour);
      fog.filter = f.colour.filter;
      fog.transmit = f.colour.transmit;
      fog.distance = f.distance;
      fog.offset = f.offset;
      fog.alt = f.alt;
      fog.up = normalize(f.up);
      fog.turbulence = f.turbulence;
      fog.turb_depth = f.turb_depth;
      fog.to_fog = own_space(f.xforms) * world;
      a->fogs.push_back(fog);
    }
    for (const pov::Rainbow& r : s_.rainbows) a->rainbows.push_back(rainbow(r));
    scene_.render.atmosphere = std::move(a);
  }
  Rainbow rainbow(const pov::Rainbow& r) const {
    Rainbow out;
    out.direction = normalize(m(r.direction));
    out.up = m(r.up);
    out.angle = r.angle;
    out.width = r.width;
    out.distance = r.distance;
    out.jitter = r.jitter;
    out.arc_angle = r.arc_angle;
    out.falloff_angle = r.falloff_angle;
    for (const pov::MapEntry& e : r.map)
      out.colors.push_back({e.at, {rgb(e.colour), e.colour.filter, e.colour.transmit}});
    return out;
  }
  // The inverse of a block's transformations (POV-Ray's world -> the block's own space); the
  // interpreter refused singular ones.
  static Transform own_space(const std::vector<XformOp>& ops) {
    return pov::pov_transform(ops).value_or(Transform()).inverse();
  }

  void camera() {
    const pov::Camera& c = s_.camera;
    CameraDesc d;
    d.position = m(c.location);
    d.look_at = m(c.location + c.direction);
    d.up = m(c.up);
    // POV-Ray's own vectors decide the view (aspect from right's length, skewed frames); the
    // position, look_at, up and fov beside them are what a viewer that moves the camera uses.
    d.frame = CameraFrame{m(c.direction), m(c.right), m(c.up)};
    static const CameraType kTypes[] = {CameraType::kPerspective, CameraType::kOrthographic,
                                        CameraType::kFisheye,     CameraType::kUltraWideAngle,
                                        CameraType::kOmnimax,     CameraType::kPanoramic,
                                        CameraType::kCylinder,    CameraType::kSpherical};
    d.type = kTypes[c.kind];
    d.angle = c.angle;
    d.vertical_angle = c.vertical_angle;
    d.cylinder = c.cylinder;
    if (c.kind == pov::Camera::Orthographic) {
      d.height = length(c.up);
    } else {
      // The vertical field of view from up's length against direction's.
      d.fov = 2 * std::atan(0.5 * length(c.up) / length(c.direction)) * 180 / std::numbers::pi;
      if (c.kind == pov::Camera::Perspective && !(d.fov > 0 && d.fov < 180))
        fail_at(c.pos, "the camera's field of view is not in (0, 180)");
      d.fov = std::clamp(d.fov, 1e-6, 179.0);
    }
    scene_.camera = d;
    scene_.marks.camera = {c.pos.file == 0 ? c.pos.line : 0, c.pos.column};
    // POV-Ray's image has right's length over up's as its aspect ratio, so a scene asks for
    // that ratio at 480 lines unless the size is given.
    const double aspect = length(c.right) / length(c.up);
    if (s_.settings.width == 0 && aspect > 0.1 && aspect < 10) {
      scene_.image.height = 480;
      scene_.image.width = std::max(1, static_cast<int>(std::lround(480 * aspect)));
    }
  }

  void light(const pov::Light& l, const std::optional<Transform>& xf) {
    Light out;
    auto place = [&](const Vec3& p) { return xf ? xf->point(m(p)) : m(p); };
    auto turn = [&](const Vec3& v) { return xf ? xf->vector(m(v)) : m(v); };
    out.color = rgb(l.colour);
    out.position = place(l.position);
    out.shadows = !l.shadowless;
    if (l.fade_distance > 0 && l.fade_power > 0) {
      out.attenuation = Attenuation::kFade;
      out.fade_distance = l.fade_distance;
      out.fade_power = l.fade_power;
    }
    const Vec3 axis = place(l.point_at) - out.position;
    if (l.kind != pov::Light::Point || l.parallel) {
      if (!(length(axis) > 0)) fail_at(l.pos, "the light's point_at is its position");
      out.direction = axis / length(axis);
    }
    // POV-Ray's cones: spotlight angles with a smooth edge over the cosine, times
    // cos^tightness; a cylinder light's radius and falloff are distances from its axis.
    out.angle = l.falloff;
    out.falloff = l.falloff - l.radius;
    out.tightness = l.tightness;
    out.edge = SpotEdge::kCosine;
    if (l.parallel) {
      out.type = LightType::kDirectional;
      out.bounded = true;
    } else if (l.area) {
      out.type = LightType::kArea;
      out.axis1 = turn(l.axis1);
      out.axis2 = turn(l.axis2);
      out.size1 = l.size1;
      out.size2 = l.size2;
      out.adaptive = l.adaptive;
      out.jitter = l.jitter;
      out.circular = l.circular;
      out.orient = l.orient;
      out.spot = l.kind == pov::Light::Spot;
    } else if (l.kind == pov::Light::Spot) {
      out.type = LightType::kSpot;
    } else if (l.kind == pov::Light::Cylinder) {
      out.type = LightType::kCylinder;
    }
    scene_.lights.push_back(out);
    scene_.marks.lights.push_back({l.pos.file == 0 ? l.pos.line : 0, l.pos.column});
  }

  // POV-Ray's world from a node's texture space: the parent's placement (in POV-Ray's frame) and
  // the node's transformations written after its texture.
  Transform texture_frame(const Node& n, const std::optional<Transform>& parent) const {
    const std::size_t at = std::min(n.texture_at, n.xforms.size());
    const std::vector<XformOp> after(n.xforms.begin() + static_cast<std::ptrdiff_t>(at),
                                     n.xforms.end());
    const std::optional<Transform> own = pov::pov_transform(after);
    if (!own) fail_at(n.pos, "the matrix cannot be inverted");
    return parent ? to_pov(*parent) * *own : *own;
  }
  // A transform of raycast's frame as seen in POV-Ray's (the mirror on both sides).
  Transform to_pov(const Transform& t) const {
    if (!mirror_) return t;
    const Transform flip = Transform::scale({1, 1, -1});
    return flip * t * flip;
  }

  // A material of the texture system for one object: its stack and the map from the object's
  // space to the texture's (POV-Ray's world from raycast's, then the texture frame's inverse).
  int textured_material(const pov::Texture& t, const Transform& frame,
                        const std::optional<Transform>& object) {
    Material mat;
    auto it = stacks_.find(&t);
    if (it == stacks_.end()) it = stacks_.emplace(&t, pov_textures_.stack(t)).first;
    mat.texture = it->second;
    mat.color = rgb(t.pigment.c0);
    set_interior(t, mat);
    const Transform world = mirror_ ? Transform::scale({1, 1, -1}) : Transform();
    mat.texture_transform = frame.inverse() * (object ? world * *object : world);
    mat.name = t.name;
    if (mat.name.empty()) mat.name.append("m").append(std::to_string(scene_.materials.size()));
    scene_.materials.push_back(std::move(mat));
    return static_cast<int>(scene_.materials.size()) - 1;
  }

  // The interior's ior and fade (POV-Ray 3.1's finish items where the interior has none).
  void set_interior(const pov::Texture& t, Material& mat) const {
    const pov::Interior in = t.interior.value_or(pov::Interior{});
    if (const std::optional<double> ior = in.ior ? in.ior : t.finish.ior) mat.ior = *ior;
    const bool own = in.fade_distance != 0 || in.fade_power != 0;
    mat.fade_distance = own ? in.fade_distance : t.finish.fade_distance;
    mat.fade_power = own ? in.fade_power : t.finish.fade_power;
    mat.fade_color = rgb(in.fade_color);
    mat.dispersion = in.dispersion;
    mat.dispersion_samples = in.dispersion_samples;
  }

  int material(const pov::Texture& t, const Transform& frame,
               const std::optional<Transform>& object) {
    if (needs_texture_system(t)) return textured_material(t, frame, object);
    Material mat;
    const pov::Pigment& p = t.pigment;
    const pov::Finish& f = t.finish;
    const double tr = std::min(1.0, p.c0.filter + p.c0.transmit);
    if (p.checker) {
      // Negating z swaps the parity of floor(z): swap the colours back.
      mat.has_checker = true;
      mat.checker.c0 = rgb(mirror_ ? p.c1 : p.c0);
      mat.checker.c1 = rgb(mirror_ ? p.c0 : p.c1);
      mat.checker.scale = p.scale;
    } else {
      mat.color = rgb(p.c0);
    }
    double specular = f.phong, shininess = f.phong_size;
    if (f.specular > 0) {
      // Blinn's (n.h)^(1/roughness) as a Phong lobe: the half-vector's angle is about half the
      // mirror direction's, so the exponent is a quarter.
      if (f.phong == 0) shininess = 1 / (4 * f.roughness);
      specular += f.specular;
    }
    // POV-Ray weighs a surface's own ambient and diffuse light by its opacity.
    const double opacity = 1 - tr;
    mat.ambient = f.ambient * opacity;
    mat.diffuse = f.diffuse * opacity;
    mat.specular = specular;
    mat.shininess = std::max(shininess, 1e-3);
    mat.reflection = std::min(1.0, f.reflection);
    mat.transmission = tr;
    mat.fresnel = f.fresnel && tr > 0;
    set_interior(t, mat);
    const MaterialKey key = {mat.color.x,       mat.color.y,
                             mat.color.z,       double(mat.has_checker),
                             mat.checker.c0.x,  mat.checker.c0.y,
                             mat.checker.c0.z,  mat.checker.c1.x,
                             mat.checker.c1.y,  mat.checker.c1.z,
                             mat.checker.scale, mat.ambient,
                             mat.diffuse,       mat.specular,
                             mat.shininess,     mat.reflection,
                             mat.transmission,  double(mat.fresnel),
                             mat.ior,           mat.fade_distance,
                             mat.fade_power,    mat.fade_color.x,
                             mat.fade_color.y,  mat.fade_color.z,
                             mat.dispersion,    double(mat.dispersion_samples)};
    const auto it = materials_.find(key);
    if (it != materials_.end()) return it->second;
    mat.name = t.name;
    if (mat.name.empty()) mat.name.append("m").append(std::to_string(scene_.materials.size()));
    scene_.materials.push_back(mat);
    const int index = static_cast<int>(scene_.materials.size()) - 1;
    materials_[key] = index;
    return index;
  }

  // The node's own transformations (object -> its parent), in raycast's frame.
  std::optional<Transform> own_transform(const Node& n, bool axial, const Vec3& shift = {}) const {
    Transform t;
    bool any = false;
    auto then = [&](const Transform& x) {
      t = any ? x * t : x;
      any = true;
    };
    if (shift.x != 0) then(Transform::translate(shift * -1.0));
    // Torus, lathe and sor are about y in POV-Ray, about z in raycast: turn z onto y. (They are
    // symmetric about their axis, so mirroring z leaves this turn as it is.)
    if (axial) then(Transform::rotate({1, 0, 0}, -90));
    const double s = mirror_ ? -1 : 1;
    for (const XformOp& x : n.xforms) {
      switch (x.kind) {
        case XformOp::Translate:
          then(Transform::translate(m(x.v)));
          break;
        case XformOp::Scale:
          then(Transform::scale(x.v));
          break;
        case XformOp::Rotate: {
          // POV-Ray turns about x, then y, then z; conjugated by the mirror, the x and y
          // angles change sign.
          const double a[3] = {x.v.x * s, x.v.y * s, x.v.z};
          const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
          for (int i = 0; i < 3; ++i)
            if (a[i] != 0) then(Transform::rotate(axes[i], a[i]));
          break;
        }
        case XformOp::Matrix: {
          // POV-Ray's rows act on row vectors: p' = x r0 + y r1 + z r2 + t.
          const double sign[4] = {1, 1, s, 1};
          Mat4 mm;
          for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
              const double v = i == 3   ? (j == 3 ? 1 : 0)
                               : j == 3 ? x.m[static_cast<std::size_t>(9 + i)]
                                        : x.m[static_cast<std::size_t>(3 * j + i)];
              mm.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
                  v * sign[i] * sign[j];
            }
          const std::optional<Transform> tm = Transform::from_matrix(mm);
          if (!tm) fail_at(n.pos, "the matrix cannot be inverted");
          then(*tm);
          break;
        }
      }
    }
    if (!any) return std::nullopt;
    return t;
  }

  static std::optional<Transform> compose(const std::optional<Transform>& parent,
                                          const std::optional<Transform>& own) {
    if (!parent) return own;
    if (!own) return parent;
    return *parent * *own;
  }

  Aabb box_of(const std::array<Vec3, 2>& b) const {
    Vec3 lo = b[0], hi = b[1];
    if (mirror_) std::swap(lo.z, hi.z), lo.z = -lo.z, hi.z = -hi.z;
    return {lo, hi};
  }

  std::string polynomial_text(const Node& n) const {
    std::ostringstream e;
    e.precision(17);
    bool first = true;
    for (const auto& [k, c] : n.terms) {
      const double v = mirror_ && k[2] % 2 ? -c : c;
      if (v == 0) continue;
      e << (first ? "(" : " + (") << v << ")";
      first = false;
      const char* var[3] = {"x", "y", "z"};
      for (int i = 0; i < 3; ++i)
        if (k[static_cast<std::size_t>(i)])
          e << "*" << var[i] << "^" << k[static_cast<std::size_t>(i)];
    }
    return first ? "0" : e.str();
  }

  // A blob from its component nodes: each component's own transformations place its field; the
  // checker offset moves the whole blob.
  Blob blob(const Node& n, const std::vector<int>* materials = nullptr) {
    std::vector<BlobComponent> components;
    components.reserve(n.children.size());
    for (const Node& c : n.children) {
      BlobComponent b;
      if (materials) b.material = (*materials)[components.size()];
      b.cylinder = c.kind == Node::Cylinder;
      b.radius = c.values[0];
      b.strength = c.values[1];
      b.xf = own_transform(c, false);
      b.a = b.xf ? m(c.points[0]) : pt(c.points[0]);
      b.b = b.cylinder ? (b.xf ? m(c.points[1]) : pt(c.points[1])) : b.a;
      if (b.xf && shift_ != Vec3{0, 0, 0}) b.xf = Transform::translate(shift_) * *b.xf;
      components.push_back(b);
    }
    return make_blob(n.values[0], std::move(components));
  }

  // POV-Ray blends the textures of a blob's components by their fields at each point; raycast
  // takes the strongest component's there (blob_material), and the blob's own (or inherited)
  // texture where that component has none: else its first component's.
  const pov::Texture* blob_texture(const Node& n, const pov::Texture* own) {
    const pov::Texture* first = nullptr;
    for (const Node& c : n.children)
      if (c.texture) {
        first = &*c.texture;
        warn(c.pos, "blended textures of blob components",
             "each point takes the texture of the component whose field is strongest there",
             "not blended");
        break;
      }
    return own ? own : first;
  }

  // The blob rebuilt with a material for each component that has a texture of its own, in the
  // frame of the component's transformations within the blob.
  void blob_materials(const Node& n, Object& o) {
    std::vector<int> materials;
    bool any = false;
    for (const Node& c : n.children) {
      materials.push_back(
          c.texture ? material(*c.texture, texture_frame(c, o.xf), csg_world_ ? csg_world_ : o.xf)
                    : -1);
      any = any || c.texture;
    }
    if (any) o.shape = blob(n, &materials);
  }

  // The shape of a primitive node, or nothing (with a warning) when raycast cannot build it.
  std::optional<ShapeVariant> shape(const Node& n, bool& axial) {
    axial = false;
    switch (n.kind) {
      case Node::Sphere:
        return make_sphere(pt(n.points[0]), n.values[0]);
      case Node::Box:
        return make_box(box_of({n.points[0], n.points[1]}).lo + shift_,
                        box_of({n.points[0], n.points[1]}).hi + shift_);
      case Node::Plane: {
        const Vec3 nn = n.points[0];
        const double l = length(nn);
        if (!(l > 0)) fail_at(n.pos, "a plane's normal must not be zero");
        // POV-Ray's distance is measured along the normal made unit length.
        return make_plane(m(nn), pt(nn * (n.values[0] / l)));
      }
      case Node::Cylinder:
        return make_cylinder(pt(n.points[0]), pt(n.points[1]), n.values[0], !n.open);
      case Node::Cone:
        return make_cone(pt(n.points[0]), pt(n.points[1]), n.values[0], n.values[1], !n.open);
      case Node::Disc:
        return make_disk(pt(n.points[0]), m(n.points[1]), n.values[0], n.values[1]);
      case Node::Torus:
        axial = true;
        return make_torus(n.values[0], n.values[1]);
      case Node::Quadric: {
        QuadricCoefficients c{};
        for (std::size_t i = 0; i < 10; ++i) c[i] = n.values[i];
        if (mirror_) c[4] = -c[4], c[5] = -c[5], c[8] = -c[8];  // the xz, yz and z terms
        return make_quadric(c);
      }
      case Node::Poly:
        if (!n.bounds) {
          warn(n.pos, "unbounded polynomials",
               "raycast needs bounded_by { box } or { sphere }, or an intersection with one");
          return std::nullopt;
        }
        return make_algebraic(polynomial_text(n), box_of(*n.bounds));
      case Node::Isosurface: {
        pov::FunctionValue f;
        f.params = {"x", "y", "z"};
        f.body = n.function;
        const std::string text = pov::formula_text(f, mirror_);
        if (text.empty()) {
          warn(n.pos, "isosurfaces of this function", "internal or pattern functions");
          return std::nullopt;
        }
        return make_implicit(text, box_of(*n.bounds), n.open);
      }
      case Node::Lathe:
      case Node::Sor: {
        axial = true;
        std::vector<std::array<double, 2>> profile;
        for (const Vec3& p : n.points) profile.push_back({p.x, p.y});
        return make_revolution(profile, ProfileCurve::kLinear, n.kind == Node::Sor && !n.open);
      }
      case Node::Prism: {
        // Swept along y in POV-Ray, along z in raycast: the axial turn takes raycast's (x, y, h)
        // to (x, h, -y), which is POV-Ray's (x, h, z) mirrored when y = z.
        axial = true;
        std::vector<std::array<double, 2>> points;
        for (const Vec3& p : n.points) points.push_back({p.x, mirror_ ? p.y : -p.y});
        return make_prism(spline_contours(points, prism_spline(n.spline)), n.values[0], n.values[1],
                          n.conic_sweep, n.open);
      }
      case Node::Blob:
        return blob(n);
      case Node::Text:
        if (n.font.empty()) return std::nullopt;  // not found: the reader warned
        try {
          return make_text_shape(n.font, n.text, n.values[0], n.points[0], mirror_);
        } catch (const std::runtime_error& e) {
          warn(n.pos, "text in this font", e.what());
          return std::nullopt;
        }
      case Node::Triangle: {
        // Mirroring reverses the winding: swap two corners to keep the face's side.
        const std::size_t b = mirror_ ? 2 : 1, c = mirror_ ? 1 : 2;
        if (n.normals.empty())
          return make_triangle(pt(n.points[0]), pt(n.points[b]), pt(n.points[c]));
        return make_triangle(pt(n.points[0]), pt(n.points[b]), pt(n.points[c]), m(n.normals[0]),
                             m(n.normals[b]), m(n.normals[c]));
      }
      case Node::Mesh: {
        std::vector<Vec3f> pos, nor;
        for (const Vec3& v : n.vertices) {
          const Vec3 q = pt(v);
          pos.push_back(
              {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)});
        }
        for (const Vec3& v : n.normals) {
          const Vec3 q = m(v);
          nor.push_back(
              {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)});
        }
        std::vector<std::array<std::uint32_t, 3>> tris;
        tris.reserve(n.triangles.size());
        for (const auto& t : n.triangles) {
          // Mirroring reverses the winding: swap two corners to keep the faces' sides.
          const auto a = static_cast<std::uint32_t>(t[0]), b = static_cast<std::uint32_t>(t[1]),
                     c = static_cast<std::uint32_t>(t[2]);
          tris.push_back(mirror_ ? std::array<std::uint32_t, 3>{a, c, b}
                                 : std::array<std::uint32_t, 3>{a, b, c});
        }
        MeshOptions opt;
        opt.smooth = !nor.empty();
        return MeshShape{make_mesh(std::move(pos), std::move(tris), std::move(nor), opt)};
      }
      default:
        return std::nullopt;
    }
  }

  void warn(const pov::Pos& at, const std::string& kind, const std::string& detail,
            const char* outcome = "left out") {
    if (strict_)
      fail_at(at, "raycast does not render " + kind + " yet (" + detail +
                      "); without --strict it is a warning and is left out");
    if (!warned_.insert(kind).second) return;
    const std::string& name = s_.sources.names[static_cast<std::size_t>(at.file)];
    warnings_.push_back(name + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                        ": warning: raycast does not render " + kind + " yet (" + detail + "); " +
                        outcome);
  }

  static bool is_csg(Node::Kind k) {
    return k == Node::Intersection || k == Node::Difference || k == Node::Merge;
  }

  // One leaf object, its transform relative to `parent`.
  std::optional<Object> leaf(const Node& n, const pov::Texture* tex, const Transform& frame,
                             const std::optional<Transform>& parent) {
    bool axial = false;
    std::optional<ShapeVariant> sh;
    shift_ = Vec3{0, 0, 0};
    if (n.kind == Node::Blob) tex = blob_texture(n, tex);
    if (tex && tex->pigment.checker && pov::on_checker_grid(n, tex->pigment.scale)) {
      const double e = pov::kCheckerOffset * tex->pigment.scale;
      shift_ = m(Vec3{e, e, e});
    }
    try {
      sh = shape(n, axial);
    } catch (const std::invalid_argument& e) {
      // POV-Ray draws degenerate shapes (a flat box, a zero radius) as nothing or a sliver.
      warn(n.pos, "degenerate shapes", e.what());
      return std::nullopt;
    }
    if (!sh) return std::nullopt;
    Object o;
    o.shape = std::move(*sh);
    o.xf = compose(parent, own_transform(n, axial, shift_));
    if (n.kind == Node::Blob) blob_materials(n, o);  // (shift_ still holds the blob's offset)
    shift_ = Vec3{0, 0, 0};
    if (tex) o.material = material(*tex, frame, csg_world_ ? csg_world_ : o.xf);
    return o;
  }

  // A top-level node (or a child of a union outside CSG): groups flatten into `out`; with
  // no_shadow, every object it gives casts no shadow.
  // `frame`: POV-Ray's world from the inherited texture's space (texture_frame).
  void add(const Node& n, const pov::Texture* inherited, const Transform& inherited_frame,
           const std::optional<Transform>& parent, int entry, std::vector<Object>& out) {
    const std::size_t first = out.size();
    add_node(n, inherited, inherited_frame, parent, entry, out);
    hide(n, first, out);
  }

  // What no_shadow, no_image and no_reflection take away from the objects a node gave.
  static void hide(const Node& n, std::size_t first, std::vector<Object>& out) {
    for (std::size_t i = first; i < out.size(); ++i) {
      if (n.no_shadow) out[i].casts_shadow = false;
      if (n.no_image) out[i].seen_by_camera = false;
      if (n.no_reflection) out[i].seen_in_reflections = false;
    }
  }

  void add_node(const Node& n, const pov::Texture* inherited, const Transform& inherited_frame,
                const std::optional<Transform>& parent, int entry, std::vector<Object>& out) {
    const pov::Texture* tex = n.texture ? &*n.texture : inherited;
    const Transform frame = n.texture ? texture_frame(n, parent) : inherited_frame;
    if (n.kind == Node::LightSource) {
      light(*n.light, parent);
      return;
    }
    if (n.kind == Node::Union && !n.clipped_by.empty() && !n.inverse) {
      add_clipped_union(n, tex, frame, parent, entry, out);
      return;
    }
    if (!n.clipped_by.empty() || (n.inverse && !is_csg(n.kind))) {
      // Clipped or inverted on its own: a CSG tree of one operand (csg_part), placed by parent.
      // An open surface cannot be a CSG leaf: it is drawn whole, as before clipping.
      if (open_leaf(n, tex, frame, parent, entry, out)) return;
      CsgTree tree;
      tree.nodes.emplace_back().op = CsgOp::kIntersection;
      csg_world_ = parent ? parent : std::optional<Transform>(Transform());
      const std::optional<std::int32_t> code = csg_part(n, tex, frame, std::nullopt, tree, false);
      csg_world_.reset();
      if (!code) return;
      tree.nodes[0].operands.push_back(*code);
      add_csg(n, std::move(tree), tex, frame, parent, entry, out);
      return;
    }
    if (n.kind == Node::Union) {
      const std::optional<Transform> xf = compose(parent, own_transform(n, false));
      for (const Node& c : n.children) add(c, tex, frame, xf, entry, out);
      return;
    }
    if (n.kind == Node::Reference) {
      add(*n.ref, tex, frame, compose(parent, own_transform(n, false)), entry, out);
      return;
    }
    if (is_csg(n.kind)) {
      CsgTree tree;
      const std::optional<Transform> xf = compose(parent, own_transform(n, false));
      csg_world_ = xf ? xf : std::optional<Transform>(Transform());
      csg_operation(n, tex, frame, std::nullopt, tree, n.inverse);
      csg_world_.reset();
      add_csg(n, std::move(tree), tex, frame, xf, entry, out);
      return;
    }
    std::optional<Object> o = leaf(n, tex, frame, parent);
    if (!o) return;
    o->entry = entry;
    out.push_back(std::move(*o));
  }

  // A union's clipping objects clip each of its children on its own: the children keep their
  // surfaces inside one another, as a union's (merge's would not).
  void add_clipped_union(const Node& n, const pov::Texture* tex, const Transform& frame,
                         const std::optional<Transform>& parent, int entry,
                         std::vector<Object>& out) {
    const std::optional<Transform> own = own_transform(n, false);
    for (const Node& c : n.children) {
      if (c.kind == Node::LightSource) {
        light(*c.light, compose(parent, own));
        continue;
      }
      CsgTree tree;
      tree.nodes.emplace_back().op = CsgOp::kIntersection;
      csg_world_ = parent ? parent : std::optional<Transform>(Transform());
      const std::optional<std::int32_t> code = csg_part(c, tex, frame, own, tree, false);
      if (code) {
        tree.nodes[0].operands.push_back(*code);
        hiding_ = true;
        for (const Node& k : n.clipped_by)
          if (const std::optional<std::int32_t> kc =
                  csg_part(k, nullptr, frame, std::nullopt, tree, false))
            tree.nodes[0].operands.push_back(*kc);
        hiding_ = false;
      }
      csg_world_.reset();
      const std::size_t first = out.size();
      if (code) add_csg(c, std::move(tree), tex, frame, parent, entry, out);
      hide(c, first, out);
    }
  }

  // For a clipped or inverted shape that is an open surface (an open cylinder, a disc, a mesh
  // that is not closed): a warning, and the surface added as it is. false for other nodes.
  bool open_leaf(const Node& n, const pov::Texture* tex, const Transform& frame,
                 const std::optional<Transform>& parent, int entry, std::vector<Object>& out) {
    if (n.kind == Node::Union || n.kind == Node::Reference || is_csg(n.kind)) return false;
    std::optional<Object> o = leaf(n, tex, frame, parent);
    if (!o || is_closed(*o)) return false;
    warn(n.pos, "clipped_by and inverse on open surfaces", "raycast's CSG needs closed solids",
         "the surface is drawn whole");
    o->entry = entry;
    out.push_back(std::move(*o));
    return true;
  }

  // The object of a built CSG tree, placed by xf.
  void add_csg(const Node& n, CsgTree tree, const pov::Texture* tex, const Transform& frame,
               const std::optional<Transform>& xf, int entry, std::vector<Object>& out) {
    if (tree.leaves.empty()) return;
    Object o;
    try {
      o.shape = CsgShape{finish_csg_tree(std::move(tree))};
    } catch (const std::invalid_argument& e) {
      fail_at(n.pos, e.what());
    }
    o.xf = xf;
    o.material = tex ? material(*tex, frame, o.xf) : -1;
    o.entry = entry;
    out.push_back(std::move(o));
  }

  // The parts' `here` placements are relative to the CSG object (csg_world_ places it).
  // `invert`: build the operation's complement (POV-Ray's `inverse`), by De Morgan's laws down to
  // the leaves: a union's complement is the intersection of its operands' complements, an
  // intersection's the union, a difference's (a minus the rest) the union of a's complement and
  // the rest.
  std::int32_t csg_operation(const Node& n, const pov::Texture* tex, const Transform& frame,
                             const std::optional<Transform>& here, CsgTree& tree, bool invert) {
    const std::size_t index = tree.nodes.size();
    tree.nodes.emplace_back();
    const CsgOp op = n.kind == Node::Intersection ? CsgOp::kIntersection
                     : n.kind == Node::Difference ? CsgOp::kDifference
                                                  : CsgOp::kUnion;
    tree.nodes[index].op = !invert                    ? op
                           : op == CsgOp::kUnion      ? CsgOp::kIntersection
                           : op == CsgOp::kDifference ? CsgOp::kUnion
                                                      : CsgOp::kUnion;
    for (const Node& c : n.children) {
      const bool first = tree.nodes[index].operands.empty();
      const bool part_invert = invert && (op != CsgOp::kDifference || first);
      if (const std::optional<std::int32_t> code = csg_part(c, tex, frame, here, tree, part_invert))
        tree.nodes[index].operands.push_back(*code);
    }
    if (tree.nodes[index].operands.empty()) {
      // Every operand was left out: an empty solid stays empty as an empty intersection.
      Object o;
      o.shape = make_sphere({0, 0, 0}, 1e-9);
      tree.nodes[index].operands.push_back(push_leaf(tree, std::move(o), false));
    }
    return static_cast<std::int32_t>(index);
  }

  // One operand of a CSG operation: a leaf, an operation, or (clipped_by) the intersection of
  // the part with its clipping objects, whose leaves are hidden. nullopt: left out.
  std::optional<std::int32_t> csg_part(const Node& c, const pov::Texture* tex,
                                       const Transform& frame, const std::optional<Transform>& here,
                                       CsgTree& tree, bool invert) {
    const pov::Texture* ct = c.texture ? &*c.texture : tex;
    if (c.kind == Node::Reference && c.ref->texture) ct = &*c.ref->texture;
    if (c.kind == Node::LightSource) {
      light(*c.light, std::nullopt);
      return std::nullopt;
    }
    const Node* part = &c;
    std::optional<Transform> at = here;
    bool inverse = invert != c.inverse;
    // Clipping objects with the placement of the frame they are written in.
    std::vector<std::pair<const Node*, std::optional<Transform>>> clips;
    for (const Node& k : c.clipped_by) clips.emplace_back(&k, here);
    while (part->kind == Node::Reference) {  // object { Name }: the shared object, placed
      at = compose(at, own_transform(*part, false));
      part = part->ref.get();
      if (part->texture && !c.texture) ct = &*part->texture;
      inverse = inverse != part->inverse;
      for (const Node& k : part->clipped_by) clips.emplace_back(&k, at);
    }
    // The clipped part is an intersection with its clipping objects: that node comes first.
    const std::size_t clip_node = tree.nodes.size();
    if (!clips.empty()) tree.nodes.emplace_back().op = CsgOp::kIntersection;
    std::optional<std::int32_t> code = csg_body(c, part, ct, frame, here, at, tree, inverse);
    if (clips.empty() || !code) return code;
    tree.nodes[clip_node].operands.push_back(*code);
    const bool hiding = hiding_;
    hiding_ = true;
    for (const auto& [k, placed] : clips)
      if (const std::optional<std::int32_t> kc = csg_part(*k, nullptr, frame, placed, tree, false))
        tree.nodes[clip_node].operands.push_back(*kc);
    hiding_ = hiding;
    return static_cast<std::int32_t>(clip_node);
  }

  // csg_part's own shape: `part` is c or the object c names, placed by `at`.
  std::optional<std::int32_t> csg_body(const Node& c, const Node* part, const pov::Texture* ct,
                                       const Transform& frame, const std::optional<Transform>& here,
                                       const std::optional<Transform>& at, CsgTree& tree,
                                       bool inverse) {
    // The texture frame of the part: its own texture's, else the one it inherits.
    const Transform part_frame =
        part->texture ? texture_frame(*part, compose(csg_world_, part == &c ? here : at))
        : c.texture   ? texture_frame(c, compose(csg_world_, here))
                      : frame;
    if (part->kind == Node::Union || is_csg(part->kind)) {
      const std::optional<Transform> xf = part == &c ? compose(here, own_transform(c, false))
                                                     : compose(at, own_transform(*part, false));
      return csg_operation(*part, ct, part_frame, xf, tree, inverse);
    }
    if (part->kind == Node::LightSource) {
      light(*part->light, at);
      return std::nullopt;
    }
    std::optional<Object> o = leaf(*part, ct, part_frame, at);
    if (!o) return std::nullopt;
    if (!is_closed(*o)) {
      warn(c.pos, "open surfaces in CSG", "raycast's CSG needs closed solids");
      return std::nullopt;
    }
    o->material = part->texture ? material(*part->texture, part_frame, csg_world_)
                  : c.texture   ? material(*c.texture, part_frame, csg_world_)
                                : -1;
    return push_leaf(tree, std::move(*o), inverse);
  }

  // Appends a leaf (inverse: its complement; hidden while clipping objects are built).
  std::int32_t push_leaf(CsgTree& tree, Object o, bool inverse) {
    tree.leaves.push_back(std::move(o));
    tree.leaf_inverse.resize(tree.leaves.size(), 0);
    tree.leaf_hidden.resize(tree.leaves.size(), 0);
    tree.leaf_inverse.back() = inverse;
    tree.leaf_hidden.back() = hiding_;
    return csg_leaf_code(tree.leaves.size() - 1);
  }

 public:
  std::vector<std::string> warnings_;

 private:
  const pov::PovScene& s_;
  Scene& scene_;
  bool strict_ = false;
  Vec3 shift_{0, 0, 0};  // the checker offset of the shape being built
  bool mirror_ = false;
  double gamma_ = 1;
  // Equal materials are stored once: every field of raycast's material, as written.
  using MaterialKey = std::array<double, 26>;
  std::map<MaterialKey, int> materials_;
  std::set<std::string> warned_;
  PovTextureBuilder pov_textures_{[this](double c) { return linear(c); }};
  std::map<const pov::Texture*, std::shared_ptr<const texture::TextureStack>> stacks_;
  // While a CSG object is built: its placement in the world (its parts' materials map from its
  // space).
  std::optional<Transform> csg_world_;
  bool hiding_ = false;  // while a CSG tree's clipping objects are built (CsgTree::leaf_hidden)
};

void report(const std::vector<std::string>& in, std::vector<std::string>* out) {
  for (const std::string& w : in) {
    if (out)
      out->push_back(w);
    else
      std::cerr << w << "\n";
  }
}

Scene build(pov::PovScene ps, const std::string& name, std::vector<std::string>* warnings,
            bool strict) {
  Scene scene;
  scene.source = name;
  Builder b(ps, scene, strict);
  b.run();
  report(ps.warnings, warnings);
  report(b.warnings_, warnings);
  for (std::size_t i = 1; i < ps.sources.paths.size(); ++i)
    scene.marks.files.push_back(ps.sources.paths[i]);
  scene.build();
  return scene;
}

pov::Options with_frame(pov::Options o, int frame) {
  if (frame >= 0 && !o.clock_on) {
    o.frame = frame;
  }
  return o;
}

// trace, inside, min_extent and max_extent: each object asked about is built once (in POV-Ray's
// own frame) and kept while the scene is read, since scenes ask thousands of times about one
// object (placing things on a height field).
class BuiltObjectQueries : public pov::ObjectQueries {
 public:
  std::optional<Trace> trace(const pov::PovScene& ps, const std::shared_ptr<const Node>& object,
                             const Vec3& origin, const Vec3& direction) override {
    const double len = length(direction);
    if (!(len > 0) || !std::isfinite(len)) return std::nullopt;
    const Ray ray{origin, direction / len, 1e-6, std::numeric_limits<double>::infinity()};
    std::optional<Trace> best;
    double best_t = ray.tmax;
    for (const Object& o : objects_of(ps, object)) {
      Ray r = ray;
      r.tmax = best_t;
      LocalHit h;
      if (!intersect(o, r, h) || !(h.t < best_t)) continue;
      best_t = h.t;
      const SurfaceInfo si = surface(o, r, h, SurfaceNeeds::kGeometry);
      best = Trace{si.p, si.n};
    }
    return best;
  }

  bool inside(const pov::PovScene& ps, const std::shared_ptr<const Node>& object,
              const Vec3& point) override {
    for (const Object& o : objects_of(ps, object))
      if (contains(o, point)) return true;
    return false;
  }

  std::pair<Vec3, Vec3> extent(const pov::PovScene& ps,
                               const std::shared_ptr<const Node>& object) override {
    const std::vector<Object>& objects = objects_of(ps, object);
    if (objects.empty()) return {Vec3{0, 0, 0}, Vec3{0, 0, 0}};
    Aabb box = bounds(objects[0]);
    for (std::size_t i = 1; i < objects.size(); ++i) box = merge(box, bounds(objects[i]));
    static constexpr double kHuge = 2e10;  // POV-Ray's bound of an unbounded side
    auto clamp = [](const Vec3& v) {
      return Vec3{std::clamp(v.x, -kHuge, kHuge), std::clamp(v.y, -kHuge, kHuge),
                  std::clamp(v.z, -kHuge, kHuge)};
    };
    return {clamp(box.lo), clamp(box.hi)};
  }

 private:
  static constexpr std::size_t kMaxKept = 256;  // objects kept built at once

  const std::vector<Object>& objects_of(const pov::PovScene& ps,
                                        const std::shared_ptr<const Node>& object) {
    auto it = built_.find(object.get());
    if (it != built_.end()) return it->second.objects;
    if (built_.size() >= kMaxKept) built_.clear();
    Scene scratch;
    Builder b(ps, scratch, false, true);
    Built& kept = built_[object.get()];
    kept.node = object;
    kept.objects = b.objects_of(*object);
    return kept.objects;
  }

  struct Built {
    std::shared_ptr<const Node> node;  // keeps the key's node alive
    std::vector<Object> objects;
  };
  std::map<const Node*, Built> built_;
};

// The options with the functions of objects answered, unless the caller answers them.
pov::Options with_object_queries(pov::Options o) {
  if (!o.object_queries) o.object_queries = std::make_shared<BuiltObjectQueries>();
  return o;
}

}  // namespace

pov::Options& default_pov_options() {
  static pov::Options o;
  return o;
}

bool is_pov_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".pov" || ext == ".ini";
}

Scene load_pov_scene_text(const std::string& text, const std::string& name, const std::string& dir,
                          int frame, const pov::Options& options,
                          std::vector<std::string>* warnings) {
  register_formula_noise();  // functions.inc's f_noise3d in isosurfaces
  return build(pov::interpret_pov(text, name, dir, with_object_queries(with_frame(options, frame))),
               name, warnings, options.strict);
}

Scene load_pov_scene_file(const std::string& path, int frame, const pov::Options& options,
                          std::vector<std::string>* warnings) {
  register_formula_noise();  // functions.inc's f_noise3d in isosurfaces
  pov::Options o = with_object_queries(with_frame(options, frame));
  std::string scene_path = path;
  if (path.size() >= 4 &&
      (path.substr(path.size() - 4) == ".ini" || path.substr(path.size() - 4) == ".INI"))
    scene_path = pov::read_ini_file(path, o);
  const SceneFileText file = read_scene_file(scene_path);
  return build(pov::interpret_pov(file.text, scene_path, file.dir, o), scene_path, warnings,
               o.strict);
}

std::string convert_pov_file(const std::string& path, const pov::Options& options) {
  pov::Options o = with_object_queries(options);
  std::string scene_path = path;
  if (path.size() >= 4 && path.substr(path.size() - 4) == ".ini")
    scene_path = pov::read_ini_file(path, o);
  const SceneFileText file = read_scene_file(scene_path);
  pov::PovScene ps = pov::interpret_pov(file.text, scene_path, file.dir, o);
  report(ps.warnings, nullptr);
  return pov::write_yaml(ps, scene_path).text;
}

}  // namespace raycast
