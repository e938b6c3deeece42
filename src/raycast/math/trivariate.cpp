#include "math/trivariate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>

namespace raycast {

namespace {

using Key = int;  // i * kStride^2 + j * kStride + k
constexpr int kStride = kMaxPolynomialDegree + 1;
// The deepest stack of polynomials line code may use (deeper formulas use the expanded terms).
constexpr int kMaxLineStack = 24;
// Saved common subexpressions of line code (more are recomputed where they occur).
constexpr int kMaxLineSlots = 8;
using Sparse = std::map<Key, double>;

int degree_of(const Sparse& p) {
  int d = 0;
  for (const auto& [key, c] : p) {
    const int deg = key / (kStride * kStride) + (key / kStride) % kStride + key % kStride;
    if (c != 0 && deg > d) d = deg;
  }
  return d;
}

bool constant_value(const Sparse& p, double& v) {
  v = 0;
  for (const auto& [key, c] : p) {
    if (c == 0) continue;
    if (key != 0) return false;
    v = c;
  }
  return true;
}

Sparse multiply(const Sparse& a, const Sparse& b, std::size_t offset) {
  if (degree_of(a) + degree_of(b) > kMaxPolynomialDegree)
    throw ExpressionError(
        offset, "the polynomial's degree would exceed " + std::to_string(kMaxPolynomialDegree));
  Sparse r;
  for (const auto& [ka, ca] : a)
    for (const auto& [kb, cb] : b) r[ka + kb] += ca * cb;
  return r;
}

class Expander {
 public:
  explicit Expander(const Expression& e) : e_(e) {}

  Sparse expand(int index) {
    const ExprNode& n = e_.nodes[index];
    switch (n.op) {
      case ExprOp::kConst:
        return {{0, n.value}};
      case ExprOp::kX:
        return {{kStride * kStride, 1.0}};
      case ExprOp::kY:
        return {{kStride, 1.0}};
      case ExprOp::kZ:
        return {{1, 1.0}};
      case ExprOp::kAdd:
      case ExprOp::kSub: {
        Sparse a = expand(n.a);
        const double sign = n.op == ExprOp::kAdd ? 1 : -1;
        for (const auto& [k, c] : expand(n.b)) a[k] += sign * c;
        return a;
      }
      case ExprOp::kNeg: {
        Sparse a = expand(n.a);
        for (auto& kv : a) kv.second = -kv.second;
        return a;
      }
      case ExprOp::kMul:
        return multiply(expand(n.a), expand(n.b), n.offset);
      case ExprOp::kDiv: {
        double v;
        if (!constant_value(expand(n.b), v))
          throw ExpressionError(n.offset, "an algebraic equation may divide only by constants");
        if (v == 0) throw ExpressionError(n.offset, "division by zero");
        Sparse a = expand(n.a);
        for (auto& kv : a) kv.second /= v;
        return a;
      }
      case ExprOp::kPow:
        return power(n);
      default:
        throw ExpressionError(n.offset,
                              "functions are not allowed in an algebraic equation "
                              "(only + - * / ^ and parentheses; use an implicit shape)");
    }
  }

 private:
  Sparse power(const ExprNode& n) {
    double exponent;
    const std::size_t at = e_.nodes[n.b].offset;
    if (!constant_value(expand(n.b), exponent))
      throw ExpressionError(at, "an exponent must be a constant");
    Sparse base = expand(n.a);
    double base_value;
    if (constant_value(base, base_value)) {
      const double v = std::pow(base_value, exponent);
      if (!std::isfinite(v)) throw ExpressionError(n.offset, "constant power is not finite");
      return {{0, v}};
    }
    if (!(exponent >= 0) || exponent != std::floor(exponent))
      throw ExpressionError(at,
                            "the exponent of a variable expression must be a whole number >= 0");
    if (exponent * degree_of(base) > kMaxPolynomialDegree)
      throw ExpressionError(
          n.offset, "the polynomial's degree would exceed " + std::to_string(kMaxPolynomialDegree));
    Sparse r{{0, 1.0}};
    for (int i = 0; i < static_cast<int>(exponent); ++i) r = multiply(r, base, n.offset);
    return r;
  }

