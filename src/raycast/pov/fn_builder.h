#pragma once
// Function trees (FnNode) written as C++ expressions: `sqrt(x * x + y * y) - p(0)` builds the
// tree of that formula over a function's parameters. For the functions raycast defines itself
// (internal_functions.cpp), so that each reads as its equation.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pov/function_expr.h"

namespace raycast::pov::fn {

/// One subtree. Sharing a subtree in several places is fine: trees are immutable.
struct Fn {
  std::shared_ptr<const FnNode> node;
  Fn(double v) {  // NOLINT: numbers mix into formulas as constants
    auto n = std::make_shared<FnNode>();
    n->number = v;
    node = n;
  }
  explicit Fn(std::shared_ptr<const FnNode> n) : node(std::move(n)) {}
};

inline Fn node(FnNode::Kind k, std::vector<Fn> args, const std::string& name = "") {
  auto n = std::make_shared<FnNode>();
  n->kind = k;
  n->function = name;
  for (const Fn& a : args) n->args.push_back(a.node);
  return Fn(n);
}
/// The function's parameter `index` (0, 1, 2: x, y, z; the extra parameters follow).
inline Fn param(int index) {
  auto n = std::make_shared<FnNode>();
  n->kind = FnNode::Param;
  n->number = index;
  return Fn(n);
}
inline Fn call(const std::string& name, std::vector<Fn> args) {
  return node(FnNode::Call, std::move(args), name);
}

inline Fn operator+(const Fn& a, const Fn& b) { return node(FnNode::Add, {a, b}); }
inline Fn operator-(const Fn& a, const Fn& b) { return node(FnNode::Subtract, {a, b}); }
inline Fn operator*(const Fn& a, const Fn& b) { return node(FnNode::Multiply, {a, b}); }
inline Fn operator/(const Fn& a, const Fn& b) { return node(FnNode::Divide, {a, b}); }
inline Fn operator-(const Fn& a) { return node(FnNode::Negate, {a}); }
inline Fn pow(const Fn& a, const Fn& b) { return node(FnNode::Power, {a, b}); }
inline Fn sqr(const Fn& a) { return a * a; }
inline Fn sqrt(const Fn& a) { return call("sqrt", {a}); }
inline Fn abs(const Fn& a) { return call("abs", {a}); }
inline Fn exp(const Fn& a) { return call("exp", {a}); }
inline Fn sin(const Fn& a) { return call("sin", {a}); }
inline Fn cos(const Fn& a) { return call("cos", {a}); }
inline Fn floor(const Fn& a) { return call("floor", {a}); }
inline Fn atan2(const Fn& y, const Fn& x) { return call("atan2", {y, x}); }
inline Fn min(const Fn& a, const Fn& b) { return call("min", {a, b}); }
inline Fn max(const Fn& a, const Fn& b) { return call("max", {a, b}); }
/// a when c > 0, else b (POV-Ray's switches are parameters: with a constant switch the choice is
/// made once, when the call is inlined, and the formula holds only the chosen branch).
inline Fn if_positive(const Fn& c, const Fn& a, const Fn& b) {
  return call("if", {call("gt", {c, 0.0}), a, b});
}

}  // namespace raycast::pov::fn
