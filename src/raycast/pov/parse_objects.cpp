// Objects of the POV-Ray subset: the shapes, CSG, `object { Name }`, and their modifiers
// (transformations, textures, interiors). Shapes keep POV-Ray's own parameters and coordinates;
// yaml_writer maps them to raycast's shapes.
#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "math/float_error.h"
#include "pov/interpreter.h"
#include "pov/pov_transform.h"

namespace raycast::pov {

namespace {

const std::map<std::string, Node::Kind>& object_kinds() {
  static const std::map<std::string, Node::Kind> kinds = {{"sphere", Node::Sphere},
                                                          {"box", Node::Box},
                                                          {"plane", Node::Plane},
                                                          {"cylinder", Node::Cylinder},
                                                          {"cone", Node::Cone},
                                                          {"disc", Node::Disc},
                                                          {"torus", Node::Torus},
                                                          {"quadric", Node::Quadric},
                                                          {"poly", Node::Poly},
                                                          {"cubic", Node::Poly},
                                                          {"quartic", Node::Poly},
                                                          {"polynomial", Node::Poly},
                                                          {"isosurface", Node::Isosurface},
                                                          {"lathe", Node::Lathe},
                                                          {"sor", Node::Sor},
                                                          {"prism", Node::Prism},
                                                          {"text", Node::Text},
                                                          {"blob", Node::Blob},
                                                          {"mesh", Node::Mesh},
                                                          {"mesh2", Node::Mesh},
                                                          {"triangle", Node::Triangle},
                                                          {"smooth_triangle", Node::Triangle},
                                                          {"union", Node::Union},
                                                          {"intersection", Node::Intersection},
                                                          {"difference", Node::Difference},
                                                          {"merge", Node::Merge},
                                                          {"light_group", Node::Union}};
  return kinds;
}

bool is_unbuilt_shape(const std::string& w) {
  static constexpr std::string_view shapes[] = {"height_field",  "sphere_sweep",  "superellipsoid",
                                                "julia_fractal", "bicubic_patch", "parametric",
                                                "polygon",       "lemon",         "ovus"};
  for (const std::string_view s : shapes)
    if (s == w) return true;
  return false;
}

// POV-Ray's lathe meets x^2 + z^2 = r(y)^2, so a radius below 0 (a spline overshooting the axis,
// or written so) draws as |r|: the profile folded onto r >= 0, with a point on the axis where it
// crosses it.
std::vector<Vec3> revolved_profile(const std::vector<Vec3>& points) {
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& q = points[i];
    if (i > 0 && (points[i - 1].x < 0) != (q.x < 0) && points[i - 1].x != 0 && q.x != 0) {
      const Vec3& p = points[i - 1];
      const double s = p.x / (p.x - q.x);
      out.push_back({0, p.y + s * (q.y - p.y), 0});
    }
    out.push_back({std::fabs(q.x), q.y, 0});
  }
  return out;
}

bool is_csg(Node::Kind k) {
  return k == Node::Union || k == Node::Intersection || k == Node::Difference || k == Node::Merge;
}

constexpr int kSplineSamples = 16;  // line segments per spline segment of a lathe or sor

// The box around a bounded_by object that a poly takes as its bounds: a box or a sphere, moved
// by the object's own transformations (the box of the moved corners); nullopt for other shapes
// and singular transformations. POV-Ray tests the bound only to skip rays that miss it; a poly
// that reaches beyond it shows there only on rays through it, which this box approximates.
std::optional<std::array<Vec3, 2>> poly_bounds_of(const Node& b) {
  Vec3 lo, hi;
  if (b.kind == Node::Box && b.points.size() == 2) {
    lo = min(b.points[0], b.points[1]);
    hi = max(b.points[0], b.points[1]);
  } else if (b.kind == Node::Sphere && !b.points.empty() && !b.values.empty()) {
    const double r = std::abs(b.values[0]);
    lo = b.points[0] - Vec3{r, r, r};
    hi = b.points[0] + Vec3{r, r, r};
  } else {
    return std::nullopt;
  }
  if (b.xforms.empty()) return std::array<Vec3, 2>{lo, hi};
  const std::optional<Transform> t = pov_transform(b.xforms);
  if (!t) return std::nullopt;
  Vec3 out_lo{kInfinity, kInfinity, kInfinity}, out_hi = -out_lo;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = t->point({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    out_lo = min(out_lo, p);
    out_hi = max(out_hi, p);
  }
  return std::array<Vec3, 2>{out_lo, out_hi};
}

// An intersection of a poly (which raycast needs bounded) with a box in the same space: the box
// becomes the poly's bounds (raycast's algebraic solid is the polynomial's inside closed by its
// box: the same solid) and leaves the intersection. With a sphere, the sphere's box bounds it.
void fold_poly_bounds(Node& n) {
  for (std::size_t k = 0; k < n.children.size(); ++k) {
    Node& p = n.children[k];
    if (p.kind != Node::Poly || p.bounds || !p.xforms.empty()) continue;
    for (std::size_t i = 0; i < n.children.size(); ++i) {
      const Node& b = n.children[i];
      if (b.kind == Node::Sphere && b.points.size() == 1 && !b.values.empty()) {
        // A sphere's box bounds the poly; the sphere stays in the intersection and cuts it.
        p.bounds = poly_bounds_of(b);
        break;
      }
      if (b.kind != Node::Box || !b.xforms.empty() || (b.texture && !p.texture)) continue;
      p.bounds = std::array<Vec3, 2>{b.points[0], b.points[1]};
      n.children.erase(n.children.begin() + static_cast<std::ptrdiff_t>(i));
      if (i < k) --k;  // the poly moved down by one
      break;
    }
  }
}

std::size_t weight(const Node& n) {
  std::size_t w = kPovNodeWeight + n.points.size() + n.vertices.size() + n.normals.size() +
                  n.triangles.size() + n.terms.size();
  for (const Node& c : n.children) w += weight(c);
  return w;
}

}  // namespace

void Interpreter::add_weight(std::size_t w, const Pos& at) {
  weight_ += w;
  if (weight_ > options_.limits.scene_weight)
    fail_at(at, "the scene is too large: its objects (" + std::to_string(kPovNodeWeight) +
                    " units each), points, vertices, triangles and terms exceed " +
                    std::to_string(options_.limits.scene_weight) +
                    " units (declared objects copied into each "
                    "other?)");
}

// A declared object placed by a new node: a composite is shared, not copied (a mesh of millions
// of triangles, a union of thousands of objects), the node placing it; a shape is copied.
void Interpreter::place_declared(const std::shared_ptr<const Node>& object, Node& n) {
  add_weight(object->weight, tok().pos);  // a use counts as a copy
  const Node::Kind k = object->kind;
  if (is_csg(k) || k == Node::Union || k == Node::Mesh || k == Node::Reference) {
    n.kind = Node::Reference;
    n.ref = object;
  } else {
    n = *object;
  }
}

bool Interpreter::is_declared_object() {
  const Token& t = tok();
  if (t.kind != Token::Word) return false;
  const Value* v = lookup(t.text);
  return v && v->kind == Value::Object;
}

// A declared object's name alone where an object may stand (POV-Ray reads it as
// object { Name }); nothing for an object raycast does not build.
std::optional<Node> Interpreter::bare_declared_object() {
  const Token t = tok();
  const std::shared_ptr<const Node> object = lookup(t.text)->object;
  if (!object) {
    next();
    return std::nullopt;
  }
  Node n;
  place_declared(object, n);
  next();
  n.pos = t.pos;
  n.name = t.text;
  n.weight = n.kind == Node::Reference ? n.ref->weight + kPovNodeWeight : weight(n);
  return n;
}

bool Interpreter::is_object_keyword() {
  const Token& t = tok();
  return t.kind == Token::Word && (object_kinds().count(t.text) || t.text == "object" ||
                                   t.text == "light_source" || is_unbuilt_shape(t.text));
}

long Interpreter::count(const char* what) {
  const Pos at = tok().pos;
  const double n = number(what);
  if (!(n >= 0 && n <= static_cast<double>(kMaxPovCount)) || n != std::floor(n))
    fail_at(at, std::string(what) + " must be a whole number in [0, " +
                    std::to_string(kMaxPovCount) + "], got " + std::to_string(n));
  return static_cast<long>(n);
}

std::optional<Node> Interpreter::object(int depth) {
  if (depth > kMaxPovNesting)
    fail_here("objects are nested deeper than " + std::to_string(kMaxPovNesting));
  // An object's depth restarts in a value declared inside it; the shared level bounds both.
  const NestingLevel level(*this);
  const Token kw = tok();
  if (kw.text == "light_source") return light_block();
  next();
  if (is_unbuilt_shape(kw.text)) {
    unsupported_warning(kw.pos, "the " + kw.text + " shape");
    skip_block(kw.text);
    return std::nullopt;
  }
  if (kw.text == "light_group") unsupported_warning(kw.pos, "light_group", "read as a union");
  expect_symbol("{", ("after " + kw.text).c_str());
  Node n;
  n.pos = kw.pos;
  bool skipped = false;  // an object raycast does not build: its modifiers are still read
  if (kw.text == "object") {
    const Value* v = tok().kind == Token::Word ? lookup(tok().text) : nullptr;
    const std::string declared_name = v ? tok().text : std::string();
    Value element;
    bool name_read = false;
    if (v && v->kind == Value::Array) {  // object { Objects[I] }
      const Pos at = tok().pos;
      element = expression();
      if (element.kind != Value::Object)
        fail_at(at, "expected an object, got " + std::string(kind_name(element)));
      v = &element;
      name_read = true;
    }
    if (!v || v->kind != Value::Object) {
      if (is_object_keyword()) {
        std::optional<Node> inner = object(depth + 1);
        if (inner)
          n = std::move(*inner);
        else
          skipped = true;
      } else {
        unexpected("a declared object's name or an object");
      }
    } else {
      if (v->object)
        place_declared(v->object, n);
      else
        skipped = true;
      if (!name_read) {
        n.name = declared_name;
        next();
      }
    }
  } else {
    n.kind = object_kinds().at(kw.text);
    if (n.kind == Node::Triangle)
      triangle_body(n, kw.text == "smooth_triangle");
    else
      object_body(n, depth);
    if (kw.text == "cubic" || kw.text == "quartic") {
      poly_coefficients(n, kw.text == "cubic" ? 3 : 4);
    } else if (kw.text == "poly") {
      const Pos at = tok().pos;
      const double order = number("poly's order");
      if (!(order >= 2 && order <= 35) || order != std::floor(order))
        fail_at(at, "poly's order must be a whole number in [2, 35]");
      skip_comma();
      poly_coefficients(n, static_cast<int>(order));
    } else if (kw.text == "polynomial") {
      polynomial_terms(n);
    } else if (kw.text == "mesh") {
      mesh_body(n, depth);
    } else if (kw.text == "mesh2") {
      mesh2_body(n, depth);
    }
  }
  while (!accept_symbol("}")) {
    if (is_csg(n.kind) && is_object_keyword()) {
      if (std::optional<Node> c = object(depth + 1)) n.children.push_back(std::move(*c));
      continue;
    }
    if (is_csg(n.kind) && is_declared_object()) {
      if (std::optional<Node> c = bare_declared_object()) n.children.push_back(std::move(*c));
      continue;
    }
    if (!modifier(n, depth)) unexpected("an object modifier in " + kw.text);
  }
  if (skipped) return std::nullopt;
  if (kw.text != "object") {  // its own data (children were counted when they were read)
    const std::size_t own = kPovNodeWeight + n.points.size() + n.vertices.size() +
                            n.normals.size() + n.triangles.size() + n.terms.size();
    add_weight(own, n.pos);
    n.weight = own;
    for (const Node& c : n.children) n.weight += c.weight;
  } else {
    n.weight = n.kind == Node::Reference ? n.ref->weight + kPovNodeWeight : weight(n);
  }
  if (n.kind == Node::Intersection) fold_poly_bounds(n);
  if (n.kind == Node::Poly && n.terms.empty()) fail_at(n.pos, "the polynomial has no terms");
  if (is_csg(n.kind) && n.children.empty()) return std::nullopt;  // every part left out
  return n;
}

// polynomial { ORDER, xyz(i, j, k): COEFFICIENT, ... }: the terms by their exponents.
void Interpreter::polynomial_terms(Node& n) {
  const Pos at = tok().pos;
  const double order = number("polynomial's order");
  if (!(order >= 1 && order <= 16) || order != std::floor(order))
    fail_at(at, "polynomial's order must be a whole number in [1, 16]");
  skip_comma();
  while (is_word("xyz")) {
    const Pos t = tok().pos;
    next();
    expect_symbol("(", "after xyz");
    std::array<int, 3> e{};
    for (int i = 0; i < 3; ++i) {
      const double v = number("an exponent");
      if (!(v >= 0 && v <= order) || v != std::floor(v))
        fail_at(t, "xyz exponents must be whole numbers in [0, order]");
      e[static_cast<std::size_t>(i)] = static_cast<int>(v);
      if (i < 2) expect_symbol(",", "between xyz exponents");
    }
    expect_symbol(")", "to close xyz(");
    expect_symbol(":", "after xyz(...)");
    if (e[0] + e[1] + e[2] > order) fail_at(t, "the term's degree is above the order");
    n.terms[e] += number("a coefficient");
    skip_comma();
  }
}

void Interpreter::object_body(Node& n, int depth) {
  switch (n.kind) {
    case Node::Sphere:
      n.points = {vector("sphere's centre")};
      skip_comma();
      n.values = {number("sphere's radius")};
      break;
    case Node::Box: {
      const Vec3 a = vector("box's corner");
      skip_comma();
      const Vec3 b = vector("box's corner");
      n.points = {Vec3{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                  Vec3{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
      break;
    }
    case Node::Plane:
      n.points = {vector("plane's normal")};
      skip_comma();
      n.values = {number("plane's distance")};
      break;
    case Node::Cylinder: {
      const Vec3 a = vector("cylinder's base");
      skip_comma();
      const Vec3 b = vector("cylinder's cap");
      skip_comma();
      n.points = {a, b};
      n.values = {number("cylinder's radius")};
      break;
    }
    case Node::Cone: {
      const Vec3 a = vector("cone's base");
      skip_comma();
      const double ra = number("cone's base radius");
      skip_comma();
      const Vec3 b = vector("cone's cap");
      skip_comma();
      const double rb = number("cone's cap radius");
      n.points = {a, b};
      n.values = {ra, rb};
      break;
    }
    case Node::Disc: {
      const Vec3 c = vector("disc's centre");
      skip_comma();
      const Vec3 nn = vector("disc's normal");
      skip_comma();
      n.points = {c, nn};
      n.values = {number("disc's radius"), 0};
      if (accept_symbol(",")) n.values[1] = number("disc's hole radius");
      break;
    }
    case Node::Torus: {
      const double major = number("torus's major radius");
      skip_comma();
      n.values = {major, number("torus's minor radius")};
      break;
    }
    case Node::Quadric: {
      for (int i = 0; i < 3; ++i) {
        const Vec3 v = vector("quadric's coefficients");
        skip_comma();
        n.values.insert(n.values.end(), {v.x, v.y, v.z});
      }
      n.values.push_back(number("quadric's constant"));
      break;
    }
    case Node::Isosurface:
      isosurface_body(n, depth);
      break;
    case Node::Lathe:
      spline_points(n, 2);
      break;
    case Node::Sor:
      spline_points(n, 4);
      break;
    case Node::Prism:
      prism_body(n);
      break;
    case Node::Text:
      text_body(n);
      break;
    case Node::Blob:
      blob_body(n, depth);
      break;
    default:
      break;  // poly, meshes: read by object(); CSG: children in the modifier loop
  }
}

void Interpreter::poly_coefficients(Node& n, int order) {
  expect_symbol("<", "to open the coefficients");
  std::vector<double> c;
  for (;;) {
    c.push_back(number_in_vector("a coefficient"));
    if (c.size() > 1000) fail_here("too many coefficients");
    accept_symbol(",");
    if (is_symbol(">")) break;
  }
  expect_symbol(">", "to close the coefficients");
  const std::size_t want = static_cast<std::size_t>((order + 1) * (order + 2) * (order + 3) / 6);
  if (c.size() != want)
    fail_at(n.pos, "a polynomial of order " + std::to_string(order) + " has " +
                       std::to_string(want) + " coefficients, got " + std::to_string(c.size()));
  // POV-Ray's order of terms: x^i y^j z^k by descending i, then j, then k.
  std::size_t at = 0;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) {
        if (c[at] != 0) n.terms[{i, j, k}] += c[at];
        ++at;
      }
}

void Interpreter::isosurface_body(Node& n, int depth) {
  double threshold = 0;
  std::shared_ptr<const FnNode> f;
  n.bounds = std::array<Vec3, 2>{Vec3{-1, -1, -1}, Vec3{1, 1, 1}};  // POV-Ray's default container
  // Items until the first object modifier (they may come in any order).
  for (;;) {
    const Pos at = tok().pos;
    if (is_word("function")) {
      next();
      expect_symbol("{", "after function");
      f = function_expression(depth, {"x", "y", "z"});
      expect_symbol("}", "to close the function");
    } else if (is_word("contained_by")) {
      next();
      expect_symbol("{", "after contained_by");
      if (is_word("box")) {
        next();
        expect_symbol("{", "after box");
        const Vec3 a = vector("box's corner");
        skip_comma();
        const Vec3 b = vector("box's corner");
        expect_symbol("}", "to close the box");
        n.bounds =
            std::array<Vec3, 2>{Vec3{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                                Vec3{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
        n.contained_by_sphere = false;
      } else if (is_word("sphere")) {
        next();
        expect_symbol("{", "after sphere");
        const Vec3 c = vector("sphere's centre");
        skip_comma();
        const double r = number("sphere's radius");
        expect_symbol("}", "to close the sphere");
        if (!(r > 0)) fail_at(at, "the containing sphere's radius must be > 0");
        n.bounds = std::array<Vec3, 2>{c - Vec3{r, r, r}, c + Vec3{r, r, r}};
        n.contained_by_sphere = true;
      } else {
        unexpected("box or sphere in contained_by");
      }
      expect_symbol("}", "to close contained_by");
    } else if (is_word("threshold")) {
      next();
      threshold = number("threshold");
    } else if (is_word("accuracy") || is_word("max_gradient") || is_word("max_trace")) {
      next();  // raycast's interval solver needs neither a gradient bound nor an accuracy
      number("an isosurface setting");
    } else if (is_word("all_intersections")) {
      next();
    } else if (is_word("open")) {
      next();
      n.open = boolean_option();
    } else if (is_word("evaluate")) {
      next();
      expression();
      skip_comma();
      expression();
      skip_comma();
      expression();
    } else {
      break;
    }
  }
  if (!f) fail_at(n.pos, "an isosurface needs a function { ... }");
  if (threshold != 0) {
    auto t = std::make_shared<FnNode>();
    t->number = threshold;
    auto s = std::make_shared<FnNode>();
    s->kind = FnNode::Subtract;
    s->args = {f, t};
    f = s;
  }
  n.function = f;
  if (n.open && n.contained_by_sphere) {
    unsupported_warning(n.pos, "open isosurfaces in a sphere", "closed by the sphere's box");
    n.contained_by_sphere = false;
  }
}

void Interpreter::spline_points(Node& n, int min_count) {
  std::string spline = "linear_spline";
  if (n.kind == Node::Lathe) {
    if (is_word("linear_spline") || is_word("cubic_spline") || is_word("bezier_spline")) {
      spline = tok().text;
      next();
    } else if (is_word("quadratic_spline")) {
      unsupported_warning(tok().pos, "quadratic_spline lathes", "drawn as a cubic_spline");
      next();
      spline = "cubic_spline";
    }
  }
  const Pos at = tok().pos;
  const long cnt = count("the number of points");
  if (spline == "cubic_spline") min_count = 4;
  if (cnt < min_count) fail_at(at, "needs at least " + std::to_string(min_count) + " points");
  if (spline == "bezier_spline" && cnt % 4 != 0)
    fail_at(at, "a bezier_spline needs a multiple of 4 points");
  if (cnt > 100000) fail_at(at, "at most 100000 points");
  std::vector<Vec3> p;
  for (long i = 0; i < cnt; ++i) {
    skip_comma();
    const Pos v = tok().pos;
    const Value pt = expression();
    if (pt.dims != 2) fail_at(v, "expected a 2-vector <r, y>");
    p.push_back({pt.v[0], pt.v[1], 0});
  }
  // raycast's revolution joins points with segments: splines are sampled into line segments.
  std::vector<Vec3> out;
  auto add = [&](const Vec3& q) {
    if (out.empty() || !(out.back().x == q.x && out.back().y == q.y)) out.push_back(q);
  };
  if (n.kind == Node::Sor) {
    for (std::size_t i = 0; i + 3 < p.size(); ++i) {
      const double y1 = p[i + 1].y, y2 = p[i + 2].y;
      if (!(p[i + 2].y > p[i].y && p[i + 3].y > p[i + 1].y && y2 > y1))
        fail_at(n.pos, "a sor's points must rise in y (each point's y above the one before)");
      // r^2 is a cubic in y through the two middle points, with slopes from their neighbours.
      const double k1 = p[i + 1].x * p[i + 1].x, k2 = p[i + 2].x * p[i + 2].x;
      const double s1 = (k2 - p[i].x * p[i].x) / (p[i + 2].y - p[i].y);
      const double s2 = (p[i + 3].x * p[i + 3].x - k1) / (p[i + 3].y - p[i + 1].y);
      const double h = y2 - y1;
      for (int s = 0; s <= kSplineSamples; ++s) {
        const double u = static_cast<double>(s) / kSplineSamples;
        const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
        const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
        const double r2 = h00 * k1 + h10 * h * s1 + h01 * k2 + h11 * h * s2;
        add({std::sqrt(std::max(0.0, r2)), y1 + u * h, 0});
      }
    }
  } else if (spline == "linear_spline") {
    for (const Vec3& q : p) add(q);
  } else if (spline == "cubic_spline") {
    for (std::size_t i = 0; i + 3 < p.size(); ++i)
      for (int s = 0; s <= kSplineSamples; ++s) {
        const double u = static_cast<double>(s) / kSplineSamples;
        // Catmull-Rom from p[i+1] to p[i+2].
        const Vec3 a = (p[i + 1] * 3.0 - p[i + 2] * 3.0 + p[i + 3] - p[i]) * 0.5;
        const Vec3 b = (p[i] * 2.0 - p[i + 1] * 5.0 + p[i + 2] * 4.0 - p[i + 3]) * 0.5;
        const Vec3 c = (p[i + 2] - p[i]) * 0.5;
        add(((a * u + b) * u + c) * u + p[i + 1]);
      }
  } else {  // bezier_spline
    for (std::size_t i = 0; i + 3 < p.size(); i += 4)
      for (int s = 0; s <= kSplineSamples; ++s) {
        const double u = static_cast<double>(s) / kSplineSamples, w = 1 - u;
        add(p[i] * (w * w * w) + p[i + 1] * (3 * w * w * u) + p[i + 2] * (3 * w * u * u) +
            p[i + 3] * (u * u * u));
      }
  }
  n.points = revolved_profile(out);
  n.spline = spline;
}

// triangle { P0, P1, P2 } or smooth_triangle { P0, N0, P1, N1, P2, N2 }: the corners in
// points, the normals in normals.
void Interpreter::triangle_body(Node& n, bool smooth) {
  std::array<Vec3, 3> p, nn;
  for (std::size_t i = 0; i < 3; ++i) {
    if (i) skip_comma();
    p[i] = vector("a triangle's corner");
    if (smooth) {
      skip_comma();
      nn[i] = vector("a triangle's corner normal");
    }
  }
  n.points.assign(p.begin(), p.end());
  if (smooth) n.normals.assign(nn.begin(), nn.end());
}

void Interpreter::mesh_body(Node& n, int) {
  std::map<std::array<double, 6>, int> index;
  bool any_smooth = false, any_flat = false;
  auto vertex = [&](const Vec3& p, const Vec3& nn) {
    const std::array<double, 6> key{p.x, p.y, p.z, nn.x, nn.y, nn.z};
    const auto [it, added] = index.emplace(key, static_cast<int>(n.vertices.size()));
    if (added) {
      n.vertices.push_back(p);
      n.normals.push_back(nn);
    }
    return it->second;
  };
  while (is_word("triangle") || is_word("smooth_triangle")) {
    const bool smooth = is_word("smooth_triangle");
    next();
    expect_symbol("{", "after triangle");
    std::array<Vec3, 3> p, nn{};
    for (int i = 0; i < 3; ++i) {
      if (i) skip_comma();
      p[static_cast<std::size_t>(i)] = vector("a vertex");
      if (smooth) {
        skip_comma();
        nn[static_cast<std::size_t>(i)] = vector("a vertex normal");
      }
    }
    while (!accept_symbol("}")) {  // a texture per triangle: raycast has one per mesh
      if (!is_word("texture")) unexpected("'}' or a texture to close the triangle");
      next();
      skip_block("texture");
      unsupported_warning(tok().pos, "textures per mesh triangle");
    }
    (smooth ? any_smooth : any_flat) = true;
    n.triangles.push_back({vertex(p[0], nn[0]), vertex(p[1], nn[1]), vertex(p[2], nn[2])});
    if (n.triangles.size() > static_cast<std::size_t>(kMaxPovCount))
      fail_here("a mesh has at most " + std::to_string(kMaxPovCount) + " triangles");
  }
  if (any_smooth && any_flat)
    unsupported_warning(n.pos, "meshes mixing triangle and smooth_triangle");
  if (!any_smooth) n.normals.clear();
  if (n.triangles.empty()) fail_at(n.pos, "the mesh has no triangles");
  if (is_word("inside_vector")) {
    next();
    vector("inside_vector");
  }
}

void Interpreter::mesh2_body(Node& n, int) {
  auto block = [&](const char* name, int dims, auto&& each) {
    next();
    expect_symbol("{", (std::string("after ") + name).c_str());
    const long cnt = count((std::string("the number of ") + name).c_str());
    for (long i = 0; i < cnt; ++i) {
      skip_comma();
      const Pos at = tok().pos;
      const Value v = item_expression();
      if (v.dims != dims)
        fail_at(at, std::string(name) + " holds " + std::to_string(dims) + "-vectors");
      each(v, at);
      // face_indices may give each face's texture index (or three): read and not used.
      if (std::string(name) == "face_indices")
        for (int k = 0; k < 3 && pov::is_symbol(peek_operator(), ",") && !pending_; ++k) {
          next();
          if (tok().kind != Token::Number && !(tok().kind == Token::Word && lookup(tok().text) &&
                                               lookup(tok().text)->kind == Value::Float))
            break;
          number("a texture index");
        }
    }
    accept_symbol(",");  // POV-Ray accepts a comma after the last item
    if (!is_symbol("}"))
      fail_here(std::string(name) + " announced " + std::to_string(cnt) + " items, got more");
    next();
  };
  std::vector<Vec3> verts, norms;
  std::vector<std::array<long, 3>> faces, face_normals;
  std::vector<Pos> face_pos, normal_pos;
  if (is_word("vertex_vectors"))
    block("vertex_vectors", 3, [&](const Value& v, const Pos&) {
      verts.push_back({v.v[0], v.v[1], v.v[2]});
    });
  else
    unexpected("vertex_vectors in mesh2");
  if (is_word("normal_vectors"))
    block("normal_vectors", 3, [&](const Value& v, const Pos&) {
      norms.push_back({v.v[0], v.v[1], v.v[2]});
    });
  while (is_word("uv_vectors") || is_word("texture_list")) {
    const std::string w = tok().text;
    next();
    skip_block(w);
  }
  auto index_block = [&](const char* name, auto& out, auto& pos) {
    block(name, 3, [&](const Value& v, const Pos& at) {
      std::array<long, 3> f{};
      for (int i = 0; i < 3; ++i) {
        const double x = v.v[static_cast<std::size_t>(i)];
        if (x < 0 || x != std::floor(x) || x > static_cast<double>(kMaxPovCount))
          fail_at(at, std::string(name) + ": indices must be whole numbers >= 0");
        f[static_cast<std::size_t>(i)] = static_cast<long>(x);
      }
      out.push_back(f);
      pos.push_back(at);
    });
  };
  if (is_word("face_indices"))
    index_block("face_indices", faces, face_pos);
  else
    unexpected("face_indices in mesh2");
  if (is_word("normal_indices")) index_block("normal_indices", face_normals, normal_pos);
  while (is_word("uv_indices") || is_word("normal_indices")) {  // uv coordinates: not used
    next();
    skip_block("uv_indices");
  }
  if (is_word("inside_vector")) {
    next();
    vector("inside_vector");
  }
  if (faces.empty()) fail_at(n.pos, "the mesh2 has no faces");
  if (!face_normals.empty() && face_normals.size() != faces.size())
    fail_at(n.pos, "normal_indices must have one entry per face");
  if (face_normals.empty() && !norms.empty() && norms.size() != verts.size())
    fail_at(n.pos, "without normal_indices, normal_vectors must have one normal per vertex");
  if (face_normals.empty()) {
    // Vertices and their normals (if any) correspond one to one: the indices stay as written.
    for (std::size_t f = 0; f < faces.size(); ++f) {
      for (std::size_t k = 0; k < 3; ++k)
        if (faces[f][k] >= static_cast<long>(verts.size()))
          fail_at(face_pos[f], "face " + std::to_string(f) + ": vertex index " +
                                   std::to_string(faces[f][k]) + " out of range (" +
                                   std::to_string(verts.size()) + " vertices)");
      n.triangles.push_back({static_cast<int>(faces[f][0]), static_cast<int>(faces[f][1]),
                             static_cast<int>(faces[f][2])});
    }
    n.vertices = std::move(verts);
    n.normals = std::move(norms);
    return;
  }
  std::map<std::pair<long, long>, int> index;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::array<int, 3> tri{};
    for (std::size_t k = 0; k < 3; ++k) {
      const long vi = faces[f][k];
      if (vi >= static_cast<long>(verts.size()))
        fail_at(face_pos[f], "face " + std::to_string(f) + ": vertex index " + std::to_string(vi) +
                                 " out of range (" + std::to_string(verts.size()) + " vertices)");
      long ni = norms.empty() ? -1 : face_normals.empty() ? vi : face_normals[f][k];
      if (ni >= static_cast<long>(norms.size()))
        fail_at(normal_pos[f], "normal index " + std::to_string(ni) + " out of range");
      const auto [it, added] =
          index.emplace(std::make_pair(vi, ni), static_cast<int>(n.vertices.size()));
      if (added) {
        n.vertices.push_back(verts[static_cast<std::size_t>(vi)]);
        if (ni >= 0) n.normals.push_back(norms[static_cast<std::size_t>(ni)]);
      }
      tri[k] = it->second;
    }
    n.triangles.push_back(tri);
  }
}

bool Interpreter::modifier(Node& n, int depth) {
  const Token t = tok();
  const std::string& w = t.text;
  // Transformations written after an object's first texture item move the texture with it.
  auto own_texture = [&]() -> Texture& {
    if (!n.texture) {
      n.texture = default_texture_;
      n.texture_at = n.xforms.size();
    }
    return *n.texture;
  };
  if (t.kind != Token::Word) return false;
  const std::size_t placed = n.xforms.size();
  if (transform_item(n.xforms)) {
    // POV-Ray moves an object's clipping objects with it from where they are attached on.
    for (Node& c : n.clipped_by)
      c.xforms.insert(c.xforms.end(), n.xforms.begin() + std::ptrdiff_t(placed), n.xforms.end());
    return true;
  }
  if (w == "texture") {
    next();
    const std::optional<Interior> interior =
        n.texture ? n.texture->interior : std::optional<Interior>{};
    if (!n.texture) n.texture_at = n.xforms.size();
    Texture layer = texture_block(default_texture_, depth + 1);
    // A second texture is laid over the first (layered textures).
    n.texture =
        n.texture ? layer_on_top(std::move(*n.texture), std::move(layer)) : std::move(layer);
    if (!n.texture->interior) n.texture->interior = interior;
  } else if (w == "pigment") {
    next();
    Texture& tx = own_texture();
    tx.pigment = pigment_block(tx.pigment);
    tx.name.clear();
  } else if (w == "finish") {
    next();
    Texture& tx = own_texture();
    tx.finish = finish_block(tx.finish);
    tx.name.clear();
  } else if (w == "normal") {
    next();
    Texture& tx = own_texture();
    tx.normal = normal_block(tx.normal);
    tx.name.clear();
  } else if (w == "interior") {
    next();
    const Interior interior = interior_block();
    Texture& tx = own_texture();
    tx.interior = interior;
    tx.name.clear();
  } else if (w == "material") {
    next();
    if (!n.texture) n.texture_at = n.xforms.size();
    n.texture = material_block(n.texture ? *n.texture : default_texture_, depth + 1);
  } else if (w == "global_lights" && n.kind == Node::Union) {
    next();
    boolean_option();
  } else if (w == "hollow" || w == "sturm" || w == "no_shadow" || w == "no_image" ||
             w == "no_reflection" || w == "double_illuminate" || w == "no_radiosity" ||
             w == "split_union" || w == "cutaway_textures" || w == "uv_mapping" ||
             w == "all_intersections") {
    next();
    bool on = true;
    if (w != "cutaway_textures" && w != "uv_mapping" && w != "all_intersections")
      on = boolean_option();
    if (w == "no_shadow")
      n.no_shadow = on;
    else if (w == "no_image")
      n.no_image = on;
    else if (w == "no_reflection")
      n.no_reflection = on;
    else if (w == "double_illuminate")
      unsupported_warning(t.pos, w);
  } else if (w == "inverse") {
    next();
    n.inverse = !n.inverse;
  } else if (w == "open" &&
             (n.kind == Node::Cylinder || n.kind == Node::Cone || n.kind == Node::Sor ||
              n.kind == Node::Lathe || n.kind == Node::Isosurface || n.kind == Node::Prism)) {
    next();
    n.open = boolean_option();
  } else if (w == "bounded_by") {
    next();
    expect_symbol("{", "after bounded_by");
    if (is_word("clipped_by")) {
      next();  // the clipping objects bound it: nothing to keep
    } else {
      n.bounded_by.clear();
      while (!is_symbol("}")) {
        std::optional<Node> b = object(depth + 1);
        if (!b) continue;
        // Only an optimisation in POV-Ray; a poly needs it as its bounds in raycast (in its own
        // space: before any transformation of the poly).
        if (n.kind == Node::Poly && n.xforms.empty())
          if (const auto box = poly_bounds_of(*b)) n.bounds = box;
        n.bounded_by.push_back(std::move(*b));  // for clipped_by { bounded_by }
      }
    }
    expect_symbol("}", "to close bounded_by");
  } else if (w == "clipped_by") {
    next();
    expect_symbol("{", "after clipped_by");
    if (is_word("bounded_by")) {
      next();
      n.clipped_by.insert(n.clipped_by.end(), n.bounded_by.begin(), n.bounded_by.end());
    } else {
      while (!is_symbol("}"))
        if (std::optional<Node> c = object(depth + 1)) n.clipped_by.push_back(std::move(*c));
    }
    expect_symbol("}", "to close clipped_by");
  } else if (w == "photons" || w == "radiosity" || w == "interior_texture" || w == "texture_list" ||
             w == "uv_vectors") {
    next();
    if (w != "texture_list" && w != "uv_vectors") unsupported_warning(t.pos, w);
    skip_block(w);
  } else {
    return false;
  }
  return true;
}

}  // namespace raycast::pov
