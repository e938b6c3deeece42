// Every shape key of the loader's table, alone, under a transform and inside a CSG difference, hit
// with adversarial rays: huge, tiny and subnormal components, -0.0 directions, origins on the
// surface and on the bounds' corners, degenerate and infinite [tmin, tmax]. Each query must finish
// quickly and return finite, in-range t and finite unit normals; spans must be sorted and NaN-free.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"
#include "load/shape_parsers.h"
#include "scene/scene.h"

namespace raycast {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSub = std::numeric_limits<double>::denorm_min();

// One valid parameter set per shape key (flow-style YAML mapping body).
const std::map<std::string, std::string>& examples() {
  static const std::map<std::string, std::string> m = {
      {"plane", "{normal: [0, 1, 0], point: [0, 0, 0]}"},
      {"sphere", "{radius: 1, z_min: -0.5, z_max: 0.8, phi_max: 270}"},
      {"box", "{min: [-1, -2, -3], max: [1, 2, 3]}"},
      {"triangle", "{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}"},
      {"parallelogram", "{origin: [1, 2, 3], u: [1, 0, 0], v: [0, 2, 0]}"},
      {"disk", "{radius: 2, inner_radius: 0.5, height: 1, phi_max: 90}"},
      {"ellipsoid", "{radii: [1, 2, 3]}"},
      {"quadric",
       "{kind: hyperboloid1, a: 0.5, c: 1, bounds: {min: [-2, -2, -1.5], max: [2, 2, 1.5]}}"},
      {"cylinder", "{radius: 1, z_min: 0, z_max: 2, phi_max: 270}"},
      {"cone", "{radius: 1, height: 2}"},
      {"polygon", "{vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.5, 0.2, 0], [0, 1, 0]]}"},
      {"slab", "{normal: [1, 1, 0], offsets: [-1, 1]}"},
      {"polyhedron",
       "{planes: [[1, 0, 0, -1], [-1, 0, 0, -1], [0, 1, 0, -1], [0, -1, 0, -1], [0, 0, 1, -1], "
       "[0, 0, -1, -1]]}"},
      {"torus", "{major_radius: 1, minor_radius: 0.35}"},
      {"algebraic",
       "{equation: \"(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3\", "
       "bounds: {min: [-1.5, -1, -1.5], max: [1.5, 1, 1.5]}}"},
      {"implicit",
       "{function: \"x^2 + y^2 + z^2 - 1 + 0.2*sin(3*x)\", bounds: {min: [-2, -2, -2], max: [2, 2, "
       "2]}}"},
      {"mesh",
       "{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
       "triangles: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]}"},
      {"revolution",
       "{profile: [[0, 0], [0.7, 0], [0.7, 0.1], [0.1, 0.3], [0.1, 1.2], [0.8, 1.6]], curve: "
       "linear}"},
      {"prism",
       "{points: [[0.3, -0.3], [1, 0], [0.3, 0.3], [0, 1], [-0.3, 0.3], [-1, 0], [-0.3, -0.3], "
       "[0, -1], [0.3, -0.3], [1, 0], [0.3, 0.3]], spline: cubic, heights: [0.2, 1.5], sweep: "
       "conic}"},
      {"blob",
       "{threshold: 0.6, components: [{center: [0, 0, 0], radius: 1, strength: 1}, {from: [0.5, "
       "0, 0], to: [1.5, 0.5, 0], radius: 0.6, strength: 1.2}, {center: [0.2, 0.3, 0], radius: "
       "0.4, strength: -0.8, transform: [{scale: [1, 2, 1]}]}]}"},
      {"text", "{font: /usr/share/povray-3.7/include/timrom.ttf, string: 'Bo8', thickness: 0.4}"},
      {"isosurface", "{grid: '" + std::string(RAYCAST_SOURCE_DIR) +
                         "/tests/volume/data/gaussians.raw', iso: 0.5}"},
  };
  return m;
}

struct Variant {
  std::string name;
  std::string yaml;
};

std::vector<Variant> variants(const std::string& key, const std::string& body) {
  const std::string shape = key + ": " + body;
  return {
      {"plain", "objects:\n  - " + shape + "\n"},
      {"transformed",
       "objects:\n  - " + shape +
           "\n    transform: [{scale: [2, 0.5, 1]}, {rotate: {axis: [1, 1, 0], degrees: 33}}, "
           "{translate: [0.5, -1, 2]}]\n"},
      {"difference", "objects:\n  - difference:\n      - " + shape +
                         "\n      - sphere: {center: [0.3, 0.2, 0.1], radius: 0.4}\n"},
  };
}

std::vector<Vec3> directions() {
  std::vector<Vec3> d = {
      {1, 0, 0},          {-1, -0.0, -0.0},   {-0.0, 1, -0.0},
      {0, -1, 0},         {-0.0, -0.0, 1},    {0, 0, -1},
      {1, 1, 1},          {-1, 0.5, -0.25},   {1e300, 1e300, -1e300},
      {1e-300, 0, 0},     {kSub, kSub, kSub}, {1, kSub, -kSub},
      {1e300, 1, 1e-300}, {0.3, -0.7, 0.2},   {1e-160, 1e-160, 0},
  };
  return d;
}

std::vector<Vec3> origins(const Scene& scene) {
  std::vector<Vec3> o = {
      {0, 0, 0},
      {-0.0, -0.0, -0.0},
      {5, 4, 3},
      {-7, 0.5, 0.25},
      {1e300, 1e300, 1e300},
      {-1e300, 0, 0},
      {1e-300, -1e-300, kSub},
      {1e150, -1e150, 3},
      {-1e100, 0.5, 0.25},
      {0, 0, 1},
      {0, 1, 0},
      {1, 0, 0},
      {0, 0, 2},
      {0, 0.1, 1.2},
  };
  const Aabb& b = scene.finite_bounds();
  if (is_finite(b.lo) && is_finite(b.hi)) {
    for (int c = 0; c < 8; ++c)
      o.push_back({c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z});
    o.push_back((b.lo + b.hi) * 0.5);
    o.push_back({b.lo.x, 0.5 * (b.lo.y + b.hi.y), b.hi.z});  // an edge midpoint
  }
  return o;
}

struct Interval {
  double tmin, tmax;
};

const std::vector<Interval>& intervals() {
  static const std::vector<Interval> v = {
      {0, kInf},  {-kInf, kInf},     {0, 0},           {1, 1}, {-kInf, 0}, {1e-300, 1e300},
      {0.5, 0.5}, {-1e300, -1e-300}, {kSub, 2 * kSub},
  };
  return v;
}

std::string describe(const Ray& r) {
  char buf[400];
  std::snprintf(buf, sizeof buf, "o=(%.17g, %.17g, %.17g) d=(%.17g, %.17g, %.17g) t=[%.17g, %.17g]",
                r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, r.tmin, r.tmax);
  return buf;
}

// Per-ray time budget: generous enough for the sanitizer build.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kBudgetSeconds = 10;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kBudgetSeconds = 10;
#else
constexpr double kBudgetSeconds = 1;
#endif
#else
constexpr double kBudgetSeconds = 1;
#endif

void check_ray(const Scene& scene, const Ray& ray) {
  SCOPED_TRACE(describe(ray));
  const auto start = std::chrono::steady_clock::now();

  SceneHit hit;
  const bool found = scene.intersect(ray, hit);
  if (!is_valid(ray)) {
    // Outside the rays' domain (|d|^2 under- or overflows): the scene answers nothing.
    EXPECT_FALSE(found);
    EXPECT_FALSE(scene.occluded(ray));
    std::vector<Crossing> all;
    scene.intersect_all(ray, all);
    EXPECT_TRUE(all.empty());
    return;
  }
  if (found) {
    const double t = hit.local.t;
    EXPECT_TRUE(std::isfinite(t)) << "t = " << t;
    EXPECT_GE(t, ray.tmin);
    EXPECT_LE(t, ray.tmax);
    const SurfaceInfo s = scene.surface(ray, hit);
    EXPECT_TRUE(is_finite(s.n)) << s.n.x << " " << s.n.y << " " << s.n.z;
    EXPECT_NEAR(length(s.n), 1.0, 1e-6);
    EXPECT_TRUE(is_finite(s.shading_n));
    EXPECT_NEAR(length(s.shading_n), 1.0, 1e-6);
    EXPECT_FALSE(std::isnan(s.u) || std::isnan(s.v)) << s.u << " " << s.v;
  }
  const bool blocked = scene.occluded(ray);
  if (found) {
    EXPECT_TRUE(blocked) << "intersect hit at " << hit.local.t << " but occluded says no";
  }

  std::vector<Crossing> all;
  scene.intersect_all(ray, all);
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_FALSE(std::isnan(all[i].t));
    EXPECT_TRUE(std::isfinite(all[i].t)) << all[i].t;
    EXPECT_GE(all[i].t, ray.tmin);
    EXPECT_LE(all[i].t, ray.tmax);
    if (i > 0) {
      EXPECT_LE(all[i - 1].t, all[i].t);
    }
    SceneHit h;
    h.object = all[i].object;
    h.local = all[i].local;
    const SurfaceInfo s = scene.surface(ray, h);
    EXPECT_TRUE(is_finite(s.n)) << "crossing " << i << " at t = " << all[i].t;
  }

