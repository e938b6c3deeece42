#include "geometry/algebraic.h"
#include "geometry/shape_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "geometry/spawn.h"
#include "geometry/torus.h"
#include "reference_roots.h"

namespace raycast {
namespace {

const Aabb kUnitBox{{-2, -2, -2}, {2, 2, 2}};
constexpr const char* kHeart = "(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3";

long double heart_ld(long double x, long double y, long double z) {
  const long double a = x * x + 2.25L * y * y + z * z - 1;
  return a * a * a - x * x * z * z * z - 9.0L / 80 * y * y * z * z * z;
}

std::vector<LocalHit> crossings(const Algebraic& s, const Ray& r) {
  SpanList l;
  spans(s, r, l);
  std::vector<LocalHit> v;
  for (const Span& sp : l) {
    v.push_back(sp.in);
    if (!s.open) v.push_back(sp.out);
  }
  return v;
}

TEST(Algebraic, Expansion_HandComputedTerms) {
  const Trivariate f = expand_polynomial("(x + 1)^2 - 2*x - 1/2");  // x^2 + 1/2
  ASSERT_EQ(f.terms.size(), 2u);
  EXPECT_EQ(f.degree, 2);
  EXPECT_EQ(evaluate(f, Vec3{3, 0, 0}), 9.5);
  EXPECT_EQ(gradient(f, Vec3{3, 7, 1}).x, 6);
  const Trivariate h = expand_polynomial(kHeart);
  EXPECT_EQ(h.degree, 6);
  const Vec3 p{0.3, -0.2, 0.7};
  EXPECT_NEAR(evaluate(h, p), (double)heart_ld(0.3L, -0.2L, 0.7L), 1e-15);
}

TEST(Algebraic, RestrictToLine_MatchesPointEvaluation) {
  const Trivariate h = expand_polynomial(kHeart);
  const Vec3 o{0.3, -1.2, 0.4}, d{0.2, 0.9, -0.1};
  const Polynomial p = restrict_to_line(h, o, d);
  EXPECT_EQ(p.degree, 6);
  for (double t : {-1.0, 0.0, 0.5, 2.0}) {
    const double want = evaluate(h, o + t * d);
    EXPECT_NEAR(evaluate(p, t), want, 1e-11 * std::max(1.0, std::abs(want)));
  }
}

// The restriction from the formula as written (line code, used where cheaper: the heart, two
// tori multiplied) and from the expanded terms, against f evaluated in long double along random
// rays through the box: both within a few ulps of the terms' magnitude (measured: heart 1.9e-16
// and 1.7e-16, two tori 8.3e-16 and 1.8e-16); the line code is chosen for both formulas here.
TEST(Algebraic, RestrictionFromTheFormula_MatchesExpandedAndLongDouble) {
  const char* const kTwoTori =
      "((x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + y^2)) * (((x-1)^2 + y^2 + z^2 + 0.84)^2 - "
      "4*((x-1)^2 + z^2))";
  for (const char* text : {kHeart, kTwoTori}) {
    SCOPED_TRACE(text);
    const Trivariate f = expand_polynomial(text);
    EXPECT_TRUE(f.line_code_cheaper);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst_code = 0, worst_expanded = 0;
    for (int i = 0; i < 300; ++i) {
      const Vec3 o{1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng)}, d{u(rng), u(rng), u(rng)};
      const Polynomial a = restrict_code_to_line(f, o, d), b = restrict_expanded_to_line(f, o, d);
      ASSERT_EQ(a.degree, b.degree);
      // The scale of f's terms along the ray: the sum of |c| |x|^i |y|^j |z|^k at |o| + |d|.
      const Vec3 m = abs(o) + abs(d);
      double scale = 0;
      for (const auto& t : f.terms)
        scale += std::abs(t.c) * std::pow(m.x, t.i) * std::pow(m.y, t.j) * std::pow(m.z, t.k);
      for (double t : {-1.0, -0.3, 0.0, 0.6, 1.0}) {
        const long double want = evaluate_extended(
            f, o.x + (long double)t * d.x, o.y + (long double)t * d.y, o.z + (long double)t * d.z);
        worst_code = std::max(worst_code, std::abs(double(evaluate(a, t) - want)) / scale);
        worst_expanded = std::max(worst_expanded, std::abs(double(evaluate(b, t) - want)) / scale);
      }
    }
    EXPECT_LT(worst_code, 1e-14);
    EXPECT_LT(worst_expanded, 1e-14);
    RecordProperty("worst_code", std::to_string(worst_code));
    RecordProperty("worst_expanded", std::to_string(worst_expanded));
  }
}

// The ray's polynomial by walking the formula's tree, every subtree computed where it occurs
// (no common subexpression saved), with the line code's arithmetic: a constant factor scales, a
// product is the double loop in (i, j) order, a power multiplies the base in n - 1 times.
std::vector<double> tree_line(const Expression& e, int index, const Vec3& o, const Vec3& d) {
  const ExprNode& n = e.nodes[index];
  auto mul = [](const std::vector<double>& a, const std::vector<double>& b) {
    if (b.size() == 1) {
      std::vector<double> r = a;
      for (double& c : r) c *= b[0];
      return r;
    }
    if (a.size() == 1) {
      std::vector<double> r = b;
      for (double& c : r) c = a[0] * c;
      return r;
    }
    std::vector<double> r(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
    return r;
  };
  switch (n.op) {
    case ExprOp::kConst:
      return {n.value};
    case ExprOp::kX:
    case ExprOp::kY:
    case ExprOp::kZ: {
      const int v = static_cast<int>(n.op) - static_cast<int>(ExprOp::kX);
      return {o[v], d[v]};
    }
    case ExprOp::kAdd:
    case ExprOp::kSub: {
      std::vector<double> a = tree_line(e, n.a, o, d);
      const std::vector<double> b = tree_line(e, n.b, o, d);
      const double sign = n.op == ExprOp::kAdd ? 1 : -1;
      if (a.size() < b.size()) a.resize(b.size(), 0.0);
      for (std::size_t k = 0; k < b.size(); ++k) a[k] += sign * b[k];
      return a;
    }
    case ExprOp::kMul: {
      const auto a = tree_line(e, n.a, o, d), b = tree_line(e, n.b, o, d);
      if (a.size() == 1 && b.size() == 1) return {a[0] * b[0]};
      return mul(a, b);
    }
    case ExprOp::kNeg: {
      std::vector<double> a = tree_line(e, n.a, o, d);
      for (double& c : a) c = -c;
      return a;
    }
    case ExprOp::kDiv: {
      std::vector<double> a = tree_line(e, n.a, o, d);
      const double v = tree_line(e, n.b, o, d)[0];
      for (double& c : a) c /= v;
      return a;
    }
    case ExprOp::kPow: {
      const auto base = tree_line(e, n.a, o, d);
      const int p = static_cast<int>(tree_line(e, n.b, o, d)[0]);
      std::vector<double> r = base;
      for (int k = 1; k < p; ++k) r = mul(r, base);
      return r;
    }
    default:
      ADD_FAILURE() << "operation not in the test formulas";
      return {};
  }
}

// restrict_code_to_line(f) on `count` random lines: bit for bit the tree walk's coefficients of
// the formula `text` f was expanded from.
void expect_line_code_equal_to_tree_walk(const Trivariate& f, const char* text, unsigned seed,
                                         int count) {
  const Expression e = parse_expression(text);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < count; ++i) {
    const Vec3 o{1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng)}, d{u(rng), u(rng), u(rng)};
    const Polynomial a = restrict_code_to_line(f, o, d);
    const std::vector<double> want = tree_line(e, e.root, o, d);
    ASSERT_EQ(a.degree, std::min(f.degree, static_cast<int>(want.size()) - 1));
    for (int k = 0; k <= a.degree; ++k) ASSERT_EQ(a.c[k], want[k]) << "coefficient " << k;
  }
}

