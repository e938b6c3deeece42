// All-hits queries on closed solids: along a ray that starts and ends outside, the crossings of
// one solid alternate entry / exit, so there is an even number of them; a tangent touch is two
// crossings or none, never one. Checked for every closed shape kind at scales 1e-6 to 1e6, on
// random rays and on rays grazing the silhouette (found by bisection on the ray's offset).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "load/loader.h"
#include "support/random.h"

namespace raycast {
namespace {

struct Solid {
  const char* name;
  const char* yaml;  // one object entry, in a unit-sized neighbourhood of the origin
};

const Solid kSolids[] = {
    {"sphere", "sphere: {radius: 1}"},
    {"ellipsoid", "ellipsoid: {radii: [1, 0.6, 0.3]}"},
    {"box", "box: {min: [-1, -0.5, -0.25], max: [1, 0.5, 0.25]}"},
    {"cylinder", "cylinder: {from: [0, -1, 0], to: [0, 1, 0], radius: 0.5}"},
    {"cone", "cone: {from: [0, -1, 0], to: [0, 1, 0], radius_from: 0.9, radius_to: 0.3}"},
    {"torus", "torus: {major_radius: 0.8, minor_radius: 0.25}"},
    {"polyhedron",
     "polyhedron: {planes: [[1, 1, 1, -1], [1, 1, -1, -1], [1, -1, 1, -1], [1, -1, -1, -1], "
     "[-1, 1, 1, -1], [-1, 1, -1, -1], [-1, -1, 1, -1], [-1, -1, -1, -1]]}"},
    {"algebraic",
     "algebraic: {equation: \"x^4 + y^4 + z^4 - 1\", "
     "bounds: {min: [-1.5, -1.5, -1.5], max: [1.5, 1.5, 1.5]}}"},
    {"implicit",
     "implicit: {function: \"x^2 + 2*y^2 + z^2 - 1\", "
     "bounds: {min: [-1.5, -1.5, -1.5], max: [1.5, 1.5, 1.5]}}"},
    {"revolution",
     "revolution: {profile: [[0, 0], [0.7, 0], [0.7, 0.1], [0.1, 0.3], [0.1, 1.2], [0.8, 1.6], "
     "[0.9, 2.4], [0, 2.4]], curve: linear}"},
    {"mesh (octahedron)",
     "mesh: {vertices: [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], "
     "triangles: [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], "
     "[0, 3, 5]]}"},
    {"csg difference",
     "difference: [{box: {min: [-1, -1, -1], max: [1, 1, 1]}}, {sphere: {radius: 1.2}}]"},
    {"csg intersection",
     "intersection: [{sphere: {radius: 1}}, {cylinder: {from: [0, -2, 0], to: [0, 2, 0], "
     "radius: 0.7}}]"},
};

const double kScales[] = {1e-6, 1e-3, 1, 1e3, 1e6};

Scene make_scene(const Solid& solid, double scale) {
  std::ostringstream text;  // (string + char* chains trip GCC 12's -Wrestrict false positive)
  text << "objects:\n  - " << solid.yaml << "\n    transform: [{scale: " << scale << "}]\n";
  return load_scene_text(text.str(), solid.name);
}

std::string label(const Solid& solid, double scale, const char* kind, int k) {
  std::ostringstream s;
  s << solid.name << " at scale " << scale << ", " << kind << " ray " << k;
  return s.str();
}

// A ray from well outside the solid along d, offset sideways by h along u.
Ray offset_ray(const Vec3& d, const Vec3& u, double h, double scale) {
  Ray r;
  r.o = u * h - d * (8 * scale);
  r.d = d;
  return r;
}

// Checks the crossing list of one ray; returns false (after reporting) when it is broken.
bool check_alternation(const Scene& scene, const Ray& ray, const std::string& what) {
  std::vector<Crossing> out;
  scene.intersect_all(ray, out);
  for (std::size_t i = 1; i < out.size(); ++i)
    if (!(out[i - 1].t <= out[i].t)) {
      ADD_FAILURE() << what << ": crossings not sorted at " << i;
      return false;
    }
  if (out.size() % 2 != 0) {
    std::ostringstream ts;
    for (const Crossing& c : out) ts << " " << c.t;
    ADD_FAILURE() << what << ": " << out.size() << " crossings (odd) at t =" << ts.str();
    return false;
  }
  // Between crossings wider apart than the surface's own uncertainty, inside alternates.
  const Object& o = scene.objects[0];
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    const double a = out[i].t, b = out[i + 1].t;
    if (b - a <= 1e-6 * std::max(std::abs(a), std::abs(b))) continue;
    const bool inside = contains(o, ray.at(0.5 * (a + b)));
    if (inside != (i % 2 == 0)) {
      ADD_FAILURE() << what << ": between crossings " << i << " and " << i + 1 << " (t " << a
                    << " .. " << b << ") the midpoint is " << (inside ? "inside" : "outside");
      return false;
    }
  }
  return true;
}

TEST(AllHits, ClosedSolidsOnRandomRays_CrossingsAlternate) {
  for (const Solid& solid : kSolids) {
    for (const double scale : kScales) {
      const Scene scene = make_scene(solid, scale);
      testing::Rng rng(7);
      std::uniform_real_distribution<double> offset(-1.5 * scale, 1.5 * scale);
      int failures = 0;
      for (int k = 0; k < 200 && failures < 3; ++k) {
        const Vec3 d = rng.direction();
        const Vec3 u = normalize(cross(d, rng.direction()));
        const std::string what = label(solid, scale, "random", k);
        if (!check_alternation(scene, offset_ray(d, u, offset(rng), scale), what)) ++failures;
      }
    }
  }
}

TEST(AllHits, ClosedSolidsOnGrazingRays_TangentTouchIsTwoCrossingsOrNone) {
  for (const Solid& solid : kSolids) {
    for (const double scale : kScales) {
      const Scene scene = make_scene(solid, scale);
      testing::Rng rng(11);
      int failures = 0;
      for (int k = 0; k < 30 && failures < 3; ++k) {
        const Vec3 d = rng.direction();
        const Vec3 u = normalize(cross(d, rng.direction()));
        // Bisect the offset between a hitting ray (through the centre, if it hits) and a
        // missing one (far off) down to the silhouette.
        SceneHit hit;
        double lo = 0, hi = 4 * scale;
        if (!scene.intersect(offset_ray(d, u, lo, scale), hit)) continue;
        for (int step = 0; step < 64; ++step) {
          const double mid = 0.5 * (lo + hi);
          (scene.intersect(offset_ray(d, u, mid, scale), hit) ? lo : hi) = mid;
        }
        for (const double h : {lo, hi, lo * (1 - 1e-12), hi * (1 + 1e-12), lo * (1 - 1e-7)}) {
          const std::string what = label(solid, scale, "grazing", k);
          if (!check_alternation(scene, offset_ray(d, u, h, scale), what)) ++failures;
        }
      }
    }
  }
}

TEST(AllHits, ExactTangentRays_GiveTwoCrossingsOrNone) {
  struct Case {
    const char* yaml;
    Vec3 o, d;
  };
  const Case cases[] = {
      {"sphere: {radius: 1}", {1, 0, -5}, {0, 0, 1}},
      {"sphere: {radius: 2, center: [1, 1, 1]}", {-5, 3, 1}, {1, 0, 0}},
      {"ellipsoid: {radii: [2, 1, 1]}", {2, 0, -5}, {0, 0, 1}},
      {"cylinder: {from: [0, -1, 0], to: [0, 1, 0], radius: 1}", {1, 0, -5}, {0, 0, 1}},
      {"torus: {major_radius: 1, minor_radius: 0.25}", {1.25, 0, -5}, {0, 0, 1}},
  };
  for (const Case& c : cases) {
    const Scene scene = load_scene_text(std::string("objects:\n  - ") + c.yaml + "\n", c.yaml);
    Ray ray;
    ray.o = c.o;
    ray.d = c.d;
    check_alternation(scene, ray, c.yaml);
  }
}

}  // namespace
}  // namespace raycast
