// CSG over the real closed shapes (box, capped cylinder, cone, torus) and closed triangle meshes:
// spans, hits and normals against inside(p) oracles along random rays (csg_oracle.h), the seed's
// cube minus sphere with a real `box`, three orthogonal capped cylinders, and open meshes rejected
// with a positioned error.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "csg_oracle.h"
#include "io/scene_error.h"

namespace raycast {
namespace {

using csg_test::check_random_rays;
using csg_test::Oracle;
using csg_test::scene_of;

bool in_ball(const Vec3& p, const Vec3& c, double r) { return length_squared(p - c) <= r * r; }
bool in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
}
// A capped cylinder of radius r along `axis` (0, 1, 2) through the origin, |axial| <= h.
bool in_rod(const Vec3& p, int axis, double r, double h) {
  const double a = p[(axis + 1) % 3], b = p[(axis + 2) % 3];
  return a * a + b * b <= r * r && std::abs(p[axis]) <= h;
}
bool in_torus(const Vec3& p, double big, double small) {
  const double s = length_squared(p) + big * big - small * small;
  return s * s - 4 * big * big * (p.x * p.x + p.y * p.y) <= 0;
}

// A triangle mesh as YAML with float-exact coordinates, and the same float vertices as doubles
// for the oracle.
struct MeshData {
  std::vector<Vec3> v;  // float-representable
  std::vector<std::array<int, 3>> f;
};

std::string mesh_yaml(const MeshData& m, const std::string& indent) {
  std::string s = indent + "- mesh:\n" + indent + "    vertices: [";
  char buf[96];
  for (std::size_t i = 0; i < m.v.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s[%.9g, %.9g, %.9g]", i ? ", " : "", m.v[i].x, m.v[i].y,
                  m.v[i].z);
    s += buf;
  }
  s += "]\n" + indent + "    triangles: [";
  for (std::size_t i = 0; i < m.f.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s[%d, %d, %d]", i ? ", " : "", m.f[i][0], m.f[i][1],
                  m.f[i][2]);
    s += buf;
  }
  return s + "]\n";
}

// The cube [-h, h]^3 as 12 triangles, counter-clockwise seen from outside (or reversed).
MeshData cube_mesh(double h, bool reversed = false) {
  MeshData m;
  for (int i = 0; i < 8; ++i) m.v.push_back({i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.f.push_back({q[0], q[1], q[2]});
    m.f.push_back({q[0], q[2], q[3]});
  }
  if (reversed)
    for (auto& t : m.f) std::swap(t[1], t[2]);
  return m;
}

// An icosahedron subdivided `levels` times, vertices on the sphere of radius r (rounded to float).
MeshData icosphere(double r, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-g, g}) {
      v.push_back({0, a, b});
      v.push_back({a, b, 0});
      v.push_back({b, 0, a});
    }
  std::vector<std::array<int, 3>> f;
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        auto edge = [&](int a, int b) { return std::abs(length(v[a] - v[b]) - 2) < 1e-9; };
        if (!edge(i, j) || !edge(j, k) || !edge(i, k)) continue;
        const bool out = dot(cross(v[j] - v[i], v[k] - v[i]), v[i] + v[j] + v[k]) > 0;
        f.push_back(out ? std::array<int, 3>{i, j, k} : std::array<int, 3>{i, k, j});
      }
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(normalize(v[a] + v[b]) * length(v[a]));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : f) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  MeshData m;
  for (const Vec3& p : v) {
    const Vec3 q = normalize(p) * r;
    m.v.push_back({static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)});
  }
  m.f = f;
  return m;
}

// Inside a convex mesh: behind the plane of every face (an oracle independent of the mesh code).
Oracle convex_inside(const MeshData& m) {
  return [m](const Vec3& p) {
    for (const auto& t : m.f) {
      const Vec3 n = cross(m.v[t[1]] - m.v[t[0]], m.v[t[2]] - m.v[t[0]]);
      if (dot(n, p - m.v[t[0]]) > 0) return false;
    }
    return true;
  };
}