// Common subexpressions (the heart's x^2, y^2, z^3; the tori's x^2, y^2, z^2, (x-1)^2) are
// computed once in the line code: it must say so (kStore, kLoad), and its polynomial must be the
// tree's, bit for bit, on random rays (the saved copy is the value computed anew).
TEST(Algebraic, LineCodeCommonSubexpressions_BitEqualToTheTreeWalk) {
  const char* const kTwoTori =
      "((x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + y^2)) * (((x-1)^2 + y^2 + z^2 + 0.84)^2 - "
      "4*((x-1)^2 + z^2))";
  for (const char* text : {kHeart, kTwoTori}) {
    SCOPED_TRACE(text);
    const Trivariate f = expand_polynomial(text);
    ASSERT_TRUE(f.line_code_cheaper);
    int stores = 0, loads = 0;
    for (const auto& op : f.line_code) {
      stores += op.kind == Trivariate::LineOp::kStore;
      loads += op.kind == Trivariate::LineOp::kLoad;
    }
    EXPECT_GE(stores, 3);
    EXPECT_GE(loads, stores);
    expect_line_code_equal_to_tree_walk(f, text, 9, 200);
  }
}

// The register steps translated from the line code: negation, division, constants added and
// multiplied on either side, products above the unrolled degrees (a 9th power times a square),
// bit for bit the tree walk's coefficients.
TEST(Algebraic, LineCodeRegisterSteps_BitEqualToTheTreeWalk) {
  for (const char* text :
       {"-(x - 2*y + 1)^3 / 3 * (z + 0.5)^2 - (y - z)^2 * (1 - x) + 2",
        "(x + y + 1)^9 * (z - 1)^2 - 3 * (y*z - 1)^5", "((x + y)^2 + 1)^4 * (0.5 - (z - x)^2)^4"}) {
    SCOPED_TRACE(text);
    const Trivariate f = expand_polynomial(text);
    ASSERT_TRUE(f.line_code_cheaper);
    ASSERT_FALSE(f.line_steps.empty());
    expect_line_code_equal_to_tree_walk(f, text, 12, 100);
  }
}