  SpanList spans;
  for (const Object& o : scene.objects) {
    spans.clear();
    raycast::spans(o, ray, spans);
    for (std::size_t i = 0; i < spans.size(); ++i) {
      EXPECT_FALSE(std::isnan(spans[i].in.t) || std::isnan(spans[i].out.t));
      EXPECT_LE(spans[i].in.t, spans[i].out.t) << "span " << i;
      if (i > 0) {
        EXPECT_LE(spans[i - 1].out.t, spans[i].in.t) << "span " << i;
      }
    }
  }

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, kBudgetSeconds) << "one ray took " << seconds << " s";
}

void throw_rays(const Scene& scene) {
  std::vector<Vec3> os = origins(scene);
  // Points exactly on the surface: where a few ordinary rays hit it, and the vertices of the
  // bounds.
  for (const Vec3& d : {Vec3{0.3, -0.7, 0.2}, Vec3{-1, -0.1, 0.05}, Vec3{0, 0, -1}}) {
    SceneHit h;
    Ray probe{Vec3{0.11, 3.3, 7.7} - 10.0 * d, d, 0, kInf};
    if (scene.intersect(probe, h)) os.push_back(probe.at(h.local.t));
  }
  for (const Vec3& o : os)
    for (const Vec3& d : directions())
      for (const Interval& iv : intervals()) {
        check_ray(scene, Ray{o, d, iv.tmin, iv.tmax});
        if (::testing::Test::HasFailure()) return;  // one failing ray is enough to report
      }
}

