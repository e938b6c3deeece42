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

// (a + b t)^0 .. (a + b t)^n.
void linear_powers(double a, double b, int n, Polynomial* out) {
  out[0] = Polynomial{};
  out[0].c[0] = 1;
  for (int i = 1; i <= n; ++i) {
    Polynomial& p = out[i];
    const Polynomial& q = out[i - 1];
    p = Polynomial{};
    p.degree = i;
    for (int k = 0; k < i; ++k) {
      p.c[k] += a * q.c[k];
      p.c[k + 1] += b * q.c[k];
    }
  }
}

void add_scaled(Polynomial& acc, const Polynomial& p, double s) {
  if (p.degree > acc.degree) acc.degree = p.degree;
  for (int i = 0; i <= p.degree; ++i) acc.c[i] += s * p.c[i];
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
long double ipow_ld(long double x, int n) {
  long double r = 1;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}
}  // namespace

long double evaluate_extended(const Trivariate& f, long double x, long double y, long double z) {
  long double s = 0;
  for (const auto& t : f.terms) s += t.c * ipow_ld(x, t.i) * ipow_ld(y, t.j) * ipow_ld(z, t.k);
  return s;
}

void gradient_extended(const Trivariate& f, long double x, long double y, long double z,
                       long double g[3]) {
  g[0] = g[1] = g[2] = 0;
  for (const auto& t : f.terms) {
    if (t.i > 0) g[0] += t.c * t.i * ipow_ld(x, t.i - 1) * ipow_ld(y, t.j) * ipow_ld(z, t.k);
    if (t.j > 0) g[1] += t.c * t.j * ipow_ld(x, t.i) * ipow_ld(y, t.j - 1) * ipow_ld(z, t.k);
    if (t.k > 0) g[2] += t.c * t.k * ipow_ld(x, t.i) * ipow_ld(y, t.j) * ipow_ld(z, t.k - 1);
  }
}

Polynomial restrict_to_line(const Trivariate& f, const Vec3& o, const Vec3& d) {
  Polynomial X[kStride], Y[kStride], Z[kStride];
  linear_powers(o.x, d.x, f.degree, X);
  linear_powers(o.y, d.y, f.degree, Y);
  linear_powers(o.z, d.z, f.degree, Z);
  Polynomial result;
  // Terms are sorted by (i, j, k): sum the z parts of each (i, j) group, then multiply once.
  std::size_t n = 0;
  while (n < f.terms.size()) {
    const int i = f.terms[n].i, j = f.terms[n].j;
    Polynomial zsum;
    for (; n < f.terms.size() && f.terms[n].i == i && f.terms[n].j == j; ++n)
      add_scaled(zsum, Z[f.terms[n].k], f.terms[n].c);
    add_scaled(result, multiply(X[i], multiply(Y[j], zsum)), 1.0);
  }
  return result;
}

}  // namespace raycast
