// functions.inc's internal functions: each against its equation written out here, the numbers
// against the installed functions.inc, calls from scenes, and an isosurface of f_sphere against
// the analytic sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/implicit.h"
#include "io/scene_error.h"
#include "load/formula_noise_registration.h"
#include "load/pov_loader.h"
#include "math/formula.h"
#include "pov/function_expr.h"
#include "pov/internal_functions.h"
#include "pov/interpreter.h"
#include "texture/noise.h"

namespace raycast::pov {
namespace {

double call(int number, std::vector<double> args) {
  const auto f = internal_function(number);
  if (!f) return std::nan("");
  EXPECT_EQ(f->params.size(), args.size()) << "internal(" << number << ")";
  return evaluate(*f, args);
}

constexpr int kSphere = 61, kTorus = 70, kRoundedBox = 60, kSuperellipsoid = 68, kR = 57, kTh = 69,
              kPh = 47, kTorus2 = 71, kEllipsoid = 17, kHelix1 = 25, kParaboloid = 45,
              kSteiner = 65, kHeart = 23, kNoise3d = 76, kNoiseGenerator = 78, kAlgbrCyl1 = 0,
              kPoly4 = 51, kSpiral = 64;

TEST(PovInternalFunctions, SphereIsTheDistanceToTheSphere) {
  EXPECT_DOUBLE_EQ(call(kSphere, {3, 4, 0, 1}), 4);
  EXPECT_DOUBLE_EQ(call(kSphere, {0, 0, 0, 2}), -2);
  EXPECT_DOUBLE_EQ(call(kSphere, {0, -2, 0, 2}), 0);
}

TEST(PovInternalFunctions, TorusIsTheDistanceToTheTorusAboutY) {
  const double R = 1.5, r = 0.25;
  EXPECT_NEAR(call(kTorus, {R + r, 0, 0, R, r}), 0, 1e-15);
  EXPECT_NEAR(call(kTorus, {0, r, -R, R, r}), 0, 1e-15);
  EXPECT_DOUBLE_EQ(call(kTorus, {R, 0, 0, R, r}), -r);
  EXPECT_DOUBLE_EQ(call(kTorus, {0, 0, 0, R, r}), R - r);
  // (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), times minus the field strength.
  const double x = 0.3, y = 0.2, z = 1.1, s = -2;
  const double f = std::pow(x * x + y * y + z * z + R * R - r * r, 2) - 4 * R * R * (x * x + z * z);
  EXPECT_NEAR(call(kTorus2, {x, y, z, s, R, r}), -s * f, 1e-12);
}

TEST(PovInternalFunctions, RoundedBoxIsTheDistanceToTheRoundedBox) {
  EXPECT_DOUBLE_EQ(call(kRoundedBox, {2, 0, 0, 0.3, 1, 1, 1}), 1);
  EXPECT_DOUBLE_EQ(call(kRoundedBox, {0, 0, 0, 0.3, 1, 2, 3}), -1);
  EXPECT_DOUBLE_EQ(call(kRoundedBox, {0, 0, 2.5, 0.3, 1, 2, 3}), -0.5);
  // Beyond a corner: the distance to the corner sphere of radius 0.3 centred at (0.7, 0.7, 0.7).
  const double d = std::sqrt(3 * 0.8 * 0.8) - 0.3;
  EXPECT_NEAR(call(kRoundedBox, {1.5, 1.5, 1.5, 0.3, 1, 1, 1}), d, 1e-15);
  EXPECT_NEAR(call(kRoundedBox, {0.7 + 0.3 / std::sqrt(3.0), 0.7 + 0.3 / std::sqrt(3.0),
                                 0.7 + 0.3 / std::sqrt(3.0), 0.3, 1, 1, 1}),
              0, 1e-15);
}

TEST(PovInternalFunctions, SuperellipsoidIsOneMinusItsEquation) {
  const double e = 0.5, n = 0.25, x = 0.3, y = 0.4, z = 0.2;
  const double f = std::pow(std::pow(x, 2 / e) + std::pow(y, 2 / e), e / n) + std::pow(z, 2 / n);
  EXPECT_NEAR(call(kSuperellipsoid, {x, -y, z, e, n}), 1 - f, 1e-14);
  EXPECT_NEAR(call(kSuperellipsoid, {0, 0, 1, e, n}), 0, 1e-15);
  EXPECT_DOUBLE_EQ(call(kSuperellipsoid, {0, 0, 0, e, n}), 1);
}

TEST(PovInternalFunctions, SphericalCoordinates) {
  EXPECT_DOUBLE_EQ(call(kR, {2, 3, 6}), 7);
  EXPECT_DOUBLE_EQ(call(kTh, {1, 5, 1}), std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(call(kTh, {-1, 0, 0}), -std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(call(kPh, {0, 1, 0}), 0);
  EXPECT_DOUBLE_EQ(call(kPh, {1, 0, 0}), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(call(kPh, {0, -2, 0}), std::numbers::pi);
}

TEST(PovInternalFunctions, ClassicSurfacesAreTheirEquationsTimesMinusTheStrength) {
  const double x = 0.7, y = -0.4, z = 0.9, s = -0.5;
  EXPECT_DOUBLE_EQ(call(kEllipsoid, {x, y, z, 1, 2, 4}), std::sqrt(x * x + 4 * y * y + 16 * z * z));
  EXPECT_NEAR(call(kParaboloid, {x, y, z, s}), -s * (x * x + z * z - y), 1e-15);
  EXPECT_NEAR(call(kSteiner, {x, y, z, s}),
              -s * (x * x * y * y + y * y * z * z + z * z * x * x + x * y * z), 1e-15);
  const double h = 2.25 * x * x + y * y + z * z - 1;
  EXPECT_NEAR(call(kHeart, {x, y, z, s}),
              -s * (h * h * h - y * y * z * z * z - 0.1125 * x * x * z * z * z), 1e-15);
  // A lathe: radius 1 + y^2 at height y.
  EXPECT_NEAR(call(kPoly4, {2, 1, 0, 1, 0, 1, 0, 0}), 0, 1e-15);
}

TEST(PovInternalFunctions, BlobsAreMinusTheirComponentsFields) {
  // Strength s, inverse radius k: s (1 - (k r)^2)^2 inside r < 1 / k, 0 outside.
  // The components at x = -0.7 and 0.7.
  EXPECT_DOUBLE_EQ(call(6, {-0.7, 0, 0, 1.4, 1, 0.8, 1.2, 1}), -1);
  EXPECT_NEAR(call(6, {0, 0, 0, 1.4, 1, 0.8, 1.2, 1}),
              -(std::pow(1 - 0.64 * 0.49, 2) + 1.2 * std::pow(1 - 0.49, 2)), 1e-15);
  // Two equal Gaussian components: P3 - s (e^-(k r1^2) + e^-(k r2^2)).
  EXPECT_NEAR(call(7, {0.5, 0, 0, 1, 5, 2, 1}), 1 - 4 * std::exp(-1.25), 1e-15);
}

TEST(PovInternalFunctions, SorSwitchRevolvesTheCurveAboutY) {
  // The lemniscate of Gerono u^4 - u^2 + v^2: extruded along z, or revolved (u = distance from y).
  const double u = 0.5, v = 0.3, g = u * u * u * u - u * u + v * v;
  EXPECT_NEAR(call(kAlgbrCyl1, {u, v, 7, 1, 10, 0, 0, 0}), g, 1e-15);
  EXPECT_NEAR(call(kAlgbrCyl1, {0.3, v, 0.4, 1, 10, 1, 0, 0}), g, 1e-15);
  EXPECT_DOUBLE_EQ(call(kAlgbrCyl1, {5, 0, 0, 1, 10, 0, 0, 0}), 10);  // the field limit
}

TEST(PovInternalFunctions, HelixIsZeroOnItsTubeAndMinusTheRadiusOnItsAxis) {
  // One strand at radius 0.9 turning 8 radians per unit of y; round cross section of radius 0.3.
  const double R = 0.9, k = 8, r = 0.3;
  for (double t : {0.0, 0.1, 0.37}) {
    const double a = k * t;
    EXPECT_NEAR(call(kHelix1, {R * std::cos(a), t, R * std::sin(a), 1, k, r, R, 1, 1, 0}), -r,
                1e-12);
    EXPECT_NEAR(
        call(kHelix1, {(R + r) * std::cos(a), t, (R + r) * std::sin(a), 1, k, r, R, 1, 1, 0}), 0,
        1e-12);
  }
  // Two strands: the second half a turn on.
  const double a = std::numbers::pi;
  EXPECT_NEAR(call(kHelix1, {R * std::cos(a), 0, R * std::sin(a), 2, k, r, R, 1, 1, 0}), -r, 1e-12);
  // A flat spiral 0.2 apart: on a winding at radius 0.4 (angle 0), a tube of radius 0.04.
  EXPECT_NEAR(call(kSpiral, {0.4, 0, 0, 0.2, 0.04, 2, 0, 0, 1}), -0.04, 1e-12);
  EXPECT_NEAR(call(kSpiral, {3, 0, 0, 0.2, 0.04, 2, 0, 0, 1}), 1, 1e-12);  // outside radius P2
}

TEST(PovInternalFunctions, NoiseIsTheTextureNoise) {
  for (double t : {0.1, 1.7, -3.3}) {
    const Vec3 p{t, 2 * t, 0.5 - t};
    EXPECT_DOUBLE_EQ(call(kNoise3d, {p.x, p.y, p.z}), texture::noise(p, 2));
    EXPECT_DOUBLE_EQ(call(kNoiseGenerator, {p.x, p.y, p.z, 3}), texture::noise(p, 3));
  }
}

TEST(PovInternalFunctions, RidgedMultifractalIsMusgravesSumAndItsFormulaAgrees) {
  const double H = 0.07, lac = 2.2, offset = 0.6, gain = 0.9;
  const Vec3 p{0.3, 1.1, -0.7};
  // Three octaves written out: the ridge of each, weighted by the one before (clamped) times gain.
  double want = 0, weight = 1;
  for (int i = 0; i < 3; ++i) {
    const double f = std::pow(lac, i);
    const double n = 2 * texture::noise(p * f, 2) - 1;
    const double ridge = (offset - std::abs(n)) * (offset - std::abs(n)) * weight;
    want += ridge * std::pow(f, -H);
    weight = std::min(std::max(ridge * gain, 0.0), 1.0);
  }
  EXPECT_NEAR(call(59, {p.x, p.y, p.z, H, lac, 3, offset, gain, 2}), want, 1e-14);
  // In an isosurface the octaves are unrolled into noise2 terms: the same value.
  FunctionValue f;
  f.params = {"x", "y", "z"};
  auto user = std::make_shared<FnNode>();
  user->kind = FnNode::User;
  user->callee = internal_function(59);
  for (const char v : {'x', 'y', 'z'}) {
    auto n = std::make_shared<FnNode>();
    n->kind = FnNode::Variable;
    n->variable = v;
    user->args.push_back(n);
  }
  for (double a : {H, lac, 3.0, offset, gain, 2.0}) {
    auto n = std::make_shared<FnNode>();
    n->number = a;
    user->args.push_back(n);
  }
  f.body = user;
  register_formula_noise();
  const std::string text = formula_text(f, false);
  ASSERT_NE(text.find("noise2"), std::string::npos) << text;
  EXPECT_NEAR(run<double>(compile_formula(text), p.x, p.y, p.z), want, 1e-14);
}

TEST(PovInternalFunctions, NumbersAndNamesAreFunctionsIncs) {
  const char* path = "/usr/share/povray-3.7/include/functions.inc";
  std::ifstream in(path);
  if (!in) GTEST_SKIP() << path << " is not installed";
  std::map<int, std::string> declared;
  const std::regex decl(R"(#declare\s+(f_\w+)\s*=\s*function\s*\{\s*internal\((\d+)\)\s*\})");
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, decl)) declared[std::stoi(m[2])] = m[1];
  }
  ASSERT_GE(declared.size(), 78u);
  for (const InternalFunctionInfo& f : internal_function_table()) {
    ASSERT_TRUE(declared.count(f.number)) << f.name;
    EXPECT_EQ(declared[f.number], f.name) << "internal(" << f.number << ")";
  }
}

// What the scene's #debug statements print, and its warnings.
std::string debug_of(const std::string& text, std::vector<std::string>* warnings = nullptr) {
  std::ostringstream out;
  Options o;
  o.debug = &out;
  o.system_library_path = false;
  const PovScene s = interpret_pov(text, "t.pov", ".", o);
  if (warnings) *warnings = s.warnings;
  return out.str();
}

TEST(PovInternalFunctions, DeclaredFunctionsCallLikeUserFunctions) {
  const std::string decl =
      "#declare f_sphere = function { internal(61) }\n"
      "#declare f_torus = function { internal(70) }\n"
      "#declare f_unknown = function { internal(999) }\n";
  EXPECT_EQ(debug_of(decl + "#debug str(f_sphere(3, 4, 0, 1), 0, 3)\n"), "4.000");
  EXPECT_EQ(debug_of(decl + "#declare F = function { f_torus(x, y, z, 2, 0.5) * 2 }\n"
                            "#debug str(F(2, 0, 0), 0, 3)\n"),
            "-1.000");
  const std::string scene =
      "camera { location <0, 0, -10> look_at 0 }\n" + decl +
      "isosurface { function { f_sphere(x, y, z, 1) } contained_by { box { -2, 2 } } }\n";
  std::vector<std::string> warnings;
  load_pov_scene_text(scene, "t.pov", ".", -1, {}, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
  // A number raycast does not define stays opaque: a call is 0, with a warning.
  debug_of(decl + "#debug str(f_unknown(1, 2, 3), 0, 3)\n", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
}

TEST(PovInternalFunctions, NoiseInAnIsosurfaceIsTheFormulasNoise) {
  const std::string scene =
      "camera { location <0, 0, -10> look_at 0 }\n"
      "#declare f_noise3d = function { internal(76) }\n"
      "isosurface { function { x * x + y * y + z * z - 1 + f_noise3d(x * 4, y * 4, z * 4) * 0.3 }\n"
      "  contained_by { box { -2, 2 } } }\n";
  std::vector<std::string> warnings;
  load_pov_scene_text(scene, "t.pov", ".", -1, {}, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
  // The formula names generator 2's noise, which the loader registered: the same values.
  const Formula f = compile_formula("noise2(4 x, 4 y, 4 z)");
  EXPECT_DOUBLE_EQ(run<double>(f, 0.3, -0.2, 0.7), texture::noise({1.2, -0.8, 2.8}, 2));
}

TEST(PovInternalFunctions, ConstantSwitchesLeaveAFormula) {
  // The SOR switch and the cross section type are constant: the formula holds only the branch.
  const auto cyl = internal_function(kAlgbrCyl1);
  auto user = std::make_shared<FnNode>();
  user->kind = FnNode::User;
  user->callee = cyl;
  for (const char v : {'x', 'y', 'z'}) {
    auto n = std::make_shared<FnNode>();
    n->kind = FnNode::Variable;
    n->variable = v;
    user->args.push_back(n);
  }
  for (double p : {1.0, 10.0, 1.0, 0.0, 0.0}) {
    auto n = std::make_shared<FnNode>();
    n->number = p;
    user->args.push_back(n);
  }
  FunctionValue f;
  f.params = {"x", "y", "z"};
  f.body = user;
  const std::string text = formula_text(f, false);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.find("if"), std::string::npos) << text;
}

TEST(PovInternalFunctions, IsosurfaceOfFSphereHasTheSphereSilhouette) {
  FunctionValue f;
  f.params = {"x", "y", "z"};
  auto user = std::make_shared<FnNode>();
  user->kind = FnNode::User;
  user->callee = internal_function(kSphere);
  for (const char v : {'x', 'y', 'z'}) {
    auto n = std::make_shared<FnNode>();
    n->kind = FnNode::Variable;
    n->variable = v;
    user->args.push_back(n);
  }
  auto radius = std::make_shared<FnNode>();
  radius->number = 1;
  user->args.push_back(radius);
  f.body = user;
  const Implicit s = make_implicit(formula_text(f, false), Aabb{{-2, -2, -2}, {2, 2, 2}});
  // Rays along z over a grid: a hit exactly where the line passes within 1 of the centre (lines
  // within 1e-6 of tangent left out), at the analytic t.
  int hits = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double px = -1.5 + 3.0 * i / 40, py = -1.5 + 3.0 * j / 40 + 1e-3;
      const double d2 = px * px + py * py;
      if (std::abs(d2 - 1) < 1e-6) continue;
      const Ray ray{{px, py, -5}, {0, 0, 1}};
      LocalHit hit;
      const bool h = intersect(s, ray, hit);
      ASSERT_EQ(h, d2 < 1) << px << " " << py;
      if (h) {
        ++hits;
        EXPECT_NEAR(hit.t, 5 - std::sqrt(1 - d2), 1e-9);
      }
    }
  EXPECT_GT(hits, 500);
}

}  // namespace
}  // namespace raycast::pov
