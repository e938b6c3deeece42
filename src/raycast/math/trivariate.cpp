#include "math/trivariate.h"

#include <cmath>
#include <map>
#include <string>

namespace raycast {

namespace {

using Key = int;  // i * kStride^2 + j * kStride + k
constexpr int kStride = kMaxPolynomialDegree + 1;
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

double ipow(double x, int n) {
  double r = 1;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

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
  return f;
}

double evaluate(const Trivariate& f, const Vec3& p) {
  double s = 0;
  for (const auto& t : f.terms) s += t.c * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k);
  return s;
}

Vec3 gradient(const Trivariate& f, const Vec3& p) {
  Vec3 g;
  for (const auto& t : f.terms) {
    if (t.i > 0) g.x += t.c * t.i * ipow(p.x, t.i - 1) * ipow(p.y, t.j) * ipow(p.z, t.k);
    if (t.j > 0) g.y += t.c * t.j * ipow(p.x, t.i) * ipow(p.y, t.j - 1) * ipow(p.z, t.k);
    if (t.k > 0) g.z += t.c * t.k * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k - 1);
  }
  return g;
}

namespace {
// x^0 .. x^n, each the previous times x: the same products, in the same order, as multiplying
// x into 1 k times, so the sums below round exactly as with a power computed per term.
struct PowersLd {
  long double v[kStride];
  PowersLd(long double x, int n) {
    v[0] = 1;
    for (int i = 1; i <= n; ++i) v[i] = v[i - 1] * x;
  }
};
}  // namespace

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
Polynomial restrict_to_line(const Trivariate& f, const Vec3& o, const Vec3& d) {
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

}  // namespace raycast
