#include "pov/function_expr.h"

#include <cstdio>
#include <sstream>

namespace raycast::pov {

namespace {
std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
}  // namespace

std::string formula_text(const FnNode& f, bool mirror_z) {
  // Every compound is parenthesised: the text is for the loader, which has its own precedence.
  std::ostringstream o;
  auto arg = [&](std::size_t i) { return formula_text(*f.args[i], mirror_z); };
  const char* op = nullptr;
  switch (f.kind) {
    case FnNode::Number:
      if (f.number < 0)
        o << "(" << number_text(f.number) << ")";
      else
        o << number_text(f.number);
      return o.str();
    case FnNode::Variable:
      if (mirror_z && f.variable == 'z') return "(-z)";
      return std::string(1, f.variable);
    case FnNode::Negate:
      o << "(-" << arg(0) << ")";
      return o.str();
    case FnNode::Add:
      op = " + ";
      break;
    case FnNode::Subtract:
      op = " - ";
      break;
    case FnNode::Multiply:
      op = " * ";
      break;
    case FnNode::Divide:
      op = " / ";
      break;
    case FnNode::Power:
      o << "pow(" << arg(0) << ", " << arg(1) << ")";
      return o.str();
    case FnNode::Call:
      o << f.function << "(";
      for (std::size_t i = 0; i < f.args.size(); ++i) o << (i ? ", " : "") << arg(i);
      o << ")";
      return o.str();
  }
  o << "(" << arg(0) << op << arg(1) << ")";
  return o.str();
}

}  // namespace raycast::pov