TEST(Algebraic, ExtendedEvaluation_MatchesTheHeartInLongDouble) {
  // The extended-precision value and gradient (tabled powers) against the heart written out by
  // hand in long double and its gradient by central differences, at random points.
  const Trivariate h = expand_polynomial(kHeart);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 200; ++i) {
    const long double x = u(rng), y = u(rng), z = u(rng);
    const long double want = heart_ld(x, y, z);
    EXPECT_NEAR(double(evaluate_extended(h, x, y, z)), double(want),
                1e-15 * std::max(1.0, double(std::abs(want))));
    long double g[3];
    gradient_extended(h, x, y, z, g);
    const long double e = 1e-6L;
    const long double want_g[3] = {(heart_ld(x + e, y, z) - heart_ld(x - e, y, z)) / (2 * e),
                                   (heart_ld(x, y + e, z) - heart_ld(x, y - e, z)) / (2 * e),
                                   (heart_ld(x, y, z + e) - heart_ld(x, y, z - e)) / (2 * e)};
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(double(g[k]), double(want_g[k]),
                  1e-6 * std::max(1.0, double(std::abs(want_g[k]))));
  }
}

TEST(Algebraic, Sphere_HandComputedCrossingsAndNormal) {
  const Algebraic s = make_algebraic("x^2 + y^2 + z^2 - 1", kUnitBox);
  const Ray r{{-5, 0, 0}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 4, 1e-14);
  const SurfaceInfo si = surface(s, r, h);
  EXPECT_NEAR(si.n.x, -1, 1e-14);
  const auto c = crossings(s, r);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[1].t, 6, 1e-14);
}