  const Expression& e_;
};

// The formula's tree as LineOp code, and the multiplications one run of it costs (each
// operation on the actual degrees). The tree was already checked by the Expander. A subtree
// written twice or more (same operations on the same constants and variables) that is neither a
// constant nor a bare variable is computed at its first occurrence, stored, and loaded at the
// others.
class LineCompiler {
 public:
  explicit LineCompiler(const Expression& e) : e_(e), keys_(e.nodes.size()) {
    for (std::size_t i = 0; i < e.nodes.size(); ++i) keys_[i] = key_of(static_cast<int>(i));
    if (e.root >= 0) count_uses(e.root);
  }
  // Emits the node; returns its degree.
  int emit(int index, std::vector<Trivariate::LineOp>& code, int depth = 0) {
    using Op = Trivariate::LineOp;
    const std::string& key = keys_[index];
    const bool shareable = uses_[key] >= 2 && !is_leaf(index);
    if (shareable) {
      if (const auto it = saved_.find(key); it != saved_.end()) {
        code.push_back({Op::kLoad, it->second.first, 0});
        max_stack = std::max(max_stack, depth + 1);
        return it->second.second;
      }
    }
    const int degree = emit_node(index, code, depth);
    max_degree = std::max(max_degree, degree);
    max_stack = std::max(max_stack, depth + 1);
    const int slot = static_cast<int>(saved_.size());
    if (shareable && degree > 0 && slot < kMaxLineSlots) {
      code.push_back({Op::kStore, slot, 0});
      saved_[key] = {slot, degree};
    }
    return degree;
  }
  long cost = 0;
  int max_degree = 0, max_stack = 0;

 private:
  // A structural key: equal keys, equal subtrees (constants by their bits).
  std::string key_of(int index) const {
    const ExprNode& n = e_.nodes[index];
    std::string k = std::to_string(static_cast<int>(n.op));
    if (n.op == ExprOp::kConst) {
      std::ostringstream v;
      v << std::hexfloat << n.value;
      k += v.str();
    }
    if (n.a >= 0) k += "(" + keys_[n.a] + ")";
    if (n.b >= 0) k += "(" + keys_[n.b] + ")";
    return k;
  }
  // How often each subtree is emitted: a repeat is loaded, so its own subtrees are not counted
  // again.
  void count_uses(int index) {
    const ExprNode& n = e_.nodes[index];
    if (uses_[keys_[index]]++ > 0) return;
    if (n.a >= 0) count_uses(n.a);
    if (n.b >= 0) count_uses(n.b);
  }
  bool is_leaf(int index) const {
    const ExprOp op = e_.nodes[index].op;
    return op == ExprOp::kConst || op == ExprOp::kX || op == ExprOp::kY || op == ExprOp::kZ;
  }

  int emit_node(int index, std::vector<Trivariate::LineOp>& code, int depth) {
    using Op = Trivariate::LineOp;
    const ExprNode& n = e_.nodes[index];
    double v;
    if (constant_value(Expander(e_).expand(index), v)) {
      code.push_back({Op::kConst, 0, v});
      return 0;
    }
    switch (n.op) {
      case ExprOp::kX:
      case ExprOp::kY:
      case ExprOp::kZ:
        code.push_back({Op::kVar, n.op == ExprOp::kX ? 0 : (n.op == ExprOp::kY ? 1 : 2), 0});
        return 1;
      case ExprOp::kAdd:
      case ExprOp::kSub:
      case ExprOp::kMul: {
        const int da = emit(n.a, code, depth), db = emit(n.b, code, depth + 1);
        if (n.op == ExprOp::kMul) {
          cost += (da + 1) * (db + 1);
          code.push_back({Op::kMul, 0, 0});
          return da + db;
        }
        cost += std::max(da, db) + 1;
        code.push_back({n.op == ExprOp::kAdd ? Op::kAdd : Op::kSub, 0, 0});
        return std::max(da, db);
      }
      case ExprOp::kNeg: {
        const int da = emit(n.a, code, depth);
        code.push_back({Op::kNeg, 0, 0});
        return da;
      }
      case ExprOp::kDiv: {
        const int da = emit(n.a, code, depth);
        constant_value(Expander(e_).expand(n.b), v);
        cost += da + 1;
        code.push_back({Op::kDiv, 0, v});
        return da;
      }
      case ExprOp::kPow: {
        constant_value(Expander(e_).expand(n.b), v);
        const int p = static_cast<int>(v), da = emit(n.a, code, depth);
        for (int k = 1; k < p; ++k) cost += (k * da + 1) * (da + 1);
        code.push_back({Op::kPow, p, 0});
        return p * da;
      }
      default:
        return 0;  // not reached: the Expander refused the formula
    }
  }

