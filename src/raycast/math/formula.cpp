#include "math/formula.h"

#include <cmath>
#include <string>

namespace raycast {

namespace {

class Compiler {
 public:
  explicit Compiler(const Expression& e) : e_(e) {}

  Formula compile() {
    emit(e_.root, 0);
    f_.stack_size = max_depth_;
    return std::move(f_);
  }

 private:
  void push(Instruction in, int depth) {
    f_.code.push_back(in);
    if (depth + 1 > max_depth_) max_depth_ = depth + 1;
  }

  // Emits code leaving the node's value on the stack, which holds `depth` values before it.
  void emit(int index, int depth) {
    const ExprNode& n = e_.nodes[index];
    if (depth + 1 > kMaxFormulaStack)
      throw ExpressionError(n.offset, "formula too deeply nested to evaluate (stack limit " +
                                          std::to_string(kMaxFormulaStack) + ")");
    if (n.op != ExprOp::kX && n.op != ExprOp::kY && n.op != ExprOp::kZ && is_constant(e_, index)) {
      const double v = constant(index);
      push({Opcode::kConst, 0, v}, depth);
      return;
    }
    switch (n.op) {
      case ExprOp::kX:
        push({Opcode::kX, 0, 0}, depth);
        return;
      case ExprOp::kY:
        push({Opcode::kY, 0, 0}, depth);
        return;
      case ExprOp::kZ:
        push({Opcode::kZ, 0, 0}, depth);
        return;
      case ExprOp::kSin:
      case ExprOp::kCos: {
        const ExprOp arg = e_.nodes[n.a].op;
        if (arg == ExprOp::kX || arg == ExprOp::kY || arg == ExprOp::kZ) {
          const int v = arg == ExprOp::kX ? 0 : (arg == ExprOp::kY ? 1 : 2);
          f_.trig_vars |= 1u << v;
          push({n.op == ExprOp::kSin ? Opcode::kSinVar : Opcode::kCosVar, v, 0}, depth);
          return;
        }
        break;
      }
      case ExprOp::kPow:
        if (is_constant(e_, n.b)) {
          const double p = constant(n.b);
          if (p == std::floor(p) && std::abs(p) <= 64) {
            emit(n.a, depth);
            push({Opcode::kPowInt, static_cast<int>(p), 0}, depth);
            return;
          }
        }
        break;
      default:
        break;
    }
    emit(n.a, depth);
    if (n.b >= 0) emit(n.b, depth + 1);
    if (n.c >= 0) emit(n.c, depth + 2);
    push({opcode(n.op), generator(n.op), 0}, depth);
  }

  // The noise generator of a noise operation (0 for the others).
  static int generator(ExprOp op) {
    return op == ExprOp::kNoise1 ? 1 : op == ExprOp::kNoise2 ? 2 : op == ExprOp::kNoise3 ? 3 : 0;
  }

  double constant(int index) {
    Formula sub = Compiler(e_).compile_at(index);
    return run<double>(sub, 0.0, 0.0, 0.0);
  }
  Formula compile_at(int index) {
    emit_plain(index, 0);
    f_.stack_size = max_depth_;
    return std::move(f_);
  }
  // Emits without folding (used to evaluate a constant subtree once).
  void emit_plain(int index, int depth) {
    const ExprNode& n = e_.nodes[index];
    if (depth + 1 > kMaxFormulaStack)
      throw ExpressionError(n.offset, "formula too deeply nested to evaluate");
    if (n.op == ExprOp::kConst) {
      push({Opcode::kConst, 0, n.value}, depth);
      return;
    }
    if (n.a >= 0) emit_plain(n.a, depth);
    if (n.b >= 0) emit_plain(n.b, depth + 1);
    if (n.c >= 0) emit_plain(n.c, depth + 2);
    push({opcode(n.op), generator(n.op), 0}, depth);
  }

  static Opcode opcode(ExprOp op) {
    switch (op) {
      case ExprOp::kConst:
        return Opcode::kConst;
      case ExprOp::kX:
        return Opcode::kX;
      case ExprOp::kY:
        return Opcode::kY;
      case ExprOp::kZ:
        return Opcode::kZ;
      case ExprOp::kAdd:
        return Opcode::kAdd;
      case ExprOp::kSub:
        return Opcode::kSub;
      case ExprOp::kMul:
        return Opcode::kMul;
      case ExprOp::kDiv:
        return Opcode::kDiv;
      case ExprOp::kPow:
        return Opcode::kPow;
      case ExprOp::kMin:
        return Opcode::kMin;
      case ExprOp::kMax:
        return Opcode::kMax;
      case ExprOp::kAtan2:
        return Opcode::kAtan2;
      case ExprOp::kFloor:
        return Opcode::kFloor;
      case ExprOp::kNoise1:
      case ExprOp::kNoise2:
      case ExprOp::kNoise3:
        return Opcode::kNoise;
      case ExprOp::kNeg:
        return Opcode::kNeg;
      case ExprOp::kSqrt:
        return Opcode::kSqrt;
      case ExprOp::kExp:
        return Opcode::kExp;
      case ExprOp::kLog:
        return Opcode::kLog;
      case ExprOp::kSin:
        return Opcode::kSin;
      case ExprOp::kCos:
        return Opcode::kCos;
      case ExprOp::kTan:
        return Opcode::kTan;
      case ExprOp::kAbs:
        return Opcode::kAbs;
    }
    return Opcode::kConst;
  }

  const Expression& e_;
  Formula f_;
  int max_depth_ = 0;
};

}  // namespace

namespace {

bool continuous_everywhere(const Formula& f) {
  for (const Instruction& in : f.code) {
    switch (in.op) {
      case Opcode::kConst:
        if (!std::isfinite(in.value)) return false;
        break;
      case Opcode::kPowInt:
        if (in.n < 0) return false;
        break;
      case Opcode::kX:
      case Opcode::kY:
      case Opcode::kZ:
      case Opcode::kAdd:
      case Opcode::kSub:
      case Opcode::kMul:
      case Opcode::kNeg:
      case Opcode::kSin:
      case Opcode::kCos:
      case Opcode::kAbs:
      case Opcode::kMin:
      case Opcode::kMax:
      case Opcode::kSinVar:
      case Opcode::kCosVar:
        break;
      default:  // division, tan (poles), sqrt, log, pow (domains), exp (overflow), atan2 (its
                // cut), floor (its steps)
        return false;
    }
  }
  return true;
}

}  // namespace

Formula compile_formula(std::string_view text) {
  const Expression e = parse_expression(text);
  if (!formula_noise().value)
    for (const ExprNode& n : e.nodes)
      if (n.op == ExprOp::kNoise1 || n.op == ExprOp::kNoise2 || n.op == ExprOp::kNoise3)
        throw ExpressionError(n.offset, "noise is not available here (no scene loader set it up)");
  Formula f = Compiler(e).compile();
  f.continuous = continuous_everywhere(f);
  return f;
}

}  // namespace raycast