TEST(Algebraic, TorusEquation_MatchesTorusShape) {
  // The seed's toroid: (x^2 + y^2 + z^2 - a^2 - b^2)^2 - 4 a^2 (b^2 - z^2), a = 1, b = 0.3.
  const Algebraic s = make_algebraic("(x^2 + y^2 + z^2 - 1 - 0.09)^2 - 4*(0.09 - z^2)",
                                     Aabb{{-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}});
  const Torus t = make_torus(1, 0.3);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    SCOPED_TRACE(i);
    const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    const Ray r{o, Vec3{1.3 * u(rng), 1.3 * u(rng), 0.3 * u(rng)} - o};
    LocalHit ha, ht;
    const bool a = intersect(s, r, ha), b = intersect(t, r, ht);
    ASSERT_EQ(a, b);
    if (!a) continue;
    ++hits;
    EXPECT_NEAR(ha.t, ht.t, 1e-9 * ht.t);
    const SurfaceInfo sa = surface(s, r, ha), st = surface(t, r, ht);
    EXPECT_NEAR(dot(sa.n, st.n), 1, 1e-9);
  }
  EXPECT_GT(hits, 500);
}

TEST(Algebraic, BoxClipsTheSolid_FaceHitWithFaceNormal) {
  // A sphere of radius 2 clipped by the box [-1, 1]^3: the box itself.
  const Algebraic s = make_algebraic("x^2 + y^2 + z^2 - 4", Aabb{{-1, -1, -1}, {1, 1, 1}});
  const Ray r{{0.2, 0.3, -5}, {0, 0, 1}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_EQ(h.t, 4);
  const SurfaceInfo si = surface(s, r, h);
  EXPECT_EQ(si.n, (Vec3{0, 0, -1}));
  EXPECT_EQ(si.p.z, -1);
  const auto c = crossings(s, r);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[1].t, 6);
  EXPECT_EQ(surface(s, r, c[1]).n, (Vec3{0, 0, 1}));
  // Open: only the curved surface, which lies outside the box.
  const Algebraic open = make_algebraic("x^2 + y^2 + z^2 - 4", Aabb{{-1, -1, -1}, {1, 1, 1}}, true);
  EXPECT_FALSE(intersect(open, r, h));
  EXPECT_FALSE(is_closed(open));
  EXPECT_FALSE(contains(open, Vec3{0, 0, 0}));
}

TEST(Algebraic, OpenSurface_EveryCrossingOnce) {
  const Algebraic s = make_algebraic("x^2 + y^2 + z^2 - 1", kUnitBox, true);
  const auto c = crossings(s, Ray{{-5, 0, 0}, {1, 0, 0}});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].t, 4, 1e-14);
  EXPECT_NEAR(c[1].t, 6, 1e-14);
}

TEST(Algebraic, TMinTMaxAndStartingInside) {
  const Algebraic s = make_algebraic("x^2 + y^2 + z^2 - 1", kUnitBox);
  LocalHit h;
  Ray r{{-5, 0, 0}, {1, 0, 0}, 0, 4};
  ASSERT_TRUE(intersect(s, r, h));
  EXPECT_NEAR(h.t, 4, 1e-14);
  r.tmax = 3.999999;
  EXPECT_FALSE(intersect(s, r, h));
  EXPECT_FALSE(occluded(s, r));
  ASSERT_TRUE(intersect(s, Ray{{0, 0, 0}, {0, 0, 2}}, h));
  EXPECT_NEAR(h.t, 0.5, 1e-14);
  EXPECT_TRUE(contains(s, Vec3{0, 0, 0}));
}

