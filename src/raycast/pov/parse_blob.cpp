// blob { ... }: the threshold and the components, read into a node with one child per component.
#include <string>

#include "pov/interpreter.h"

namespace raycast::pov {

namespace {

// The most components one blob may have (the engine's own bound, geometry/blob.h).
constexpr std::size_t kMaxComponents = 1000000;

}  // namespace

// sphere { <C>, R, [strength] S MODIFIERS } or cylinder { <A>, <B>, R, [strength] S MODIFIERS }:
// the component's transformations and texture are read as an object's.
Node Interpreter::blob_component(int depth) {
  Node c;
  c.pos = tok().pos;
  const bool cylinder = is_word("cylinder");
  c.kind = cylinder ? Node::Cylinder : Node::Sphere;
  next();
  expect_symbol("{", cylinder ? "after cylinder" : "after sphere");
  c.points = {vector(cylinder ? "the component's first end" : "the component's centre")};
  skip_comma();
  if (cylinder) {
    c.points.push_back(vector("the component's second end"));
    skip_comma();
  }
  const double radius = number("the component's radius");
  skip_comma();
  if (is_word("strength")) next();
  c.values = {radius, number("the component's strength")};
  while (!accept_symbol("}"))
    if (!modifier(c, depth + 1)) unexpected("a transformation or texture of the blob's component");
  return c;
}

// blob { threshold T, components..., sturm, hierarchy }: the items before the object's modifiers
// (POV-Ray reads them in any order). `component S, R, <C>` is the old syntax of a sphere.
void Interpreter::blob_body(Node& n, int depth) {
  n.values = {1};  // POV-Ray's default threshold
  for (;;) {
    const Pos at = tok().pos;
    const std::size_t before = n.children.size();
    if (is_word("threshold")) {
      next();
      n.values[0] = number("the blob's threshold");
      skip_comma();
    } else if (is_word("sphere") || is_word("cylinder")) {
      n.children.push_back(blob_component(depth));
    } else if (is_word("component")) {
      next();
      Node c;
      c.pos = at;
      c.kind = Node::Sphere;
      const double strength = number("the component's strength");
      skip_comma();
      const double radius = number("the component's radius");
      skip_comma();
      c.points = {vector("the component's centre")};
      c.values = {radius, strength};
      skip_comma();
      n.children.push_back(std::move(c));
    } else if (is_word("sturm") || is_word("hierarchy")) {
      next();
      boolean_option();  // the roots are exact and the hierarchy is always built
    } else {
      break;
    }
    if (n.children.size() == before) continue;
    if (n.children.size() > kMaxComponents)
      fail_at(at, "a blob has at most " + std::to_string(kMaxComponents) + " components");
    n.children.back().weight = kPovNodeWeight;
    add_weight(kPovNodeWeight, at);
  }
  if (n.children.empty()) fail_at(n.pos, "a blob needs at least one component");
}

}  // namespace raycast::pov