  const Expression& e_;
  std::vector<std::string> keys_;
  std::map<std::string, int> uses_;
  std::map<std::string, std::pair<int, int>> saved_;  // key -> (slot, degree)
};

// Multiplications of restrict_expanded_to_line on f.
long expanded_cost(const Trivariate& f) {
  long cost = 3L * f.degree * (f.degree + 1) / 2;  // the power rows
  std::size_t n = 0;
  while (n < f.terms.size()) {
    const int i = f.terms[n].i, j = f.terms[n].j;
    int dz = 0;
    for (; n < f.terms.size() && f.terms[n].i == i && f.terms[n].j == j; ++n) {
      cost += f.terms[n].k + 1;
      dz = std::max(dz, f.terms[n].k);
    }
    cost += (j + 1) * (dz + 1) + (i + 1) * (j + dz + 1);
  }
  return cost;
}

void translate_line_code(Trivariate& f);

}  // namespace

Trivariate expand_polynomial(std::string_view text) {
  const Expression e = parse_expression(text);
  const Sparse s = Expander(e).expand(e.root);
  Trivariate f;
  for (const auto& [key, c] : s) {
    if (c == 0) continue;
    if (!std::isfinite(c))
      throw ExpressionError(0, "a coefficient of the expanded polynomial is not finite");
    f.terms.push_back({key / (kStride * kStride), (key / kStride) % kStride, key % kStride, c});
  }
  f.degree = degree_of(s);
  LineCompiler lc(e);
  lc.emit(e.root, f.line_code);
  // Intermediate degrees can exceed the result's where terms cancel: such code is not used.
  f.line_code_cheaper = lc.max_degree <= kMaxPolynomialDegree && lc.max_stack <= kMaxLineStack &&
                        lc.cost < expanded_cost(f);
  if (!f.line_code_cheaper) f.line_code.clear();
  translate_line_code(f);
  return f;
}

namespace {
// x^0 .. x^n, each the previous times x: the same products, in the same order, as multiplying
// x into 1 k times, so the sums below round exactly as with a power computed per term.
template <class T>
struct Powers {
  T v[kStride];
  Powers(T x, int n) {
    v[0] = 1;
    for (int i = 1; i <= n; ++i) v[i] = v[i - 1] * x;
  }
};
using PowersLd = Powers<long double>;
}  // namespace

// Surface normals call these once per hit: the powers are tabled once per call.
double evaluate(const Trivariate& f, const Vec3& p) {
  const Powers<double> px(p.x, f.degree), py(p.y, f.degree), pz(p.z, f.degree);
  double s = 0;
  for (const auto& t : f.terms) s += t.c * px.v[t.i] * py.v[t.j] * pz.v[t.k];
  return s;
}

Vec3 gradient(const Trivariate& f, const Vec3& p) {
  const Powers<double> px(p.x, f.degree), py(p.y, f.degree), pz(p.z, f.degree);
  Vec3 g;
  for (const auto& t : f.terms) {
    if (t.i > 0) g.x += t.c * t.i * px.v[t.i - 1] * py.v[t.j] * pz.v[t.k];
    if (t.j > 0) g.y += t.c * t.j * px.v[t.i] * py.v[t.j - 1] * pz.v[t.k];
    if (t.k > 0) g.z += t.c * t.k * px.v[t.i] * py.v[t.j] * pz.v[t.k - 1];
  }
  return g;
}

// The polish of a hit calls this dozens of times per ray: the powers are tabled once per call.
long double evaluate_extended(const Trivariate& f, long double x, long double y, long double z) {
  const PowersLd px(x, f.degree), py(y, f.degree), pz(z, f.degree);
  long double s = 0;
  for (const auto& t : f.terms) s += t.c * px.v[t.i] * py.v[t.j] * pz.v[t.k];
  return s;
}

void gradient_extended(const Trivariate& f, long double x, long double y, long double z,
                       long double g[3]) {
  const PowersLd px(x, f.degree), py(y, f.degree), pz(z, f.degree);
  g[0] = g[1] = g[2] = 0;
  for (const auto& t : f.terms) {
    if (t.i > 0) g[0] += t.c * t.i * px.v[t.i - 1] * py.v[t.j] * pz.v[t.k];
    if (t.j > 0) g[1] += t.c * t.j * px.v[t.i] * py.v[t.j - 1] * pz.v[t.k];
    if (t.k > 0) g[2] += t.c * t.k * px.v[t.i] * py.v[t.j] * pz.v[t.k - 1];
  }
}

namespace {
// (a + b t)^i for i = 0..n: row i holds its i + 1 coefficients (the rest is never read).
void linear_power_rows(double a, double b, int n, double (*rows)[kStride]) {
  rows[0][0] = 1;
  for (int i = 1; i <= n; ++i) {
    const double* q = rows[i - 1];
    double* r = rows[i];
    r[0] = a * q[0];
    for (int k = 1; k < i; ++k) r[k] = b * q[k - 1] + a * q[k];
    r[i] = b * q[i - 1];
  }
}

// r[0..da+db] = a[0..da] * b[0..db] (the same sums, in the same order, as multiply()).
void multiply_into(const double* a, int da, const double* b, int db, double* r) {
  for (int k = 0; k <= da + db; ++k) r[k] = 0;
  for (int i = 0; i <= da; ++i)
    for (int j = 0; j <= db; ++j) r[i + j] += a[i] * b[j];
}
}  // namespace

// Works on arrays sized by the actual degrees (no full Polynomial copies or zero-filled
// products); the arithmetic is that of the Polynomial-based form, so the result is the same.
Polynomial restrict_expanded_to_line(const Trivariate& f, const Vec3& o, const Vec3& d) {
  double X[kStride][kStride], Y[kStride][kStride], Z[kStride][kStride];
  linear_power_rows(o.x, d.x, f.degree, X);
  linear_power_rows(o.y, d.y, f.degree, Y);
  linear_power_rows(o.z, d.z, f.degree, Z);
  Polynomial result;
  // Terms are sorted by (i, j, k): sum the z parts of each (i, j) group, then multiply once.
  std::size_t n = 0;
  while (n < f.terms.size()) {
    const int i = f.terms[n].i, j = f.terms[n].j;
    double zsum[kStride], yz[kStride], xyz[kStride];
    int dz = 0;
    zsum[0] = 0;
    for (; n < f.terms.size() && f.terms[n].i == i && f.terms[n].j == j; ++n) {
      const int k = f.terms[n].k;
      const double c = f.terms[n].c;
      for (; dz < k;) zsum[++dz] = 0;
      for (int m = 0; m <= k; ++m) zsum[m] += c * Z[k][m];
    }
    multiply_into(Y[j], j, zsum, dz, yz);
    multiply_into(X[i], i, yz, j + dz, xyz);
    const int dr = i + j + dz;
    if (dr > result.degree) result.degree = dr;
    for (int m = 0; m <= dr; ++m) result.c[m] += xyz[m];
  }
  return result;
}

namespace {
// A polynomial in t of small degree on the code's stack.
struct LinePoly {
  int degree;
  double c[kStride];
};
}  // namespace

namespace {
// a[0..DA+DB] = a[0..DA] * b[0..DB] with the loops unrolled for the degrees: the sums of
// multiply_into in the same order (so the same bits), without its loop overhead.
template <int DA, int DB>
void multiply_fixed(double* a, const double* b) {
  double r[DA + DB + 1] = {};
  for (int i = 0; i <= DA; ++i)
    for (int j = 0; j <= DB; ++j) r[i + j] += a[i] * b[j];
  for (int k = 0; k <= DA + DB; ++k) a[k] = r[k];
}

// Products of degrees up to kFixedDegree each (the heart's and the tori's are) by table.
constexpr int kFixedDegree = 8;
using MultiplyFixed = void (*)(double*, const double*);
template <int DA, int... DB>
constexpr std::array<MultiplyFixed, sizeof...(DB)> multiply_row(std::integer_sequence<int, DB...>) {
  return {&multiply_fixed<DA, DB>...};
}
template <int... DA>
constexpr std::array<std::array<MultiplyFixed, kFixedDegree + 1>, sizeof...(DA)> multiply_table(
    std::integer_sequence<int, DA...>) {
  return {multiply_row<DA>(std::make_integer_sequence<int, kFixedDegree + 1>())...};
}
constexpr auto kMultiplyFixed = multiply_table(std::make_integer_sequence<int, kFixedDegree + 1>());

// a = a * b (a.degree + b.degree <= kMaxPolynomialDegree).
void multiply_line(LinePoly& a, const double* b, int db) {
  if (a.degree <= kFixedDegree && db <= kFixedDegree) {
    kMultiplyFixed[a.degree][db](a.c, b);
  } else {
    double r[kStride];
    multiply_into(a.c, a.degree, b, db, r);
    for (int k = 0; k <= a.degree + db; ++k) a.c[k] = r[k];
  }
  a.degree += db;
}
}  // namespace

namespace {
// The register steps (Trivariate::LineStep): each the arithmetic of the stack interpreter below
// for its operation, written into a fresh register.
using Reg = double (*)[kStride];
using Step = Trivariate::LineStep;

// a + value * b (value +1 or -1), coefficients above the shorter operand's degree as the stack
// code forms them (0 + value * b).
void add_step(const Step& s, Reg r) {
  const double *a = r[s.a], *b = r[s.b];
  double* d = r[s.dst];
  const int m = std::min(s.da, s.db);
  for (int k = 0; k <= m; ++k) d[k] = a[k] + s.value * b[k];
  for (int k = m + 1; k <= s.db; ++k) d[k] = 0.0 + s.value * b[k];
  for (int k = m + 1; k <= s.da; ++k) d[k] = a[k];
}
template <int DA, int DB>
void add_fixed_step(const Step& s, Reg r) {
  const double *a = r[s.a], *b = r[s.b];
  double* d = r[s.dst];
  constexpr int m = DA < DB ? DA : DB;
  for (int k = 0; k <= m; ++k) d[k] = a[k] + s.value * b[k];
  for (int k = m + 1; k <= DB; ++k) d[k] = 0.0 + s.value * b[k];
  for (int k = m + 1; k <= DA; ++k) d[k] = a[k];
}
template <int DA, int... DB>
constexpr std::array<Step::Run, sizeof...(DB)> add_step_row(std::integer_sequence<int, DB...>) {
  return {&add_fixed_step<DA, DB>...};
}
template <int... DA>
constexpr std::array<std::array<Step::Run, kFixedDegree + 1>, sizeof...(DA)> add_step_table(
    std::integer_sequence<int, DA...>) {
  return {add_step_row<DA>(std::make_integer_sequence<int, kFixedDegree + 1>())...};
}
constexpr auto kAddStep = add_step_table(std::make_integer_sequence<int, kFixedDegree + 1>());

void scale_step(const Step& s, Reg r) {
  const double* a = r[s.a];
  double* d = r[s.dst];
  for (int k = 0; k <= s.da; ++k) d[k] = a[k] * s.value;
}
void divide_step(const Step& s, Reg r) {
  const double* a = r[s.a];
  double* d = r[s.dst];
  for (int k = 0; k <= s.da; ++k) d[k] = a[k] / s.value;
}
void negate_step(const Step& s, Reg r) {
  const double* a = r[s.a];
  double* d = r[s.dst];
  for (int k = 0; k <= s.da; ++k) d[k] = -a[k];
}
void multiply_step(const Step& s, Reg r) { multiply_into(r[s.a], s.da, r[s.b], s.db, r[s.dst]); }
template <int DA, int DB>
void multiply_fixed_step(const Step& s, Reg r) {
  const double *a = r[s.a], *b = r[s.b];
  double* d = r[s.dst];
  for (int k = 0; k <= DA + DB; ++k) d[k] = 0;
  for (int i = 0; i <= DA; ++i)
    for (int j = 0; j <= DB; ++j) d[i + j] += a[i] * b[j];
}
template <int DA, int... DB>
constexpr std::array<Step::Run, sizeof...(DB)> multiply_step_row(
    std::integer_sequence<int, DB...>) {
  return {&multiply_fixed_step<DA, DB>...};
}
template <int... DA>
constexpr std::array<std::array<Step::Run, kFixedDegree + 1>, sizeof...(DA)> multiply_step_table(
    std::integer_sequence<int, DA...>) {
  return {multiply_step_row<DA>(std::make_integer_sequence<int, kFixedDegree + 1>())...};
}
constexpr auto kMultiplyStep =
    multiply_step_table(std::make_integer_sequence<int, kFixedDegree + 1>());

// Registers restrict_code_to_line keeps on its stack (longer code runs the stack interpreter).
constexpr int kMaxLineRegisters = 64;

void translate_line_code(Trivariate& f) {
  using Op = Trivariate::LineOp;
  f.line_steps.clear();
  f.line_constants.clear();
  if (f.line_code.empty()) return;
  struct Value {
    int reg = -1, degree = 0;
    bool constant = false;
    double c = 0;
  };
  std::vector<Value> stack, saved(kMaxLineSlots);
  std::vector<Step> steps;
  std::vector<std::pair<int, double>> constants;
  int next = 3;
  auto reg_of = [&](Value& v) {  // a constant used as a polynomial gets its register
    if (v.reg < 0) {
      v.reg = next++;
      constants.push_back({v.reg, v.c});
    }
    return v.reg;
  };
  auto multiply = [&](Value& a, Value& b) {
    Step s;
    if (b.constant || a.constant) {
      Value& p = b.constant ? a : b;
      s = {&scale_step,
           0,
           static_cast<unsigned char>(reg_of(p)),
           0,
           static_cast<unsigned char>(p.degree),
           0,
           b.constant ? b.c : a.c};
    } else {
      s.run = a.degree <= kFixedDegree && b.degree <= kFixedDegree
                  ? kMultiplyStep[a.degree][b.degree]
                  : &multiply_step;
      s.a = static_cast<unsigned char>(a.reg);
      s.b = static_cast<unsigned char>(b.reg);
      s.da = static_cast<unsigned char>(a.degree);
      s.db = static_cast<unsigned char>(b.degree);
    }
    s.dst = static_cast<unsigned char>(next++);
    steps.push_back(s);
    return Value{s.dst, a.degree + b.degree};
  };
  for (const Op& in : f.line_code) {
    switch (in.kind) {
      case Op::kConst:
        stack.push_back({-1, 0, true, in.value});
        break;
      case Op::kVar:
        stack.push_back({in.n, 1});
        break;
      case Op::kAdd:
      case Op::kSub: {
        Value b = stack.back();
        stack.pop_back();
        Value a = stack.back();
        stack.pop_back();
        const int ra = reg_of(a), rb = reg_of(b);
        Step s{a.degree <= kFixedDegree && b.degree <= kFixedDegree ? kAddStep[a.degree][b.degree]
                                                                    : &add_step,
               static_cast<unsigned char>(next++),
               static_cast<unsigned char>(ra),
               static_cast<unsigned char>(rb),
               static_cast<unsigned char>(a.degree),
               static_cast<unsigned char>(b.degree),
               in.kind == Op::kAdd ? 1.0 : -1.0};
        steps.push_back(s);
        stack.push_back({s.dst, std::max(a.degree, b.degree)});
        break;
      }
      case Op::kMul: {
        Value b = stack.back();
        stack.pop_back();
        Value a = stack.back();
        stack.pop_back();
        stack.push_back(multiply(a, b));
        break;
      }
      case Op::kNeg:
      case Op::kDiv: {
        Value a = stack.back();
        stack.pop_back();
        Step s{in.kind == Op::kNeg ? &negate_step : &divide_step,
               static_cast<unsigned char>(0),
               static_cast<unsigned char>(reg_of(a)),
               0,
               static_cast<unsigned char>(a.degree),
               0,
               in.value};
        s.dst = static_cast<unsigned char>(next++);
        steps.push_back(s);
        stack.push_back({s.dst, a.degree});
        break;
      }
      case Op::kPow: {
        Value base = stack.back();
        stack.pop_back();
        if (in.n == 0 || base.constant) return;  // folded by the compiler: not translated
        Value acc = base;
        for (int m = 1; m < in.n; ++m) acc = multiply(acc, base);
        stack.push_back(acc);
        break;
      }
      case Op::kStore:
        saved[in.n] = stack.back();
        break;
      case Op::kLoad:
        stack.push_back(saved[in.n]);
        break;
    }
    if (next > kMaxLineRegisters) return;
  }
  if (stack.size() != 1 || stack.back().constant) return;
  f.line_steps = std::move(steps);
  f.line_constants = std::move(constants);
  f.line_result = stack.back().reg;
  f.line_result_degree = stack.back().degree;
}
}  // namespace

Polynomial restrict_code_to_line(const Trivariate& f, const Vec3& o, const Vec3& d) {
  if (!f.line_steps.empty()) {
    double reg[kMaxLineRegisters][kStride];
    for (int i = 0; i < 3; ++i) {
      reg[i][0] = o[i];
      reg[i][1] = d[i];
    }
    for (const auto& [r, v] : f.line_constants) reg[r][0] = v;
    for (const Step& s : f.line_steps) s.run(s, reg);
    // Coefficients above f's degree belong to terms that cancel (rounding residue): dropped.
    Polynomial p;
    p.degree = std::min(f.line_result_degree, f.degree);
    for (int k = 0; k <= p.degree; ++k) p.c[k] = reg[f.line_result][k];
    return p;
  }
  using Op = Trivariate::LineOp;
  LinePoly s[kMaxLineStack], saved[kMaxLineSlots];
  int top = -1;
  for (const Op& in : f.line_code) {
    switch (in.kind) {
      case Op::kConst:
        s[++top].degree = 0;
        s[top].c[0] = in.value;
        break;
      case Op::kVar:
        s[++top].degree = 1;
        s[top].c[0] = o[in.n];
        s[top].c[1] = d[in.n];
        break;
      case Op::kAdd:
      case Op::kSub: {
        LinePoly& a = s[top - 1];
        const LinePoly& b = s[top];
        const double sign = in.kind == Op::kAdd ? 1 : -1;
        for (int k = a.degree + 1; k <= b.degree; ++k) a.c[k] = 0;
        for (int k = 0; k <= b.degree; ++k) a.c[k] += sign * b.c[k];
        a.degree = std::max(a.degree, b.degree);
        --top;
        break;
      }
      case Op::kMul: {
        LinePoly& a = s[top - 1];
        const LinePoly& b = s[top];
        if (b.degree == 0) {  // a constant factor (the common "c * term"): scale in place
          for (int k = 0; k <= a.degree; ++k) a.c[k] *= b.c[0];
        } else if (a.degree == 0) {
          const double c = a.c[0];
          a.degree = b.degree;
          for (int k = 0; k <= b.degree; ++k) a.c[k] = c * b.c[k];
        } else {
          multiply_line(a, b.c, b.degree);
        }
        --top;
        break;
      }
      case Op::kNeg:
        for (int k = 0; k <= s[top].degree; ++k) s[top].c[k] = -s[top].c[k];
        break;
      case Op::kStore:
        saved[in.n].degree = s[top].degree;
        for (int k = 0; k <= s[top].degree; ++k) saved[in.n].c[k] = s[top].c[k];
        break;
      case Op::kLoad:
        s[++top].degree = saved[in.n].degree;
        for (int k = 0; k <= saved[in.n].degree; ++k) s[top].c[k] = saved[in.n].c[k];
        break;
      case Op::kDiv:
        for (int k = 0; k <= s[top].degree; ++k) s[top].c[k] /= in.value;
        break;
      case Op::kPow: {
        LinePoly& a = s[top];
        if (in.n == 0) {
          a.degree = 0;
          a.c[0] = 1;
          break;
        }
        double base[kStride];
        const int db = a.degree;
        for (int k = 0; k <= db; ++k) base[k] = a.c[k];
        for (int m = 1; m < in.n; ++m) multiply_line(a, base, db);  // a = a * base, n - 1 times
        break;
      }
    }
  }
  // Coefficients above f's degree belong to terms that cancel (rounding residue): dropped.
  Polynomial p;
  p.degree = std::min(s[0].degree, f.degree);
  for (int k = 0; k <= p.degree; ++k) p.c[k] = s[0].c[k];
  return p;
}

Polynomial restrict_to_line(const Trivariate& f, const Vec3& o, const Vec3& d) {
  return f.line_code_cheaper ? restrict_code_to_line(f, o, d) : restrict_expanded_to_line(f, o, d);
}

}  // namespace raycast