TEST(Algebraic, Degree12_RootsOfProductOfSpheres) {
  // Six concentric spheres: radii 0.5 .. 1.75, degree 12.
  const Algebraic s = make_algebraic(
      "(x^2+y^2+z^2-0.25)*(x^2+y^2+z^2-0.5625)*(x^2+y^2+z^2-1)*(x^2+y^2+z^2-1.5625)*"
      "(x^2+y^2+z^2-2.25)*(x^2+y^2+z^2-3.0625)",
      kUnitBox);
  EXPECT_EQ(s.f.degree, 12);
  const auto c = crossings(s, Ray{{0, 0, -1.9}, {0, 0, 1}});
  ASSERT_EQ(c.size(), 12u);
  const double radii[] = {1.75, 1.5, 1.25, 1.0, 0.75, 0.5};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(c[i].t, 1.9 - radii[i], 1e-9);
    EXPECT_NEAR(c[11 - i].t, 1.9 + radii[i], 1e-9);
  }
}

TEST(Algebraic, Heart_RandomRaysMatchLongDoubleReference) {
  const Algebraic s = make_algebraic(kHeart, Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}});
  int compared = 0;
  for (unsigned seed = 0; seed < 600; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const Vec3 o{4 * u(rng), 4 * u(rng), 4 * u(rng)};
    const Ray r{o, Vec3{1.2 * u(rng), 0.7 * u(rng), 1.2 * u(rng)} - o};
    auto f = [&](long double t) {
      return heart_ld(r.o.x + t * r.d.x, r.o.y + t * r.d.y, r.o.z + t * r.d.z);
    };
    const auto ref = testing_reference::sign_change_roots(f, 0, 3, 3000);
    LocalHit h;
    const bool hit = intersect(s, r, h);
    if (ref.empty()) continue;
    ASSERT_TRUE(hit);
    if (h.t < (double)ref[0] * (1 - 1e-9)) {
      EXPECT_NEAR((double)f(h.t), 0.0, 1e-9);
      continue;
    }
    EXPECT_NEAR(h.t, (double)ref[0], 1e-9 * (double)ref[0]);
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TEST(Algebraic, Heart_SpansMatchInsideOracleAndNormalsOutward) {
  const Algebraic s = make_algebraic(kHeart, Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  int normals = 0;
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE(i);
    const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
    const Ray r{o, Vec3{1.2 * u(rng), 0.7 * u(rng), 1.2 * u(rng)} - o};
    testing::check_spans_against_oracle(
        s, r, [&](const Vec3& p) { return contains(s, p); }, 0, 3.0, 300);
    LocalHit h;
    if (!intersect(s, r, h)) continue;
    const SurfaceInfo si = surface(s, r, h);
    EXPECT_NEAR(length(si.n), 1, 1e-12);
    // Away from the two singular points, the normal points out of the solid.
    if (std::abs(si.p.x) + std::abs(si.p.y) > 1e-3) {
      EXPECT_FALSE(contains(s, si.p + 1e-6 * si.n));
      EXPECT_TRUE(contains(s, si.p - 1e-6 * si.n));
      ++normals;
    }
  }
  EXPECT_GT(normals, 50);
}

// Pinned: a camera ray hitting the heart just below its equator z = 0, where f vanishes to second
// order; the double-precision root was 3e-7 off and the gradient there pointed 40 degrees wrong.
TEST(Algebraic, HeartEquatorHit_NormalFacesTheViewer) {
  const Algebraic s = make_algebraic(kHeart, Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}});
  const Ray r{{0.3, -5, 2.5}, {-0.14106469656424878, 0.86507734142178705, -0.49220315393326086}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  const SurfaceInfo si = surface(s, r, h);
  // The surface near z = 0 is A = c z with A = x^2 + 9/4 y^2 + z^2 - 1, c = cbrt(x^2 + 9/80 y^2):
  // its normal is grad A - c e_z.
  const Vec3 p = si.p;
  const double c = std::cbrt(p.x * p.x + 9.0 / 80 * p.y * p.y);
  const Vec3 want = normalize(Vec3{2 * p.x, 4.5 * p.y, -c});
  EXPECT_GT(dot(si.n, want), 0.9999);
  EXPECT_LT(dot(si.n, normalize(r.d)), -0.5);
}

