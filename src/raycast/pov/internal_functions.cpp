#include "pov/internal_functions.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pov/fn_builder.h"
#include "texture/noise.h"

namespace raycast::pov {

// A named namespace, not an anonymous one: in a unity build the using-directive would otherwise
// reach the other files of the batch.
namespace internal_definitions {

using namespace fn;  // NOLINT: the definitions below read as equations

const Fn x = param(0), y = param(1), z = param(2);
Fn P(int i) { return param(3 + i); }
const Fn r2_xz = x * x + z * z;         // squared distance from the y axis
const Fn rho2 = x * x + y * y + z * z;  // squared distance from the origin
constexpr double kDegree = std::numbers::pi / 180;

// Most of the classic surfaces take a field strength P0 that scales the equation F (written
// negative inside): POV-Ray's value is -P0 F, so the documented examples, which pass a negative
// strength, get the solid inside the surface.
Fn strength(const Fn& f) { return -P(0) * f; }

// A 2-d curve g(u, v) made a surface (functions.inc's "SOR switch", "SOR offset", "SOR angle"
// parameters, the extra parameters sw, sw + 1, sw + 2): with the switch > 0 the curve, shifted by
// the offset along u and turned by the angle (degrees) about the z axis, is revolved about the y
// axis; else it is extruded along z.
template <class G>
Fn curve_surface(const G& g, int sw) {
  const Fn a = P(sw + 2) * kDegree;
  const Fn u = sqrt(r2_xz) - P(sw + 1);
  const Fn ur = u * cos(a) + y * sin(a), vr = y * cos(a) - u * sin(a);
  return if_positive(P(sw), g(ur, vr), g(x, y));
}

// The size of (u, v) for a cross section type t (functions.inc's "Cross section type"): the
// p-norm with p = 2 / t: t = 0 a square (the largest coordinate), 1 a circle, 2 a diamond, 3 a
// concave diamond, rounded squares and diamonds between.
Fn section(const Fn& u, const Fn& v, const Fn& t) {
  const Fn p = 2.0 / t;
  return if_positive(t, pow(pow(abs(u), p) + pow(abs(v), p), 1.0 / p), max(abs(u), abs(v)));
}

// A tube of radius `minor` wound `n` times about the y axis at radius `major`, turning `period`
// radians per unit of y; the cross section (type t, turned by `angle` degrees, stretched by
// `shape` along the helix's axis) is measured across the tube: the offset from the nearest turn
// along y, times the cosine of the helix's slope.
Fn helix(const Fn& n, const Fn& period, const Fn& minor, const Fn& major, const Fn& shape,
         const Fn& t, const Fn& angle) {
  const double two_pi = 2 * std::numbers::pi;
  const Fn phase = atan2(z, x) - period * y;
  const Fn step = two_pi / n;
  const Fn off = phase - step * floor(phase / step + 0.5);  // to the nearest turn, in radians
  const Fn u = sqrt(r2_xz) - major;
  const Fn w = off * major / sqrt(1.0 + sqr(major * period)) / shape;
  const Fn a = angle * kDegree;
  return section(u * cos(a) + w * sin(a), w * cos(a) - u * sin(a), t) - minor;
}

struct Definition {
  InternalFunctionInfo info;
  Fn (*body)();
};

// The definitions, by functions.inc's numbers. Curves and surfaces from the classic literature
// (MathWorld's and Mathcurve's equations), each surface about the y axis where it has one, except
// where POV-Ray's own example (incdemo/i_internal.pov) shows it otherwise.
const Definition kDefinitions[] = {
    {{0, "f_algbr_cyl1", 5},  // a figure of eight: the lemniscate of Gerono, u^4 - u^2 + v^2 = 0
     [] {
       return min(P(0) * curve_surface([](Fn u, Fn v) { return sqr(sqr(u)) - sqr(u) + sqr(v); }, 2),
                  P(1));
     }},
    {{1, "f_algbr_cyl2", 5},  // a cross: the cruciform u^2 v^2 = (u^2 + v^2) / 4
     [] {
       return min(
           P(0) * curve_surface(
                      [](Fn u, Fn v) { return (sqr(u) + sqr(v)) * 0.25 - sqr(u) * sqr(v); }, 2),
           P(1));
     }},
    {{2, "f_algbr_cyl3", 5},  // the trifolium (u^2 + v^2)^2 = u^3 - 3 u v^2
     [] {
       return min(
           P(0) * curve_surface(
                      [](Fn u, Fn v) { return u * (sqr(u) - 3.0 * sqr(v)) - sqr(sqr(u) + sqr(v)); },
                      2),
           P(1));
     }},
    {{3, "f_algbr_cyl4", 5},  // the quadrifolium (u^2 + v^2)^3 = 4 u^2 v^2
     [] {
       return min(P(0) * curve_surface(
                             [](Fn u, Fn v) {
                               const Fn s = sqr(u) + sqr(v);
                               return 4.0 * sqr(u) * sqr(v) - s * s * s;
                             },
                             2),
                  P(1));
     }},
    {{4, "f_bicorn", 2},  // the bicorn (r^2 + 2 a y - a^2)^2 = y^2 (a^2 - r^2), revolved
     [] {
       const Fn a = P(1);
       return strength(sqr(r2_xz + 2.0 * a * y - a * a) - sqr(y) * (a * a - r2_xz));
     }},
    {{5, "f_bifolia", 2},  // the bifolium (r^2 + y^2)^2 = a r^2 y, revolved
     [] { return strength(sqr(rho2) - P(1) * r2_xz * y); }},
    {{6, "f_blob", 5},  // two blob components P0 apart on x, centred on the origin: strength s and
                        // inverse radius k, field
                        // s (1 - (k r)^2)^2 within r < 1 / k; the value is minus their sum
     [] {
       const Fn r1 = sqr(x + 0.5 * P(0)) + y * y + z * z, r2 = sqr(x - 0.5 * P(0)) + y * y + z * z;
       return -(P(1) * sqr(max(1.0 - sqr(P(2)) * r1, 0.0)) +
                P(3) * sqr(max(1.0 - sqr(P(4)) * r2, 0.0)));
     }},
    {{7, "f_blob2", 4},  // two equal components P0 apart on x, fields s e^-(k r^2); P3 is a
                         // threshold
     [] {
       const Fn r1 = rho2, r2 = sqr(x - P(0)) + y * y + z * z;
       return P(3) - P(2) * (exp(-P(1) * r1) + exp(-P(1) * r2));
     }},
    {{8, "f_boy_surface", 2},  // Boy's surface, the sextic of its Apery-Morin form, axis y
     [] {
       const Fn X = x * P(1), Y = z * P(1), Z = y * P(1);
       const Fn s2 = std::numbers::sqrt2;
       const Fn q = sqr(X) + sqr(Y), w = 1.0 - Z;
       const Fn f = 64.0 * w * w * w * Z * Z * Z - 48.0 * w * w * Z * Z * (3.0 * q + 2.0 * Z * Z) +
                    12.0 * w * Z *
                        (27.0 * q * q - 24.0 * Z * Z * q +
                         36.0 * s2 * Y * Z * (Y * Y - 3.0 * X * X) + 4.0 * sqr(sqr(Z))) +
                    (9.0 * q - 2.0 * Z * Z) *
                        (-81.0 * q * q - 72.0 * Z * Z * q +
                         108.0 * s2 * X * Z * (X * X - 3.0 * Y * Y) + 4.0 * sqr(sqr(Z)));
       return strength(f);
     }},
    {{11, "f_crossed_trough", 1},  // z = x^2 y^2 (upright along z, as POV-Ray's examples show it)
     [] { return strength(sqr(x) * sqr(y) - z); }},
    {{12, "f_cubic_saddle", 1},  // the monkey saddle y = x^3 - 3 x z^2
     [] { return strength(x * x * x - 3.0 * x * z * z - y); }},
    {{14, "f_devils_curve", 1},  // the devil's curve revolved: x^4 + 2 x^2 z^2 - 0.36 x^2 - y^4
                                 // + 0.25 y^2 + z^4 = 0
     [] {
       return strength(sqr(sqr(x)) + 2.0 * sqr(x) * sqr(z) - 0.36 * sqr(x) - sqr(sqr(y)) +
                       0.25 * sqr(y) + sqr(sqr(z)));
     }},
    {{15, "f_devils_curve_2d", 6},  // u^2 (u^2 - a) = v^2 (v^2 - b), a and b the x and y factors
     [] {
       return strength(curve_surface(
           [](Fn u, Fn v) { return sqr(u) * (sqr(u) - P(1)) - sqr(v) * (sqr(v) - P(2)); }, 3));
     }},
    {{16, "f_dupin_cyclid", 6},  // a torus (R, r, moved by (P3, P4)) inverted in the sphere P5
     [] {
       const Fn k = sqr(P(5)) / rho2;
       const Fn X = x * k - P(3), Y = y * k - P(4), Z = z * k;
       const Fn R = P(1), r = P(2);
       return strength(sqr(sqr(X) + sqr(Y) + sqr(Z) + R * R - r * r) -
                       4.0 * R * R * (sqr(X) + sqr(Z)));
     }},
    {{17, "f_ellipsoid", 3},  // |(P0 x, P1 y, P2 z)|: 1 on the ellipsoid of semi-axes 1 / Pi
     [] { return sqrt(sqr(P(0) * x) + sqr(P(1) * y) + sqr(P(2) * z)); }},
    {{23, "f_heart", 1},  // Taubin's heart (9/4 x^2 + y^2 + z^2 - 1)^3 = y^2 z^3 + 9/80 x^2 z^3:
                          // lobes towards +z, thin along x
     [] {
       const Fn s = 2.25 * sqr(x) + sqr(y) + sqr(z) - 1.0;
       return strength(s * s * s - sqr(y) * z * z * z - 0.1125 * sqr(x) * z * z * z);
     }},
    {{25, "f_helix1", 7}, [] { return helix(P(0), P(1), P(2), P(3), P(4), P(5), P(6)); }},
    {{26, "f_helix2", 7},  // one strand, round along the axis (P0 and P4 unused)
     [] { return helix(1.0, P(1), P(2), P(3), 1.0, P(5), P(6)); }},
    {{30, "f_hunt_surface", 1},  // 4 (x^2 + y^2 + z^2 - 13)^3 + 27 (3 x^2 + y^2 - 4 z^2 - 12)^2
     [] {
       const Fn s = rho2 - 13.0;
       return strength(4.0 * s * s * s + 27.0 * sqr(3.0 * sqr(x) + sqr(y) - 4.0 * sqr(z) - 12.0));
     }},
    {{31, "f_hyperbolic_torus", 3},  // (x^2 - y^2 + z^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2)
     [] {
       const Fn R = P(1), r = P(2);
       return strength(sqr(r2_xz - sqr(y) + R * R - r * r) - 4.0 * R * R * r2_xz);
     }},
    {{35, "f_klein_bottle", 1},  // the Klein bottle's implicit sextic
     [] {
       const Fn a = rho2 + 2.0 * y - 1.0, b = rho2 - 2.0 * y - 1.0;
       return strength(a * (sqr(b) - 8.0 * sqr(z)) + 16.0 * x * z * b);
     }},
    {{38, "f_lemniscate_of_gerono", 1},  // x^4 - x^2 + y^2 + z^2 = 0, about the x axis
     [] { return strength(sqr(sqr(x)) - sqr(x) + sqr(y) + sqr(z)); }},
    {{39, "f_lemniscate_of_gerono_2d", 6},  // (u / a)^4 - (u / a)^2 + (v / b)^2, a size, b width
     [] {
       return strength(curve_surface(
           [](Fn u, Fn v) {
             const Fn s = u / P(1);
             return sqr(sqr(s)) - sqr(s) + sqr(v / P(2));
           },
           3));
     }},
    {{41, "f_mitre", 1},  // 4 x^2 (x^2 + y^2 + z^2) = y^2 (1 - y^2 - z^2)
     [] { return strength(4.0 * sqr(x) * rho2 - sqr(y) * (1.0 - sqr(y) - sqr(z))); }},
    {{42, "f_nodal_cubic", 1},  // Cayley's nodal cubic 4 (x^2 + y^2 + z^2) + 16 x y z = 1
     [] { return strength(4.0 * rho2 + 16.0 * x * y * z - 1.0); }},
    {{45, "f_paraboloid", 1},  // y = x^2 + z^2
     [] { return strength(r2_xz - y); }},
    {{47, "f_ph", 0},  // the angle from the +y axis, 0 to pi
     [] { return atan2(sqrt(r2_xz), y); }},
    {{49, "f_piriform", 1},  // the pear x^4 - x^3 + y^2 + z^2 = 0, between x = 0 and 1
     [] { return P(0) * (sqr(sqr(x)) - x * x * x + sqr(y) + sqr(z)); }},
    {{50, "f_piriform_2d", 7},  // a u^4 + b u^3 + c v^2, a and b the size factors, c fatness
     [] {
       return strength(curve_surface(
           [](Fn u, Fn v) { return P(1) * sqr(sqr(u)) + P(2) * u * u * u + P(3) * sqr(v); }, 4));
     }},
    {{51, "f_poly4", 5},  // a lathe: the distance from the y axis against a quartic in y
     [] { return sqrt(r2_xz) - (P(0) + y * (P(1) + y * (P(2) + y * (P(3) + y * P(4))))); }},
    {{54, "f_quartic_paraboloid", 1},  // y = x^4 + z^4
     [] { return strength(sqr(sqr(x)) + sqr(sqr(z)) - y); }},
    {{55, "f_quartic_saddle", 1},  // y = x^4 - z^4
     [] { return strength(sqr(sqr(x)) - sqr(sqr(z)) - y); }},
    {{57, "f_r", 0},  // the distance from the origin
     [] { return sqrt(rho2); }},
    {{60, "f_rounded_box", 4},  // the box of half sizes P1, P2, P3 with edges of radius P0
     [] {
       const Fn r = P(0);
       const Fn qx = abs(x) - P(1) + r, qy = abs(y) - P(2) + r, qz = abs(z) - P(3) + r;
       const Fn outside = sqrt(sqr(max(qx, 0.0)) + sqr(max(qy, 0.0)) + sqr(max(qz, 0.0)));
       return outside + min(max(qx, max(qy, qz)), 0.0) - r;
     }},
    {{61, "f_sphere", 1},  // the distance from the sphere of radius P0 at the origin
     [] { return sqrt(rho2) - P(0); }},
    {{59, "f_ridged_mf", 6},  // H, lacunarity, octaves, offset, gain, noise generator
     [] {
       return fn::call("ridged_mf", {x, y, z, P(0), P(1), P(2), P(3), P(4), P(5)});
     }},
    {{64, "f_spiral", 6},  // a tube wound as a flat spiral about y, P0 apart, radius P1, out to
                           // P2 from the centre (the documented "diameter" acts so in its examples)
     [] {
       const double two_pi = 2 * std::numbers::pi;
       const Fn d = sqrt(r2_xz) - P(0) * atan2(z, x) / two_pi;
       const Fn u = d - P(0) * floor(d / P(0) + 0.5);
       return max(section(u, y, P(5)) - P(1), sqrt(rho2) - P(2));
     }},
    {{65, "f_steiners_roman", 1},  // x^2 y^2 + y^2 z^2 + z^2 x^2 + x y z = 0
     [] { return strength(sqr(x) * sqr(y) + sqr(y) * sqr(z) + sqr(z) * sqr(x) + x * y * z); }},
    {{68, "f_superellipsoid", 2},  // 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n)): positive
                                   // inside, e = P0 (east-west), n = P1 (north-south)
     [] {
       const Fn e = P(0), n = P(1);
       return 1.0 -
              (pow(pow(abs(x), 2.0 / e) + pow(abs(y), 2.0 / e), e / n) + pow(abs(z), 2.0 / n));
     }},
    {{69, "f_th", 0},  // the angle about the y axis from +z towards +x
     [] { return atan2(x, z); }},
    {{70, "f_torus", 2},  // the distance from the torus about y, major radius P0, minor P1
     [] { return sqrt(sqr(sqrt(r2_xz) - P(0)) + sqr(y)) - P(1); }},
    {{71, "f_torus2", 3},  // (x^2 + y^2 + z^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2)
     [] {
       const Fn R = P(1), r = P(2);
       return strength(sqr(rho2 + R * R - r * r) - 4.0 * R * R * r2_xz);
     }},
    {{72, "f_torus_gumdrop", 1},  // 4 (x^4 + (y^2 + z^2)^2) + 17 x^2 (y^2 + z^2) - 20 (x^2 + y^2
                                  // + z^2) + 17 = 0
     [] {
       const Fn q = sqr(y) + sqr(z);
       return strength(4.0 * (sqr(sqr(x)) + sqr(q)) + 17.0 * sqr(x) * q - 20.0 * rho2 + 17.0);
     }},
    {{73, "f_umbrella", 1},  // Whitney's umbrella x^2 = y z^2
     [] { return strength(sqr(x) - y * sqr(z)); }},
    {{74, "f_witch_of_agnesi", 2},  // y = a / (x^2 + z^2 + a): height 1, width a
     [] { return strength(y * (r2_xz + P(1)) - P(1)); }},
    {{75, "f_witch_of_agnesi_2d", 6},  // v (u^2 + a) = b, a the width, b the height
     [] {
       return strength(curve_surface([](Fn u, Fn v) { return v * (sqr(u) + P(1)) - P(2); }, 3));
     }},
    {{76, "f_noise3d", 0},  // solid noise in [0, 1] (noise_generator 2, POV-Ray's default)
     [] {
       return fn::call("noise3d", {x, y, z, 2.0});
     }},
    {{78, "f_noise_generator", 1},  // solid noise of generator P0
     [] {
       return fn::call("noise3d", {x, y, z, P(0)});
     }},
};

}  // namespace internal_definitions

namespace {
// Octaves are bounded as POV-Ray's turbulence bounds them, so that a formula stays small.
int octave_count(double v) { return std::clamp(static_cast<int>(v), 1, 10); }
}  // namespace

double ridged_mf(const double a[9]) {
  const double H = a[3], lacunarity = a[4], offset = a[6], gain = a[7];
  const int generator = static_cast<int>(a[8]);
  double f = 1, result = 0, weight = 1;
  for (int i = 0; i < octave_count(a[5]); ++i) {
    const double n = 2 * texture::noise({a[0] * f, a[1] * f, a[2] * f}, generator) - 1;
    const double signal = (offset - std::abs(n)) * (offset - std::abs(n)) * weight;
    result += signal * std::pow(f, -H);
    weight = std::clamp(signal * gain, 0.0, 1.0);
    f *= lacunarity;
  }
  return result;
}

std::shared_ptr<const FnNode> ridged_mf_tree(std::shared_ptr<const FnNode> x,
                                             std::shared_ptr<const FnNode> y,
                                             std::shared_ptr<const FnNode> z, const double a[9]) {
  using namespace fn;  // NOLINT: the equation
  const Fn X(std::move(x)), Y(std::move(y)), Z(std::move(z));
  const double H = a[3], lacunarity = a[4], offset = a[6], gain = a[7], generator = a[8];
  double f = 1;
  Fn result = 0.0, weight = 1.0;
  for (int i = 0; i < octave_count(a[5]); ++i) {
    const Fn n = 2.0 * fn::call("noise3d", {X * f, Y * f, Z * f, generator}) - 1.0;
    const Fn signal = sqr(offset - abs(n)) * weight;
    result = result + signal * std::pow(f, -H);
    weight = min(max(signal * gain, 0.0), 1.0);
    f *= lacunarity;
  }
  return result.node;
}

using internal_definitions::Definition;
using internal_definitions::kDefinitions;

std::span<const InternalFunctionInfo> internal_function_table() {
  static const std::vector<InternalFunctionInfo> table = [] {
    std::vector<InternalFunctionInfo> t;
    for (const Definition& d : kDefinitions) t.push_back(d.info);
    return t;
  }();
  return table;
}

std::shared_ptr<const FunctionValue> internal_function(int number) {
  for (const Definition& d : kDefinitions) {
    if (d.info.number != number) continue;
    auto f = std::make_shared<FunctionValue>();
    f->params = {"x", "y", "z"};
    // (Names from a table: GCC 12 reports a false -Wrestrict on "P" + to_string in a unity
    // batch, GCC bug 105329.)
    static const char* const kNames[] = {"P0", "P1", "P2", "P3", "P4",
                                         "P5", "P6", "P7", "P8", "P9"};
    for (int i = 0; i < d.info.extra && i < 10; ++i) f->params.push_back(kNames[i]);
    f->body = d.body().node;
    return f;
  }
  return nullptr;
}

}  // namespace raycast::pov
