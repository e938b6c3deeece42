#include "pov/yaml_writer.h"

#include "pov/checker_grid.h"

#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

namespace raycast::pov {

namespace {

std::string num(double v) {
  if (v == 0) v = 0;  // no "-0" in the output
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

class Writer {
 public:
  Writer(const PovScene& s, const std::string& name) : s_(s), name_(name) {}

  YamlScene run() {
    const Camera& c = s_.camera;
    // POV-Ray's frame is left-handed when (up x direction) . right > 0 (the default camera):
    // then z is negated everywhere, which shows the same picture in raycast's right-handed frame.
    mirror_ = dot(cross(c.up, c.direction), c.right) > 0;
    line({}, "# Converted from " + name_ + " by raycast's POV-Ray import (docs/pov-import.md)" +
                 (mirror_ ? "; z negated (left-handed to right-handed)" : "") + ".");
    camera();
    line({}, "image: {width: 640, height: 480}");
    {
      std::ostringstream r;
      r << "render: {integrator: whitted, max_depth: " << s_.max_trace_level - 1
        << ", background: " << rgb(s_.background) << ", ambient: " << rgb(s_.ambient_light);
      if (s_.adc_bailout) r << ", bailout: " << num(*s_.adc_bailout);
      r << "}";
      line({}, r.str());
    }
    // Materials first (collected from the objects), then lights and objects.
    std::vector<std::string> object_lines;
    std::vector<Pos> object_pos;
    std::swap(out_, object_lines);
    std::swap(pos_, object_pos);
    line({}, "objects:");
    for (const Node& n : s_.objects) object(n, 1, false, nullptr);
    std::swap(out_, object_lines);
    std::swap(pos_, object_pos);
    if (!materials_.empty()) {
      line({}, "materials:");
      for (const auto& [name, m] : material_order_) line(m.second, "  " + name + ": " + m.first);
    }
    bool any_light = false;
    for (const Node& n : s_.objects)
      if (n.kind == Node::LightSource) {
        if (!any_light) line({}, "lights:");
        any_light = true;
        light(*n.light);
      }
    out_.insert(out_.end(), object_lines.begin(), object_lines.end());
    pos_.insert(pos_.end(), object_pos.begin(), object_pos.end());
    YamlScene y;
    for (const std::string& l : out_) y.text += l + "\n";
    y.line_pos = pos_;
    y.mirrored = mirror_;
    return y;
  }

 private:
  void line(const Pos& p, const std::string& text) {
    out_.push_back(text);
    pos_.push_back(p);
  }
  [[noreturn]] void fail_at(const Pos& p, const std::string& m) const { fail(s_.sources, p, m); }

  Vec3 m(const Vec3& v) const { return mirror_ ? Vec3{v.x, v.y, -v.z} : v; }
  static std::string vec(const Vec3& v) { return triple(v.x, v.y, v.z); }
  static std::string rgb(const Colour& c) { return triple(c.r, c.g, c.b); }
  static std::string triple(double a, double b, double c) {
    std::string s("[");
    s.append(num(a)).append(", ").append(num(b)).append(", ").append(num(c)).append("]");
    return s;
  }

  void camera() {
    const Camera& c = s_.camera;
    const Vec3 look = c.location + c.direction;
    static const char* const kTypes[] = {"perspective",      "orthographic", "fisheye",
                                         "ultra_wide_angle", "omnimax",      "panoramic",
                                         "cylinder",         "spherical"};
    std::ostringstream o;
    o << "camera: {type: " << kTypes[c.kind] << ", position: " << vec(m(c.location))
      << ", look_at: " << vec(m(look)) << ", up: " << vec(m(c.up));
    if (c.kind == Camera::Orthographic) {
      o << ", height: " << num(length(c.up));
    } else if (c.kind == Camera::Perspective) {
      // The vertical field of view from up's length against direction's (POV-Ray's `angle` has
      // already set direction's length from right's), for a viewer that moves the camera.
      const double fov =
          2 * std::atan(0.5 * length(c.up) / length(c.direction)) * 180 / std::numbers::pi;
      o << ", fov: " << num(fov);
    } else {
      o << ", angle: " << num(c.angle);
      if (c.kind == Camera::Spherical)
        o << ", vertical_angle: " << num(c.vertical_angle > 0 ? c.vertical_angle : 0.5 * c.angle);
      if (c.kind == Camera::Cylinder) o << ", cylinder: " << c.cylinder;
    }
    // POV-Ray's vectors as they are: they decide the view and its aspect.
    o << ", direction: " << vec(m(c.direction)) << ", right: " << vec(m(c.right)) << "}";
    line(c.pos, o.str());
  }

  void light(const Light& l) {
    std::ostringstream o;
    const Vec3 axis = m(l.point_at - l.position);
    const std::string cone = ", angle: " + num(l.falloff) +
                             ", falloff: " + num(l.falloff - l.radius) +
                             ", tightness: " + num(l.tightness) + ", edge: cosine";
    if (l.parallel) {
      o << "  - {type: directional, direction: " << vec(axis)
        << ", position: " << vec(m(l.position));
    } else if (l.area) {
      o << "  - {type: area, position: " << vec(m(l.position)) << ", axis1: " << vec(m(l.axis1))
        << ", axis2: " << vec(m(l.axis2)) << ", size1: " << l.size1 << ", size2: " << l.size2
        << (l.adaptive >= 0 ? ", adaptive: " + std::to_string(l.adaptive) : std::string())
        << ", jitter: " << (l.jitter ? "true" : "false")
        << ", circular: " << (l.circular ? "true" : "false")
        << ", orient: " << (l.orient ? "true" : "false");
      if (l.kind == Light::Spot) o << ", direction: " << vec(axis) << cone;
    } else if (l.kind == Light::Spot) {
      o << "  - {type: spot, position: " << vec(m(l.position)) << ", direction: " << vec(axis)
        << cone;
    } else if (l.kind == Light::Cylinder) {
      o << "  - {type: cylinder, position: " << vec(m(l.position)) << ", direction: " << vec(axis)
        << ", radius: " << num(l.falloff) << ", falloff: " << num(l.falloff - l.radius);
    } else {
      o << "  - {type: point, position: " << vec(m(l.position));
    }
    if (l.fade_distance > 0 && l.fade_power > 0)
      o << ", attenuation: fade, fade_distance: " << num(l.fade_distance)
        << ", fade_power: " << num(l.fade_power);
    if (l.shadowless) o << ", shadows: false";
    o << ", color: " << rgb(l.colour) << "}";
    line(l.pos, o.str());
  }

  // The material's YAML mapping (docs/pov-import.md "Materials").
  std::string material_text(const Texture& t, const Pos& at) const {
    const Pigment& p = t.pigment;
    const Finish& f = t.finish;
    const double tr0 = p.c0.filter + p.c0.transmit, tr1 = p.c1.filter + p.c1.transmit;
    if (p.checker && tr0 != tr1)
      fail_at(at, unsupported("a checker of colours with different filter or transmit"));
    const double transmission = std::min(1.0, tr0);
    std::ostringstream o;
    o << "{";
    if (p.checker) {
      // Negating z swaps the parity of floor(z): swap the colours back.
      const Colour& a = mirror_ ? p.c1 : p.c0;
      const Colour& b = mirror_ ? p.c0 : p.c1;
      o << "texture: {checker: {colors: [" << rgb(a) << ", " << rgb(b)
        << "], scale: " << num(p.scale) << "}}";
    } else {
      o << "color: " << rgb(p.c0);
    }
    double specular = f.phong, shininess = f.phong_size;
    if (f.specular > 0) {
      // Blinn's (n.h)^(1/roughness) as a Phong lobe: the half-vector's angle is about half the
      // mirror direction's, so the exponent is a quarter.
      if (f.phong == 0) shininess = 1 / (4 * f.roughness);
      specular += f.specular;
    }
    // POV-Ray weighs a surface's own ambient and diffuse light by its opacity,
    // 1 - filter - transmit (the rest is what shows through); raycast never scales them.
    const double opacity = 1 - transmission;
    o << ", ambient: " << num(f.ambient * opacity) << ", diffuse: " << num(f.diffuse * opacity)
      << ", specular: " << num(specular) << ", shininess: " << num(shininess)
      << ", reflection: " << num(std::min(1.0, f.reflection));
    if (transmission > 0) o << ", transmission: " << num(transmission);
    if (f.fresnel) {
      if (transmission == 0)
        fail_at(at, unsupported("reflection { fresnel } on an opaque pigment") +
                        " (raycast's Fresnel splits transmitted light)");
      o << ", fresnel: true";
    }
    const Interior in = t.interior.value_or(Interior{});
    if (in.ior) o << ", ior: " << num(*in.ior);
    if (in.dispersion != 1)
      o << ", dispersion: " << num(in.dispersion)
        << ", dispersion_samples: " << in.dispersion_samples;
    const bool own = in.fade_distance != 0 || in.fade_power != 0;
    const double fade_distance = own ? in.fade_distance : f.fade_distance;
    const double fade_power = own ? in.fade_power : f.fade_power;
    if (fade_distance > 0 && fade_power > 0)
      o << ", fade_distance: " << num(fade_distance) << ", fade_power: " << num(fade_power)
        << ", fade_color: " << rgb(in.fade_color);
    o << "}";
    return o.str();
  }

  std::string material(const Texture& t, const Pos& at) {
    const std::string text = material_text(t, at);
    const auto it = materials_.find(text);
    if (it != materials_.end()) return it->second;
    std::string name = t.name.empty() ? "m" + std::to_string(materials_.size()) : t.name;
    while (material_order_.count(name)) name += "_";
    materials_[text] = name;
    material_order_[name] = {text, at};
    return name;
  }

  std::string transform(const Node& n, bool axial, bool flip_z = false) const {
    std::vector<std::string> ops;
    // Text is extruded towards +z in both frames: the mirror turns it round.
    if (flip_z) ops.push_back("{scale: [1, 1, -1]}");
    // Torus, lathe and sor are about y in POV-Ray, about z in raycast: turn z onto y. (They are
    // symmetric about their axis, so mirroring z leaves this turn as it is.)
    if (axial) ops.push_back("{rotate: {axis: [1, 0, 0], degrees: -90}}");
    if (shift_.x != 0) ops.push_back("{translate: " + vec(shift_ * -1.0) + "}");
    const double s = mirror_ ? -1 : 1;
    for (const XformOp& x : n.xforms) {
      switch (x.kind) {
        case XformOp::Translate:
          ops.push_back("{translate: " + vec(m(x.v)) + "}");
          break;
        case XformOp::Scale:
          ops.push_back("{scale: " + vec(x.v) + "}");
          break;
        case XformOp::Rotate: {
          // POV-Ray turns about x, then y, then z, with the same matrices as raycast's
          // right-hand rule; conjugated by the mirror, the x and y angles change sign.
          const double a[3] = {x.v.x * s, x.v.y * s, x.v.z};
          const char* axes[3] = {"[1, 0, 0]", "[0, 1, 0]", "[0, 0, 1]"};
          for (int i = 0; i < 3; ++i)
            if (a[i] != 0)
              ops.push_back(std::string("{rotate: {axis: ") + axes[i] + ", degrees: " + num(a[i]) +
                            "}}");
          break;
        }
        case XformOp::Matrix: {
          // POV-Ray's rows act on row vectors: p' = x r0 + y r1 + z r2 + t.
          const double sign[4] = {1, 1, s, 1};
          std::string t = "{matrix: [";
          for (int i = 0; i < 4; ++i) {
            t += i ? ", [" : "[";
            for (int j = 0; j < 4; ++j) {
              double v = i == 3   ? (j == 3 ? 1 : 0)
                         : j == 3 ? x.m[static_cast<std::size_t>(9 + i)]
                                  : x.m[static_cast<std::size_t>(3 * j + i)];
              v *= sign[i] * sign[j];
              t += (j ? ", " : "") + num(v);
            }
            t += "]";
          }
          ops.push_back(t + "]}");
          break;
        }
      }
    }
    if (ops.empty()) return "";
    std::string t = "[";
    for (std::size_t i = 0; i < ops.size(); ++i) t += (i ? ", " : "") + ops[i];
    return t + "]";
  }

  std::string polynomial_text(const Node& n) const {
    std::string e;
    for (const auto& [k, c] : n.terms) {
      const double v = mirror_ && k[2] % 2 ? -c : c;
      if (v == 0) continue;
      e += (e.empty() ? "(" : " + (") + num(v) + ")";
      const char* var[3] = {"x", "y", "z"};
      for (int i = 0; i < 3; ++i)
        if (k[static_cast<std::size_t>(i)])
          e += std::string("*") + var[i] + "^" + std::to_string(k[static_cast<std::size_t>(i)]);
    }
    return e.empty() ? "0" : e;
  }

  std::string bounds_text(const std::array<Vec3, 2>& b, const Vec3& shift = {0, 0, 0}) const {
    Vec3 lo = b[0], hi = b[1];
    if (mirror_) std::swap(lo.z, hi.z), lo.z = -lo.z, hi.z = -hi.z;
    return "{min: " + vec(lo + shift) + ", max: " + vec(hi + shift) + "}";
  }

  // One object at `indent` list depth. `solid`: it is a CSG operand (POV-Ray's union becomes
  // raycast's solid union there, and a group elsewhere, keeping its inner surfaces).
  void object(const Node& n, int indent, bool solid, const Texture* inherited) {
    if (n.kind == Node::LightSource) return;  // written under lights:
    // The scene format has neither (raycast renders them from the .pov file itself).
    if (!n.clipped_by.empty()) fail_at(n.pos, unsupported("clipped_by"));
    if (n.inverse) fail_at(n.pos, unsupported("inverse"));
    if (n.kind == Node::Reference) {  // object { Name }: a union of the shared object, placed
      Node wrap = n;
      wrap.kind = Node::Union;
      wrap.children = {*n.ref};
      wrap.ref.reset();
      object(wrap, indent, solid, inherited);
      return;
    }
    const std::string pad(static_cast<std::size_t>(2 * indent), ' ');
    const std::string more(static_cast<std::size_t>(2 * indent + 2), ' ');
    std::ostringstream o;
    bool axial = false;
    std::vector<const Node*> children;
    std::string key;
    const Texture* here = n.texture ? &*n.texture : inherited;
    // POV-Ray evaluates its checker at p + 0.001 (its SMALL_TOLERANCE), so a floor through an
    // integer coordinate (plane { y, 0 }) is one colour, not noise. raycast's checker has no
    // offset: the shape's points are moved by it in object space and moved back by the
    // transform (for the shapes given by points; see docs/pov-import.md). Only where a flat
    // face lies on the grid: the transform costs time on every ray.
    shift_ = Vec3{0, 0, 0};
    if (here && here->pigment.checker && on_checker_grid(n, here->pigment.scale)) {
      const double e = kCheckerOffset * here->pigment.scale;
      shift_ = m(Vec3{e, e, e});
    }
    auto pt = [&](const Vec3& v) { return vec(m(v) + shift_); };
    switch (n.kind) {
      case Node::Sphere:
        o << "sphere: {center: " << pt(n.points[0]) << ", radius: " << num(n.values[0]) << "}";
        break;
      case Node::Box: {
        o << "box: " << bounds_text({n.points[0], n.points[1]}, shift_);
        break;
      }
      case Node::Plane: {
        const Vec3 nn = n.points[0];
        // POV-Ray's distance is measured along the normal made unit length.
        const double l = length(nn);
        if (!(l > 0)) fail_at(n.pos, "a plane's normal must not be zero");
        o << "plane: {normal: " << vec(m(nn)) << ", point: " << pt(nn * (n.values[0] / l)) << "}";
        break;
      }
      case Node::Cylinder:
        o << "cylinder: {from: " << pt(n.points[0]) << ", to: " << pt(n.points[1])
          << ", radius: " << num(n.values[0]) << ", capped: " << (n.open ? "false" : "true") << "}";
        break;
      case Node::Cone:
        o << "cone: {from: " << pt(n.points[0]) << ", to: " << pt(n.points[1])
          << ", radius_from: " << num(n.values[0]) << ", radius_to: " << num(n.values[1])
          << ", capped: " << (n.open ? "false" : "true") << "}";
        break;
      case Node::Disc:
        o << "disk: {center: " << pt(n.points[0]) << ", normal: " << vec(m(n.points[1]))
          << ", radius: " << num(n.values[0]);
        if (n.values[1] > 0) o << ", inner_radius: " << num(n.values[1]);
        o << "}";
        break;
      case Node::Torus:
        axial = true;
        o << "torus: {major_radius: " << num(n.values[0]) << ", minor_radius: " << num(n.values[1])
          << "}";
        break;
      case Node::Quadric: {
        std::vector<double> c = n.values;
        if (mirror_) c[4] = -c[4], c[5] = -c[5], c[8] = -c[8];  // the xz, yz and z terms
        o << "quadric: {coefficients: [";
        for (std::size_t i = 0; i < c.size(); ++i) o << (i ? ", " : "") << num(c[i]);
        o << "]}";
        break;
      }
      case Node::Poly:
        if (!n.bounds)
          fail_at(n.pos,
                  "raycast needs a bounded polynomial: put it in an intersection with a "
                  "box, or give it bounded_by { box { ... } }");
        o << "algebraic: {equation: \"" << polynomial_text(n)
          << "\", bounds: " << bounds_text(*n.bounds) << "}";
        break;
      case Node::Isosurface: {
        FunctionValue f;
        f.params = {"x", "y", "z"};
        f.body = n.function;
        const std::string text = formula_text(f, mirror_);
        if (text.empty())
          fail_at(n.pos, "raycast's formulas cannot express this isosurface's function");
        o << "implicit: {function: \"" << text << "\", bounds: " << bounds_text(*n.bounds);
        if (n.open) o << ", open: true";
        o << "}";
        break;
      }
      case Node::Lathe:
      case Node::Sor: {
        axial = true;
        o << "revolution: {profile: [";
        for (std::size_t i = 0; i < n.points.size(); ++i)
          o << (i ? ", " : "") << "[" << num(n.points[i].x) << ", " << num(n.points[i].y) << "]";
        o << "], curve: linear, capped: " << (n.kind == Node::Sor && !n.open ? "true" : "false")
          << "}";
        break;
      }
      case Node::Prism: {
        // Swept along y in POV-Ray, along z in raycast: see the loader's prism.
        axial = true;
        const char* spline = n.spline == "quadratic_spline" ? "quadratic"
                             : n.spline == "cubic_spline"   ? "cubic"
                             : n.spline == "bezier_spline"  ? "bezier"
                                                            : "linear";
        o << "prism: {points: [";
        for (std::size_t i = 0; i < n.points.size(); ++i)
          o << (i ? ", " : "") << "[" << num(n.points[i].x) << ", "
            << num(mirror_ ? n.points[i].y : -n.points[i].y) << "]";
        o << "], spline: " << spline << ", heights: [" << num(n.values[0]) << ", "
          << num(n.values[1]) << "]";
        if (n.conic_sweep) o << ", sweep: conic";
        if (n.open) o << ", open: true";
        o << "}";
        break;
      }
      case Node::Text: {
        if (n.font.empty()) return;  // the font was not found (the reader warned)
        const auto quoted = [](const std::string& text) {
          std::string q = "\"";
          for (char c : text) {
            if (c == '"' || c == '\\') q += '\\';
            q += c;
          }
          return q + "\"";
        };
        o << "text: {font: " << quoted(n.font) << ", string: " << quoted(n.text)
          << ", thickness: " << num(n.values[0]) << ", offset: " << vec(n.points[0]) << "}";
        break;
      }
      case Node::Blob: {
        o << "blob: {threshold: " << num(n.values[0]) << ", components: [";
        for (std::size_t i = 0; i < n.children.size(); ++i) {
          const Node& c = n.children[i];
          const std::string xf = transform(c, false);
          const auto at = [&](const Vec3& v) { return xf.empty() ? pt(v) : vec(m(v)); };
          o << (i ? ", " : "") << "{";
          if (c.kind == Node::Cylinder)
            o << "from: " << at(c.points[0]) << ", to: " << at(c.points[1]);
          else
            o << "center: " << at(c.points[0]);
          o << ", radius: " << num(c.values[0]) << ", strength: " << num(c.values[1]);
          if (!xf.empty()) o << ", transform: " << xf;
          o << "}";
        }
        o << "]}";
        break;
      }
      case Node::Triangle: {
        // Mirroring reverses the winding: swap two corners to keep the face's side.
        const std::size_t b = mirror_ ? 2 : 1, c = mirror_ ? 1 : 2;
        o << "triangle: {vertices: [" << pt(n.points[0]) << ", " << pt(n.points[b]) << ", "
          << pt(n.points[c]) << "]";
        if (!n.normals.empty())
          o << ", normals: [" << vec(m(n.normals[0])) << ", " << vec(m(n.normals[b])) << ", "
            << vec(m(n.normals[c])) << "]";
        o << "}";
        break;
      }
      case Node::Mesh: {
        o << "mesh: {vertices: [";
        for (std::size_t i = 0; i < n.vertices.size(); ++i)
          o << (i ? ", " : "") << pt(n.vertices[i]);
        o << "], triangles: [";
        for (std::size_t i = 0; i < n.triangles.size(); ++i) {
          const auto& t = n.triangles[i];
          // Mirroring reverses the winding: swap two corners to keep the faces' sides.
          o << (i ? ", " : "") << "[" << t[0] << ", " << (mirror_ ? t[2] : t[1]) << ", "
            << (mirror_ ? t[1] : t[2]) << "]";
        }
        o << "]";
        if (!n.normals.empty()) {
          o << ", normals: [";
          for (std::size_t i = 0; i < n.normals.size(); ++i)
            o << (i ? ", " : "") << vec(m(n.normals[i]));
          o << "], smooth: true";
        }
        o << "}";
        break;
      }
      case Node::LightSource:
      case Node::Reference:
      case Node::Union:
      case Node::Merge:
      case Node::Intersection:
      case Node::Difference:
        key = n.kind == Node::Intersection     ? "intersection"
              : n.kind == Node::Difference     ? "difference"
              : n.kind == Node::Merge || solid ? "union"
                                               : "group";
        break;
    }
    std::string mat;
    if (n.texture &&
        (!inherited || material_text(*n.texture, n.pos) != material_text(*inherited, n.pos)))
      mat = material(*n.texture, n.pos);
    const std::string xf = transform(n, axial, n.kind == Node::Text && mirror_);
    if (n.kind == Node::Isosurface && n.contained_by_sphere) {
      // POV-Ray's container sphere: the implicit solid in the sphere's box, cut by the sphere.
      const Vec3 c = (n.bounds->at(0) + n.bounds->at(1)) * 0.5;
      const double r = 0.5 * (n.bounds->at(1).x - n.bounds->at(0).x);
      line(n.pos, pad + "- intersection:");
      line(n.pos, more + "  - " + o.str());
      line(n.pos, more + "  - sphere: {center: " + vec(m(c)) + ", radius: " + num(r) + "}");
    } else if (key.empty()) {
      line(n.pos, pad + "- " + o.str());
    } else {
      line(n.pos, pad + "- " + key + ":");
      const bool operand = key != "group";
      for (const Node& c : n.children) object(c, indent + 2, operand, here);
    }
    if (!mat.empty()) line(n.pos, more + "material: " + mat);
    if (!xf.empty()) line(n.pos, more + "transform: " + xf);
  }

  const PovScene& s_;
  std::string name_;
  Vec3 shift_{0, 0, 0};  // the checker offset of the object being written
  bool mirror_ = false;
  std::vector<std::string> out_;
  std::vector<Pos> pos_;
  std::map<std::string, std::string> materials_;  // YAML text -> name
  std::map<std::string, std::pair<std::string, Pos>> material_order_;
};

}  // namespace

YamlScene write_yaml(const PovScene& scene, const std::string& source_name) {
  return Writer(scene, source_name).run();
}

}  // namespace raycast::pov
