// Objects of the POV-Ray subset: the shapes, CSG, `object { Name }`, and their modifiers
// (transformations, textures, interiors). Shapes keep POV-Ray's own parameters and coordinates;
// yaml_writer maps them to raycast's shapes.
#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "pov/parser_impl.h"

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
                                                          {"mesh", Node::Mesh},
                                                          {"mesh2", Node::Mesh},
                                                          {"union", Node::Union},
                                                          {"intersection", Node::Intersection},
                                                          {"difference", Node::Difference},
                                                          {"merge", Node::Merge}};
  return kinds;
}

bool is_csg(Node::Kind k) {
  return k == Node::Union || k == Node::Intersection || k == Node::Difference || k == Node::Merge;
}

constexpr int kSplineSamples = 16;  // line segments per spline segment of a lathe or sor

// An intersection of a poly (which raycast needs bounded) with a box in the same space: the box
// becomes the poly's bounds (raycast's algebraic solid is the polynomial's inside closed by its
// box: the same solid) and leaves the intersection.
void fold_poly_bounds(Node& n) {
  for (std::size_t k = 0; k < n.children.size(); ++k) {
    Node& p = n.children[k];
    if (p.kind != Node::Poly || p.bounds || !p.xforms.empty()) continue;
    for (std::size_t i = 0; i < n.children.size(); ++i) {
      const Node& b = n.children[i];
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

void Parser::add_weight(std::size_t w, const Pos& at) {
  weight_ += w;
  if (weight_ > kMaxPovWeight)
    fail_at(at, "the scene is too large: its objects (" + std::to_string(kPovNodeWeight) +
                    " units each), points, vertices, triangles and terms exceed " +
                    std::to_string(kMaxPovWeight) +
                    " units (declared objects copied into each "
                    "other?)");
}

bool Parser::is_object_keyword() const {
  return tok().kind == Token::Word && (object_kinds().count(tok().text) || tok().text == "object");
}

long Parser::count(const char* what) {
  const Pos at = tok().pos;
  const double n = number(what);
  if (!(n >= 0 && n <= static_cast<double>(kMaxPovCount)) || n != std::floor(n))
    fail_at(at, std::string(what) + " must be a whole number in [0, " +
                    std::to_string(kMaxPovCount) + "], got " + std::to_string(n));
  return static_cast<long>(n);
}

Node Parser::object(int depth) {
  if (depth > kMaxPovNesting)
    fail_here("objects are nested deeper than " + std::to_string(kMaxPovNesting));
  const Token kw = tok();
  next();
  expect_symbol('{', ("after " + kw.text).c_str());
  Node n;
  n.pos = kw.pos;
  if (kw.text == "object") {
    const auto it = tok().kind == Token::Word ? symbols_.find(tok().text) : symbols_.end();
    if (it == symbols_.end() || it->second.kind != Declared::Object) {
      if (is_object_keyword())
        n = object(depth + 1);
      else
        unexpected("a declared object's name or an object");
    } else {
      add_weight(weight(*it->second.node), tok().pos);  // a copy
      n = *it->second.node;
      next();
    }
  } else {
    n.kind = object_kinds().at(kw.text);
    object_body(n, depth);
    if (kw.text == "cubic" || kw.text == "quartic") {
      poly_coefficients(n, kw.text == "cubic" ? 3 : 4);
    } else if (kw.text == "poly") {
      const Pos at = tok().pos;
      const double order = number("poly's order");
      if (!(order >= 2 && order <= 16) || order != std::floor(order))
        fail_at(at,
                "poly's order must be a whole number in [2, 16] (raycast's algebraic "
                "surfaces go to degree 16)");
      skip_comma();
      poly_coefficients(n, static_cast<int>(order));
    } else if (kw.text == "polynomial") {
      const Pos at = tok().pos;
      const double order = number("polynomial's order");
      if (!(order >= 1 && order <= 16) || order != std::floor(order))
        fail_at(at, "polynomial's order must be a whole number in [1, 16]");
      skip_comma();
      while (is_word("xyz")) {
        const Pos t = tok().pos;
        next();
        expect_symbol('(', "after xyz");
        std::array<int, 3> e{};
        for (int i = 0; i < 3; ++i) {
          const double v = number("an exponent");
          if (!(v >= 0 && v <= order) || v != std::floor(v))
            fail_at(t, "xyz exponents must be whole numbers in [0, order]");
          e[static_cast<std::size_t>(i)] = static_cast<int>(v);
          if (i < 2) expect_symbol(',', "between xyz exponents");
        }
        expect_symbol(')', "to close xyz(");
        expect_symbol(':', "after xyz(...)");
        if (e[0] + e[1] + e[2] > order) fail_at(t, "the term's degree is above the order");
        n.terms[e] += number("a coefficient");
        skip_comma();
      }
    } else if (kw.text == "mesh") {
      mesh_body(n, depth);
    } else if (kw.text == "mesh2") {
      mesh2_body(n, depth);
    }
  }
  while (!accept_symbol('}')) {
    if (directive()) continue;
    if (is_csg(n.kind) && is_object_keyword()) {
      n.children.push_back(object(depth + 1));
      continue;
    }
    if (!modifier(n, depth)) unexpected(("an object modifier in " + kw.text).c_str());
  }
  if (kw.text != "object")  // its own data (children were counted when they were read)
    add_weight(kPovNodeWeight + n.points.size() + n.vertices.size() + n.normals.size() +
                   n.triangles.size() + n.terms.size(),
               n.pos);
  if (n.kind == Node::Intersection) fold_poly_bounds(n);
  if (n.kind == Node::Poly && n.terms.empty()) fail_at(n.pos, "the polynomial has no terms");
  if (is_csg(n.kind) && n.children.empty()) fail_at(n.pos, kw.text + " needs at least one object");
  return n;
}

void Parser::object_body(Node& n, int depth) {
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
      if (accept_symbol(',')) n.values[1] = number("disc's hole radius");
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
    default:
      break;  // poly, meshes: read by object(); CSG: children in the modifier loop
  }
}

void Parser::poly_coefficients(Node& n, int order) {
  expect_symbol('<', "to open the coefficients");
  std::vector<double> c;
  for (;;) {
    c.push_back(number("a coefficient"));
    if (c.size() > 1000) fail_here("too many coefficients");
    if (!accept_symbol(',')) break;
  }
  expect_symbol('>', "to close the coefficients");
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

std::shared_ptr<const FnNode> Parser::function_expression(int depth) {
  if (depth > kMaxPovNesting) fail_here("the function is nested too deeply");
  auto make = [](FnNode::Kind k, std::vector<std::shared_ptr<const FnNode>> args) {
    auto f = std::make_shared<FnNode>();
    f->kind = k;
    f->args = std::move(args);
    return std::shared_ptr<const FnNode>(f);
  };
  auto num = [](double v) {
    auto f = std::make_shared<FnNode>();
    f->number = v;
    return std::shared_ptr<const FnNode>(f);
  };
  std::function<std::shared_ptr<const FnNode>(int)> unary, power, primary;
  primary = [&](int d) -> std::shared_ptr<const FnNode> {
    if (d > kMaxPovNesting) fail_here("the function is nested too deeply");
    const Token t = tok();
    if (t.kind == Token::Number) {
      next();
      return num(t.number);
    }
    if (accept_symbol('(')) {
      auto e = function_expression(d + 1);
      expect_symbol(')', "to close '('");
      return e;
    }
    if (t.kind != Token::Word) unexpected("a number, x, y, z, a function or '('");
    next();
    if (t.text == "x" || t.text == "y" || t.text == "z") {
      auto f = std::make_shared<FnNode>();
      f->kind = FnNode::Variable;
      f->variable = t.text[0];
      return f;
    }
    if (t.text == "pi") return num(std::numbers::pi);
    if (const auto it = symbols_.find(t.text); it != symbols_.end()) {
      if (it->second.kind != Declared::Value || it->second.val.dims != 1)
        fail_at(t.pos, "'" + t.text + "' is not a float (functions take floats)");
      return num(it->second.val.v[0]);
    }
    static const std::map<std::string, std::pair<std::string, int>> fns = {
        {"sin", {"sin", 1}}, {"cos", {"cos", 1}}, {"tan", {"tan", 1}}, {"sqrt", {"sqrt", 1}},
        {"exp", {"exp", 1}}, {"ln", {"log", 1}},  {"log", {"log", 1}}, {"abs", {"abs", 1}},
        {"min", {"min", 2}}, {"max", {"max", 2}}, {"pow", {"pow", 2}}};
    const auto fn = fns.find(t.text);
    if (fn == fns.end()) fail_at(t.pos, unsupported(t.text) + " in an isosurface function");
    expect_symbol('(', ("after " + t.text).c_str());
    std::vector<std::shared_ptr<const FnNode>> args;
    for (;;) {
      args.push_back(function_expression(d + 1));
      if (!accept_symbol(',')) break;
    }
    expect_symbol(')', ("to close " + t.text + "(").c_str());
    if (static_cast<int>(args.size()) != fn->second.second)
      fail_at(t.pos, t.text + " takes " + std::to_string(fn->second.second) + " argument(s)");
    auto call = std::make_shared<FnNode>();
    call->kind = FnNode::Call;
    call->function = fn->second.first;
    call->args = std::move(args);
    if (t.text == "log")  // POV-Ray's log is decimal
      return make(FnNode::Divide, {call, num(std::log(10.0))});
    return call;
  };
  power = [&](int d) {
    auto base = primary(d);
    if (accept_symbol('^')) return make(FnNode::Power, {base, unary(d + 1)});
    return base;
  };
  unary = [&](int d) -> std::shared_ptr<const FnNode> {
    if (d > kMaxPovNesting) fail_here("the function is nested too deeply");
    if (accept_symbol('-')) return make(FnNode::Negate, {unary(d + 1)});
    if (accept_symbol('+')) return unary(d + 1);
    return power(d);
  };
  auto term = [&]() {
    auto v = unary(depth);
    for (;;) {
      if (accept_symbol('*'))
        v = make(FnNode::Multiply, {v, unary(depth)});
      else if (accept_symbol('/'))
        v = make(FnNode::Divide, {v, unary(depth)});
      else
        return v;
    }
  };
  auto v = term();
  for (;;) {
    if (accept_symbol('+'))
      v = make(FnNode::Add, {v, term()});
    else if (accept_symbol('-'))
      v = make(FnNode::Subtract, {v, term()});
    else
      return v;
  }
}

void Parser::isosurface_body(Node& n, int depth) {
  double threshold = 0;
  std::shared_ptr<const FnNode> f;
  n.bounds = std::array<Vec3, 2>{Vec3{-1, -1, -1}, Vec3{1, 1, 1}};  // POV-Ray's default container
  // Items until the first object modifier (they may come in any order).
  for (;;) {
    const Pos at = tok().pos;
    if (is_word("function")) {
      next();
      expect_symbol('{', "after function");
      f = function_expression(depth);
      expect_symbol('}', "to close the function");
    } else if (is_word("contained_by")) {
      next();
      expect_symbol('{', "after contained_by");
      if (is_word("box")) {
        next();
        expect_symbol('{', "after box");
        const Vec3 a = vector("box's corner");
        skip_comma();
        const Vec3 b = vector("box's corner");
        expect_symbol('}', "to close the box");
        n.bounds =
            std::array<Vec3, 2>{Vec3{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                                Vec3{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
        n.contained_by_sphere = false;
      } else if (is_word("sphere")) {
        next();
        expect_symbol('{', "after sphere");
        const Vec3 c = vector("sphere's centre");
        skip_comma();
        const double r = number("sphere's radius");
        expect_symbol('}', "to close the sphere");
        if (!(r > 0)) fail_at(at, "the containing sphere's radius must be > 0");
        n.bounds = std::array<Vec3, 2>{c - Vec3{r, r, r}, c + Vec3{r, r, r}};
        n.contained_by_sphere = true;
      } else {
        unexpected("box or sphere in contained_by");
      }
      expect_symbol('}', "to close contained_by");
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
      fail_here(unsupported("evaluate"));
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
  if (n.open && n.contained_by_sphere)
    fail_at(n.pos, unsupported("open isosurface contained_by a sphere") + " (use a box)");
}

void Parser::spline_points(Node& n, int min_count) {
  std::string spline = "linear_spline";
  if (n.kind == Node::Lathe) {
    if (is_word("linear_spline") || is_word("cubic_spline") || is_word("bezier_spline")) {
      spline = tok().text;
      next();
    } else if (is_word("quadratic_spline")) {
      fail_here(unsupported("quadratic_spline"));
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
    const Val pt = expression();
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
        fail_at(n.pos, "a sor's points must rise in y");
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
  for (const Vec3& q : out)
    if (q.x < 0)
      fail_at(n.pos, "profile radii must be >= 0 (raycast revolves r >= 0 about the axis)");
  n.points = out;
  n.spline = spline;
}

void Parser::mesh_body(Node& n, int) {
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
    expect_symbol('{', "after triangle");
    std::array<Vec3, 3> p, nn{};
    for (int i = 0; i < 3; ++i) {
      if (i) skip_comma();
      p[static_cast<std::size_t>(i)] = vector("a vertex");
      if (smooth) {
        skip_comma();
        nn[static_cast<std::size_t>(i)] = vector("a vertex normal");
      }
    }
    if (!is_symbol('}'))
      fail_here(unsupported(describe(tok()) + " in a mesh triangle") + " (textures per triangle)");
    next();
    (smooth ? any_smooth : any_flat) = true;
    n.triangles.push_back({vertex(p[0], nn[0]), vertex(p[1], nn[1]), vertex(p[2], nn[2])});
    if (n.triangles.size() > static_cast<std::size_t>(kMaxPovCount))
      fail_here("a mesh has at most " + std::to_string(kMaxPovCount) + " triangles");
  }
  if (any_smooth && any_flat)
    fail_at(n.pos, unsupported("a mesh mixing triangle and smooth_triangle"));
  if (!any_smooth) n.normals.clear();
  if (n.triangles.empty()) fail_at(n.pos, "the mesh has no triangles");
  if (is_word("inside_vector")) {
    next();
    vector("inside_vector");
  }
}

void Parser::mesh2_body(Node& n, int) {
  auto block = [&](const char* name, int dims, auto&& each) {
    next();
    expect_symbol('{', (std::string("after ") + name).c_str());
    const long cnt = count((std::string("the number of ") + name).c_str());
    for (long i = 0; i < cnt; ++i) {
      skip_comma();
      const Pos at = tok().pos;
      const Val v = expression();
      if (v.dims != dims)
        fail_at(at, std::string(name) + " holds " + std::to_string(dims) + "-vectors");
      each(v, at);
    }
    if (!is_symbol('}'))
      fail_here(std::string(name) + " announced " + std::to_string(cnt) + " items, got more");
    next();
  };
  std::vector<Vec3> verts, norms;
  std::vector<std::array<long, 3>> faces, face_normals;
  std::vector<Pos> face_pos, normal_pos;
  if (is_word("vertex_vectors"))
    block("vertex_vectors", 3, [&](const Val& v, const Pos&) {
      verts.push_back({v.v[0], v.v[1], v.v[2]});
    });
  else
    unexpected("vertex_vectors in mesh2");
  if (is_word("normal_vectors"))
    block("normal_vectors", 3, [&](const Val& v, const Pos&) {
      norms.push_back({v.v[0], v.v[1], v.v[2]});
    });
  if (is_word("uv_vectors") || is_word("texture_list")) fail_here(unsupported(tok().text));
  auto index_block = [&](const char* name, auto& out, auto& pos) {
    block(name, 3, [&](const Val& v, const Pos& at) {
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
  if (is_word("inside_vector")) {
    next();
    vector("inside_vector");
  }
  if (faces.empty()) fail_at(n.pos, "the mesh2 has no faces");
  if (!face_normals.empty() && face_normals.size() != faces.size())
    fail_at(n.pos, "normal_indices must have one entry per face");
  if (face_normals.empty() && !norms.empty() && norms.size() != verts.size())
    fail_at(n.pos, "without normal_indices, normal_vectors must have one normal per vertex");
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

bool Parser::modifier(Node& n, int depth) {
  const Pos at = tok().pos;
  auto own_texture = [&]() -> Texture& {
    if (!n.texture) n.texture = default_texture_;
    return *n.texture;
  };
  if (is_word("translate") || is_word("scale") || is_word("rotate")) {
    XformOp op;
    op.kind = is_word("translate") ? XformOp::Translate
              : is_word("scale")   ? XformOp::Scale
                                   : XformOp::Rotate;
    next();
    op.v = vector("the transformation");
    if (op.kind == XformOp::Scale && (op.v.x == 0 || op.v.y == 0 || op.v.z == 0))
      fail_at(at, "scale must not be 0 on any axis");
    n.xforms.push_back(op);
  } else if (is_word("matrix")) {
    next();
    expect_symbol('<', "after matrix");
    XformOp op;
    op.kind = XformOp::Matrix;
    for (int i = 0; i < 12; ++i) {
      if (i) expect_symbol(',', "between the matrix's 12 values");
      op.m[static_cast<std::size_t>(i)] = number("a matrix value");
    }
    expect_symbol('>', "after the matrix's 12 values");
    n.xforms.push_back(op);
  } else if (is_word("texture")) {
    next();
    const std::optional<double> ior = n.texture ? n.texture->ior : std::nullopt;
    n.texture = texture_block(default_texture_, depth + 1);
    if (!n.texture->ior) n.texture->ior = ior;
  } else if (is_word("pigment")) {
    next();
    Texture& t = own_texture();
    t.pigment = pigment_block(t.pigment);
    t.name.clear();
  } else if (is_word("finish")) {
    next();
    Texture& t = own_texture();
    t.finish = finish_block(t.finish);
    t.name.clear();
  } else if (is_word("interior")) {
    next();
    const std::optional<double> ior = interior_block();
    Texture& t = own_texture();
    t.ior = ior;
    t.name.clear();
  } else if (is_word("material")) {
    next();
    n.texture = material_block(default_texture_, depth + 1);
  } else if (is_word("hollow")) {
    next();
    boolean_option();  // only matters for media, which the subset has not
  } else if (is_word("sturm")) {
    next();
    boolean_option();  // raycast's polynomial solver always isolates every root
  } else if (is_word("open") &&
             (n.kind == Node::Cylinder || n.kind == Node::Cone || n.kind == Node::Sor)) {
    next();
    n.open = boolean_option();
  } else if (is_word("bounded_by")) {
    next();
    expect_symbol('{', "after bounded_by");
    if (!is_word("box")) unexpected("a box in bounded_by");
    const Node b = object(depth + 1);
    expect_symbol('}', "to close bounded_by");
    if (!b.xforms.empty()) fail_at(b.pos, unsupported("a transformed bounded_by box"));
    // Only an optimisation in POV-Ray; a poly needs it as its bounds in raycast.
    if (n.kind == Node::Poly) n.bounds = std::array<Vec3, 2>{b.points[0], b.points[1]};
  } else {
    return false;
  }
  return true;
}

}  // namespace raycast::pov