TEST(Algebraic, GrazingSphere_NoMissJustInside) {
  const Algebraic s = make_algebraic("x^2 + y^2 + z^2 - 1", kUnitBox);
  for (double eps : {1e-4, 1e-8, 1e-12}) {
    SCOPED_TRACE(eps);
    LocalHit h;
    EXPECT_TRUE(intersect(s, Ray{{-5, 1 - eps, 0}, {1, 0, 0}}, h));
    EXPECT_FALSE(intersect(s, Ray{{-5, 1 + eps, 0}, {1, 0, 0}}, h));
  }
}

// occluded takes a short cut (a certain sign change of f between tmin, plus the largest root
// error, and tmax proves a hit); it must answer exactly as intersect does: on random segments
// through the heart and two linked tori (degree 8), closed and open, and on shadow rays leaving a
// hit on the surface itself (which must not see their own surface).
TEST(Algebraic, Occluded_AgreesWithIntersectOnSegmentsAndShadowRays) {
  const char* kTori =
      "((x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + y^2)) * "
      "(((x-1)^2 + y^2 + z^2 + 0.84)^2 - 4*((x-1)^2 + z^2))";
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  int hits = 0, shadow_cases = 0;
  for (const bool open : {false, true}) {
    for (const auto& [text, box] : {std::pair{kHeart, Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}}},
                                    std::pair{kTori, Aabb{{-1.5, -1.5, -1.5}, {2.5, 1.5, 1.5}}}}) {
      const Algebraic s = make_algebraic(text, box, open);
      for (int i = 0; i < 1500; ++i) {
        const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
        const Vec3 target{1.2 * u(rng), 0.8 * u(rng), 1.2 * u(rng)};
        Ray r{o, target - o};
        r.tmin = unit(rng) < 0.3 ? 0 : 0.6 * unit(rng);
        r.tmax = unit(rng) < 0.3 ? kInfinity : r.tmin + 2 * unit(rng);
        LocalHit h;
        const bool hit = intersect(s, r, h);
        hits += hit;
        ASSERT_EQ(occluded(s, r), hit) << "open " << open << " ray " << i;
        if (!hit || h.part != 0) continue;
        // A shadow ray from the hit towards a random light, as the integrator spawns it (tmin 0
        // at a point on the surface).
        const Vec3 p = r.at(h.t);
        const Vec3 light{4 * u(rng), 4 * u(rng), 4 * u(rng)};
        for (const double tmax : {1.0, 0.5, 0.01}) {
          const Ray sr{p, light - p, 0, tmax};
          LocalHit sh;
          ASSERT_EQ(occluded(s, sr), intersect(s, sr, sh)) << "open " << open << " shadow " << i;
          ++shadow_cases;
        }
      }
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(shadow_cases, 3000);
}