TEST(Robustness, EveryShapeKeyHasAnExample) {
  for (const auto& [key, parser] : shape_parsers()) {
    (void)parser;
    EXPECT_TRUE(examples().count(key)) << "add an example for shape '" << key << "' to examples()";
  }
}

std::vector<std::string> shape_keys() {
  std::vector<std::string> keys;
  for (const auto& entry : shape_parsers()) keys.push_back(entry.first);
  return keys;
}

class AdversarialRays : public ::testing::TestWithParam<std::string> {};

TEST_P(AdversarialRays, FiniteInRangeHitsUnitNormalsSortedSpans) {
  const std::string& key = GetParam();
  const auto it = examples().find(key);
  if (it == examples().end()) GTEST_SKIP() << "no example (reported by EveryShapeKeyHasAnExample)";
  for (const Variant& v : variants(key, it->second)) {
    SCOPED_TRACE(key + " (" + v.name + ")");
    Scene scene;
    try {
      scene = load_scene_text(v.yaml, key + ".yaml");
    } catch (const SceneError& e) {
      // Only open surfaces may be refused as CSG operands.
      EXPECT_EQ(v.name, "difference") << e.what();
      continue;
    }
    throw_rays(scene);
    if (HasFailure()) return;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryShapeKey, AdversarialRays, ::testing::ValuesIn(shape_keys()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace raycast