struct Case {
  const char* name;
  std::string yaml;  // one entry of `objects`
  Oracle inside;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"BoxMinusSphere_Seed000",
               "- difference:\n    - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
               "    - sphere: {radius: 1.3}\n",
               [](const Vec3& p) {
                 return in_box(p, {-1, -1, -1}, {1, 1, 1}) && !in_ball(p, {}, 1.3);
               }});
  c.push_back({"ThreeOrthogonalCappedCylinders",
               "- intersection:\n"
               "    - cylinder: {radius: 1, z_min: -1.2, z_max: 1.2}\n"
               "    - cylinder: {from: [-1.2, 0, 0], to: [1.2, 0, 0], radius: 1}\n"
               "    - cylinder: {radius: 1, z_min: -1.2, z_max: 1.2}\n"
               "      transform: [{rotate: {axis: [1, 0, 0], degrees: 90}}]\n",
               [](const Vec3& p) {
                 return in_rod(p, 2, 1, 1.2) && in_rod(p, 0, 1, 1.2) && in_rod(p, 1, 1, 1.2);
               }});
  c.push_back({"BoxMinusThreeCylinders",
               "- difference:\n    - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
               "    - cylinder: {radius: 0.5, z_min: -2, z_max: 2}\n"
               "    - cylinder: {from: [-2, 0, 0], to: [2, 0, 0], radius: 0.5}\n"
               "    - cylinder: {from: [0, -2, 0], to: [0, 2, 0], radius: 0.5}\n",
               [](const Vec3& p) {
                 return in_box(p, {-1, -1, -1}, {1, 1, 1}) && !in_rod(p, 0, 0.5, 2) &&
                        !in_rod(p, 1, 0.5, 2) && !in_rod(p, 2, 0.5, 2);
               }});
  c.push_back({"ConeMinusBox",
               "- difference:\n    - cone: {radius: 1.2, height: 2.4}\n"
               "      transform: [{translate: [0, 0, -1.2]}]\n"
               "    - box: {min: [0, 0, -2], max: [2, 2, 2]}\n",
               [](const Vec3& p) {
                 const double z = p.z + 1.2, r = 1.2 * (1 - z / 2.4);
                 const bool cone = z >= 0 && z <= 2.4 && p.x * p.x + p.y * p.y <= r * r;
                 return cone && !in_box(p, {0, 0, -2}, {2, 2, 2});
               }});
  c.push_back({"FrustumIntersectSphere",
               "- intersection:\n"
               "    - cone: {from: [0, -1.2, 0], to: [0, 1.2, 0], radius_from: 1.2, radius_to: "
               "0.4}\n"
               "    - sphere: {radius: 1.25}\n",
               [](const Vec3& p) {
                 const double r = 1.2 + (p.y + 1.2) / 2.4 * (0.4 - 1.2);
                 return std::abs(p.y) <= 1.2 && p.x * p.x + p.z * p.z <= r * r &&
                        in_ball(p, {}, 1.25);
               }});
  c.push_back({"TorusUnionCylinder",
               "- union:\n    - torus: {major_radius: 1, minor_radius: 0.35}\n"
               "    - cylinder: {from: [-1.4, 0, 0], to: [1.4, 0, 0], radius: 0.25}\n",
               [](const Vec3& p) { return in_torus(p, 1, 0.35) || in_rod(p, 0, 0.25, 1.4); }});
  c.push_back({"BoxMinusTorus",
               "- difference:\n    - box: {min: [-1.5, -1.5, -0.2], max: [1.5, 1.5, 0.2]}\n"
               "    - torus: {major_radius: 1, minor_radius: 0.35}\n",
               [](const Vec3& p) {
                 return in_box(p, {-1.5, -1.5, -0.2}, {1.5, 1.5, 0.2}) && !in_torus(p, 1, 0.35);
               }});
  // Closed meshes: the seed's cube as 12 triangles, the same cube wound inside out (a solid with
  // inward normals: in CSG its reported normals must still point out of the result), an
  // icosphere.
  const MeshData cube = cube_mesh(1);
  const Oracle cube_in = convex_inside(cube);
  c.push_back({"CubeMeshMinusSphere",
               "- difference:\n" + mesh_yaml(cube, "    ") + "    - sphere: {radius: 1.3}\n",
               [cube_in](const Vec3& p) { return cube_in(p) && !in_ball(p, {}, 1.3); }});
  c.push_back(
      {"InsideOutCubeMeshMinusSphere",
       "- difference:\n" + mesh_yaml(cube_mesh(1, true), "    ") + "    - sphere: {radius: 1.3}\n",
       [cube_in](const Vec3& p) { return cube_in(p) && !in_ball(p, {}, 1.3); }});
  c.push_back({"SphereMinusCubeMesh",
               "- difference:\n    - sphere: {radius: 1.3}\n" + mesh_yaml(cube, "    "),
               [cube_in](const Vec3& p) { return in_ball(p, {}, 1.3) && !cube_in(p); }});
  const MeshData ico = icosphere(1.3, 2);
  const Oracle ico_in = convex_inside(ico);
  c.push_back({"IcosphereMinusBoxAndCylinder",
               "- difference:\n" + mesh_yaml(ico, "    ") +
                   "    - box: {min: [0, 0, -2], max: [2, 2, 2]}\n"
                   "    - cylinder: {radius: 0.4, z_min: -2, z_max: 2}\n",
               [ico_in](const Vec3& p) {
                 return ico_in(p) && !in_box(p, {0, 0, -2}, {2, 2, 2}) && !in_rod(p, 2, 0.4, 2);
               }});
  // Two overlapping closed components in one mesh: their union (nonzero winding).
  MeshData two = cube_mesh(0.8);
  for (int i = 0; i < 8; ++i) two.v.push_back(two.v[i] + Vec3{0.6, 0.5, 0.4});
  for (int i = 0; i < 12; ++i) two.f.push_back({two.f[i][0] + 8, two.f[i][1] + 8, two.f[i][2] + 8});
  c.push_back({"OverlappingMeshComponentsIntersectSphere",
               "- intersection:\n" + mesh_yaml(two, "    ") + "    - sphere: {radius: 1.5}\n",
               [](const Vec3& p) {
                 const Vec3 h{0.8, 0.8, 0.8}, s{0.6, 0.5, 0.4};
                 return (in_box(p, -h, h) || in_box(p, s - h, s + h)) && in_ball(p, {}, 1.5);
               }});
  return c;
}