// occluded settles most rays by Bernstein sweeps of [tmin, tmax] without isolating roots: shadow
// rays as the renderer spawns them (origin offset off the surface), segments starting inside a
// solid that a box face cuts (no root at all, the sign decides), short and long segments.
TEST(Algebraic, Occluded_BySweeps_AgreesWithIntersect) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  int cases = 0, hits = 0, inside = 0;
  for (const bool open : {false, true}) {
    for (const auto& [text, box] :
         {std::pair{kHeart, Aabb{{-1.5, -1, -1.5}, {1.5, 1, 1.5}}},
          std::pair{"x^2 + y^2 + z^2 - 2.5", Aabb{{-1, -1, -1}, {1, 1, 1}}},
          std::pair{"(x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + y^2)", Aabb{{-2, -2, -1}, {2, 2, 1}}}}) {
      const Algebraic s = make_algebraic(text, box, open);
      for (int i = 0; i < 1500; ++i) {
        const Vec3 o{2.5 * u(rng), 2.5 * u(rng), 2.5 * u(rng)};
        const Vec3 target{u(rng), u(rng), u(rng)};
        Ray r{o, target - o};
        r.tmin = unit(rng) < 0.3 ? 0 : 0.8 * unit(rng);
        r.tmax = unit(rng) < 0.3 ? kInfinity : r.tmin + 1.5 * unit(rng);
        LocalHit h;
        const bool hit = intersect(s, r, h);
        inside += contains(s, r.at(r.tmin));
        ASSERT_EQ(occluded(s, r), hit) << text << " open " << open << " ray " << i;
        ++cases;
        if (!hit) continue;
        ++hits;
        // tmin just before the hit, within the cap of a root's error estimate: only the full
        // solve can judge that root.
        Ray before = r;
        before.tmin = h.t - 1e-4 * unit(rng) * std::abs(h.t);
        LocalHit bh;
        ASSERT_EQ(occluded(s, before), intersect(s, before, bh))
            << text << " open " << open << " before " << i;
        const SurfaceInfo si = surface(s, r, h);
        const Vec3 light{4 * u(rng), 4 * u(rng), 4 * u(rng)};
        for (const double tmax : {1.0, 0.3, 0.002}) {
          const Vec3 from = offset_ray_origin(si, light - si.p);
          const Ray sr{from, light - from, 0, tmax};
          LocalHit sh;
          ASSERT_EQ(occluded(s, sr), intersect(s, sr, sh))
              << text << " open " << open << " shadow " << i << " tmax " << tmax;
          ++cases;
        }
      }
    }
  }
  EXPECT_GT(hits, 3000);
  EXPECT_GT(inside, 300);
  EXPECT_GT(cases, 15000);
}