TEST(CsgShapes, RandomRays_SpansHitsAndNormalsAgreeWithOracle) {
  unsigned seed = 4321;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const Scene scene = scene_of(c.yaml);
    ASSERT_EQ(scene.objects.size(), 1u);
    check_random_rays(scene.objects[0], c.inside, seed++, 300, 1.6);
    if (HasFailure()) return;
  }
}

TEST(CsgShapes, BoxMinusSphere_HandComputedHits) {
  for (const std::string& cube : {std::string("    - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"),
                                  mesh_yaml(cube_mesh(1), "    ")}) {
    SCOPED_TRACE(cube);
    const Scene scene = scene_of("- difference:\n" + cube + "    - sphere: {radius: 1.3}\n");
    SceneHit hit;
    const Ray corner{{0.9, 0.9, -5}, {0, 0, 1}};
    ASSERT_TRUE(scene.intersect(corner, hit));
    EXPECT_EQ(hit.local.t, 4);
    EXPECT_EQ(scene.surface(corner, hit).n.z, -1);
    const Ray inside{{0.9, 0.9, -0.5}, {0, 0, 1}};
    ASSERT_TRUE(scene.intersect(inside, hit));
    const double z = -std::sqrt(1.69 - 1.62);
    EXPECT_NEAR(hit.local.t, z + 0.5, 1e-15);
    const Vec3 n = scene.surface(inside, hit).n, expected = -Vec3{0.9, 0.9, z} / 1.3;
    EXPECT_NEAR(n.x, expected.x, 1e-12);
    EXPECT_NEAR(n.y, expected.y, 1e-12);
    EXPECT_NEAR(n.z, expected.z, 1e-12);
    EXPECT_FALSE(scene.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, hit));
    std::vector<Crossing> all;
    scene.intersect_all(corner, all);
    ASSERT_EQ(all.size(), 4u);
    EXPECT_EQ(all[0].t, 4);
    EXPECT_NEAR(all[1].t, 5 + z, 1e-15);
    EXPECT_NEAR(all[2].t, 5 - z, 1e-15);
    EXPECT_EQ(all[3].t, 6);
  }
}

TEST(CsgShapes, ThreeCylinders_HandComputedHits) {
  const Scene scene = scene_of(
      "- intersection:\n"
      "    - cylinder: {radius: 1, z_min: -2, z_max: 2}\n"
      "    - cylinder: {from: [-2, 0, 0], to: [2, 0, 0], radius: 1}\n"
      "    - cylinder: {from: [0, -2, 0], to: [0, 2, 0], radius: 1}\n");
  SceneHit hit;
  // Along the z axis: the x and y cylinders bound it at |z| = 1.
  const Ray r{{0, 0, -5}, {0, 0, 1}};
  ASSERT_TRUE(scene.intersect(r, hit));
  EXPECT_NEAR(hit.local.t, 4, 1e-14);
  const Vec3 n = scene.surface(r, hit).n;
  EXPECT_NEAR(n.z, -1, 1e-12);
  // Along x at y = 0.6: the y cylinder bounds |x| <= 0.8, the z one |x| <= 0.8 as well.
  std::vector<Crossing> all;
  scene.intersect_all(Ray{{-5, 0.6, 0}, {1, 0, 0}}, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_NEAR(all[0].t, 4.2, 1e-14);
  EXPECT_NEAR(all[1].t, 5.8, 1e-14);
}

std::string error_of(const std::string& text) {
  try {
    load_scene_text(text, "s.yaml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CsgShapes, OpenOperands_AreErrorsWithPosition) {
  // A cube with one face missing: open, so not a solid.
  MeshData open = cube_mesh(1);
  open.f.pop_back();
  open.f.pop_back();
  EXPECT_EQ(error_of("objects:\n  - difference:\n" + mesh_yaml(open, "      ") +
                     "      - sphere: {radius: 1.3}\n"),
            "s.yaml:3:9: mesh cannot be a CSG operand: it is an open surface");
  EXPECT_EQ(error_of("objects:\n  - union:\n      - sphere: {radius: 1}\n"
                     "      - cylinder: {radius: 1, capped: false}\n"),
            "s.yaml:4:9: cylinder cannot be a CSG operand: it is an open surface");
  EXPECT_EQ(error_of("objects:\n  - union:\n      - cone: {radius: 1, phi_max: 180}\n"),
            "s.yaml:3:9: cone cannot be a CSG operand: it is an open surface");
  // The closed cube loads.
  EXPECT_EQ(error_of("objects:\n  - difference:\n" + mesh_yaml(cube_mesh(1), "      ") +
                     "      - sphere: {radius: 1.3}\n"),
            "no error");
}

}  // namespace
}  // namespace raycast