// bounds() is the reach: the part of the box where solid or surface may lie (interval bounds of
// f over halved cells). Every crossing spans() reports on random rays through the whole box, every
// hit, and every sampled point inside the solid must lie in it; it must lie in the box; and on the
// heart and the linked tori it must come within the search's resolution of the extents a dense
// sample of f < 0 gives (so that it shrinks at all). occluded, which skips segments missing the
// reach, must answer as intersect on segments of those lines.
TEST(Algebraic, Reach_HoldsEveryCrossingAndInsidePoint) {
  const char* kTori =
      "((x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + y^2)) * "
      "(((x-1)^2 + y^2 + z^2 + 0.84)^2 - 4*((x-1)^2 + z^2))";
  struct Case {
    const char* text;
    Aabb box;
  };
  const Case cases[] = {
      {kHeart, {{-1.5, -1, -1.5}, {1.5, 1, 1.5}}},
      {kTori, {{-1.5, -1.5, -1.5}, {2.5, 1.5, 1.5}}},
      {"x^2 + y^2 + z^2 - 2.5", {{-1, -1, -1}, {1, 1, 1}}},   // cut by the box: all of it
      {"x^2 + y^2 + z^2 - 0.25", {{-3, -1, -1}, {1, 2, 4}}},  // a small ball in a large box
      {"z - 0.3*x + 0.1*y^2", {{-1, -1, -2}, {1, 1, 2}}},     // a sheet: half the box (closed)
      {"(x^2 + y^2 + z^2 + 0.5)^2 + 1", {{-1, -1, -1}, {1, 1, 1}}},  // no solid: the box
  };
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  int crossings_seen = 0, inside_seen = 0;
  for (const bool open : {false, true}) {
    for (const Case& c : cases) {
      const Algebraic s = make_algebraic(c.text, c.box, open);
      const Aabb bound = bounds(s);
      ASSERT_FALSE(bound.is_empty()) << c.text;
      for (int a = 0; a < 3; ++a) {
        ASSERT_GE(bound.lo[a], c.box.lo[a]) << c.text;
        ASSERT_LE(bound.hi[a], c.box.hi[a]) << c.text;
      }
      // Points computed from a hit's t carry the rounding of o + t d (a face hit's lies on the
      // box's face only up to that).
      Aabb reach = bound;
      for (int a = 0; a < 3; ++a) {
        reach.lo[a] -= 1e-12 * c.box.extent()[a];
        reach.hi[a] += 1e-12 * c.box.extent()[a];
      }
      const Vec3 lo = c.box.lo, ext = c.box.extent();
      auto in_box = [&] {
        return Vec3{lo.x + ext.x * unit(rng), lo.y + ext.y * unit(rng), lo.z + ext.z * unit(rng)};
      };
      // Lines through two random points of the box (some grazing a face), both directions.
      for (int i = 0; i < 4000; ++i) {
        const Vec3 a = in_box(), b = in_box();
        const Ray r{a - 2.0 * (b - a), b - a};
        SpanList l;
        spans(s, r, l);
        for (const Span& sp : l)
          for (const LocalHit* h : {&sp.in, &sp.out}) {
            if (!std::isfinite(h->t)) continue;
            ++crossings_seen;
            ASSERT_TRUE(reach.contains(r.at(h->t))) << c.text << " open " << open << " ray " << i;
          }
        LocalHit h;
        if (intersect(s, r, h)) {
          ASSERT_TRUE(reach.contains(r.at(h.t))) << c.text << " open " << open << " ray " << i;
        }
        // occluded skips segments that miss the reach box: it must still answer as intersect.
        Ray seg = r;
        seg.tmin = 4 * unit(rng);
        seg.tmax = seg.tmin + 2 * unit(rng);
        LocalHit sh;
        ASSERT_EQ(occluded(s, seg), intersect(s, seg, sh))
            << c.text << " open " << open << " segment " << i;
        const Vec3 p = in_box();
        if (contains(s, p)) {
          ++inside_seen;
          ASSERT_TRUE(reach.contains(p)) << c.text << " point " << i;
        }
      }
    }
  }
  EXPECT_GT(crossings_seen, 20000);
  EXPECT_GT(inside_seen, 2000);
  // Tightness: within 3/64 of the box of the sampled extents (the search resolves 1/256).
  for (const Case& c : {cases[0], cases[1], cases[3]}) {
    const Algebraic s = make_algebraic(c.text, c.box);
    Aabb sampled;
    const int n = 120;
    const Vec3 lo = c.box.lo, ext = c.box.extent();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= n; ++k) {
          const Vec3 p{lo.x + ext.x * i / n, lo.y + ext.y * j / n, lo.z + ext.z * k / n};
          if (evaluate(s.f, p) < 0) sampled.grow(p);
        }
    const Aabb reach = bounds(s);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(reach.lo[a], sampled.lo[a]) << c.text;
      EXPECT_GE(reach.hi[a], sampled.hi[a]) << c.text;
      EXPECT_LT(sampled.lo[a] - reach.lo[a], 3 * ext[a] / 64) << c.text << " axis " << a;
      EXPECT_LT(reach.hi[a] - sampled.hi[a], 3 * ext[a] / 64) << c.text << " axis " << a;
    }
  }
}

TEST(Algebraic, MakeAlgebraic_RejectsBadInput) {
  EXPECT_THROW(make_algebraic("x^2 - 1", Aabb{{0, 0, 0}, {0, 1, 1}}), std::invalid_argument);
  EXPECT_THROW(make_algebraic("2 + 3", kUnitBox), ExpressionError);
  EXPECT_THROW(make_algebraic("x^17", kUnitBox), ExpressionError);
  EXPECT_THROW(make_algebraic("x / y", kUnitBox), ExpressionError);
  EXPECT_THROW(make_algebraic("x^0.5", kUnitBox), ExpressionError);
  EXPECT_THROW(make_algebraic("x / (1 - 1)", kUnitBox), ExpressionError);
}

}  // namespace
}  // namespace raycast
