// The mesh as a shape: hits in double, prim numbering, normals, spans, degenerate input.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/spawn.h"
#include "mesh/mesh.h"
#include "mesh/procedural.h"

namespace raycast {
namespace {

std::shared_ptr<const Mesh> unit_cube(bool smooth = false) {
  std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                       {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<std::array<std::uint32_t, 3>> t{{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                              {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                              {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  MeshOptions o;
  o.smooth = smooth;
  return make_mesh(p, t, {}, o);
}

TEST(MeshShape, CubeFromBelow_HitsBottomWithOutwardNormalAndBarycentrics) {
  const MeshShape s{unit_cube()};
  const Ray ray{{0.25, 0.5, -2}, {0, 0, 2}};
  LocalHit h;
  ASSERT_TRUE(intersect(s, ray, h));
  EXPECT_DOUBLE_EQ(h.t, 1.0);
  EXPECT_TRUE(h.prim == 0 || h.prim == 1);
  const SurfaceInfo si = surface(s, ray, h);
  EXPECT_DOUBLE_EQ(si.p.x, 0.25);
  EXPECT_DOUBLE_EQ(si.p.y, 0.5);
  EXPECT_DOUBLE_EQ(si.p.z, 0.0);
  EXPECT_DOUBLE_EQ(si.n.z, -1.0);
  EXPECT_DOUBLE_EQ(si.u, h.a);
  EXPECT_DOUBLE_EQ(si.v, h.b);
  // The barycentrics reproduce the point.
  const Mesh& m = *s.mesh;
  const auto& t = m.triangles[h.part];
  const Vec3 q = (1 - h.a - h.b) * Vec3(m.positions[t[0]]) + h.a * Vec3(m.positions[t[1]]) +
                 h.b * Vec3(m.positions[t[2]]);
  EXPECT_NEAR(length(q - si.p), 0, 1e-6);
}

TEST(MeshShape, T_IsRefinedInDouble) {
  // A plane at z = 0.1 (not a float): the answer must carry double precision, not float's.
  const std::vector<Vec3f> p{{-1, -1, 0.1f}, {1, -1, 0.1f}, {0, 1, 0.1f}};
  const MeshShape s{make_mesh(p, {{0, 1, 2}})};
  LocalHit h;
  ASSERT_TRUE(intersect(s, Ray{{0.1, 0.1, 3.3}, {0, 0, -1}}, h));
  EXPECT_DOUBLE_EQ(h.t, 3.3 - double(0.1f));
}

TEST(MeshShape, TminTmax_AreInclusive) {
  const MeshShape s{unit_cube()};
  LocalHit h;
  EXPECT_TRUE(intersect(s, Ray{{0.5, 0.5, -1}, {0, 0, 1}, 0, 1}, h));
  EXPECT_EQ(h.t, 1.0);
  EXPECT_FALSE(intersect(s, Ray{{0.5, 0.5, -1}, {0, 0, 1}, 0, 0.999}, h));
  EXPECT_TRUE(occluded(s, Ray{{0.5, 0.5, -1}, {0, 0, 1}, 0, 1}));
  EXPECT_FALSE(occluded(s, Ray{{0.5, 0.5, -1}, {0, 0, 1}, 0, 0.999}));
}

TEST(MeshShape, HugeAndTinyDirections_GiveTInUnitsOfD) {
  const MeshShape s{unit_cube()};
  for (double scale : {1e-30, 1e-8, 1.0, 1e8, 1e30, 1e300}) {
    LocalHit h;
    ASSERT_TRUE(intersect(s, Ray{{0.5, 0.5, -1}, {0, 0, scale}}, h)) << scale;
    EXPECT_NEAR(h.t * scale, 1.0, 1e-12) << scale;
  }
}

// The float ray's [tmin, tmax] is the double one rounded outwards: the nearest float at or below
// tmin and at or above tmax (std::nextafter's answer where the cast rounded the wrong way),
// including zeros, tiny values, values beyond the float range and infinities.
TEST(MeshShape, ToMeshRay_RoundsTheIntervalOutwards) {
  const double kMax = std::numeric_limits<float>::max();
  const double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> xs{0.0,  -0.0,  1e-50,      -1e-50,      1e-40, -1e-40, 0.1,   -0.1,
                         1.0,  -1.0,  kMax,       -kMax,       1e39,  -1e39,  1e300, -1e300,
                         kInf, -kInf, 1.5 * kMax, -1.5 * kMax, 3e-45, -3e-45};
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-160, 140);
  for (int i = 0; i < 2000; ++i) xs.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  auto down = [](double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
  };
  auto up = [](double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  };
  for (double x : xs) {
    Ray ray{{0.25, -3, 7}, {1.5, -0.75, 0.5}};  // scale 1: t unchanged
    ray.tmin = ray.tmax = x;
    double scale = 0;
    const MeshRay r = to_mesh_ray(ray, scale);
    EXPECT_EQ(scale, 1.0);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(r.tmin), std::bit_cast<std::uint32_t>(down(x))) << x;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(r.tmax), std::bit_cast<std::uint32_t>(up(x))) << x;
    EXPECT_LE(static_cast<double>(r.tmin), x);
    EXPECT_GE(static_cast<double>(r.tmax), x);
  }
}

// Directions of every size and sign scale by the power of two that brings the largest component
// into [1, 2); the scaled direction is exact.
TEST(MeshShape, ToMeshRay_ScalesDirectionByAPowerOfTwo) {
  for (double mag : {1e-300, 1e-30, 0.3, 1.0, 1.999, 2.0, 1e30, 1e300, 1.7e308})
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        Vec3 d{0.25 * mag, -0.125 * mag, 0.0625 * mag};
        d[axis] = sign * mag;
        double scale = 0;
        const MeshRay r = to_mesh_ray(Ray{{1, 2, 3}, d}, scale);
        const double m =
            std::max(std::abs(d.x * scale), std::max(std::abs(d.y * scale), std::abs(d.z * scale)));
        EXPECT_GE(m, 1.0) << mag;
        EXPECT_LT(m, 2.0) << mag;
        EXPECT_EQ(std::ilogb(scale), -std::ilogb(mag)) << mag;
        EXPECT_EQ(r.d[axis], static_cast<float>(sign * mag * scale)) << mag;
      }
}

TEST(MeshShape, PrimIsTheInputIndex_WhenDegenerateTrianglesAreDropped) {
  const std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  // Triangle 0 repeats an index, 1 is collinear (zero area), 2 is the real one.
  const auto m = make_mesh(p, {{0, 0, 1}, {0, 1, 3}, {0, 1, 2}});
  EXPECT_EQ(m->dropped, 2u);
  EXPECT_EQ(m->triangle_count(), 1u);
  LocalHit h;
  ASSERT_TRUE(intersect(MeshShape{m}, Ray{{0.2, 0.2, 1}, {0, 0, -1}}, h));
  EXPECT_EQ(h.prim, 2);
}

TEST(MeshShape, NeedleTriangles_AreKeptAndHitWhereTheyAre) {
  // A sliver 1e-6 wide along x.
  const std::vector<Vec3f> p{{0, 0, 0}, {1, 0, 0}, {1, 1e-6f, 0}};
  const auto m = make_mesh(p, {{0, 1, 2}});
  EXPECT_EQ(m->dropped, 0u);
  LocalHit h;
  EXPECT_TRUE(intersect(MeshShape{m}, Ray{{0.9, 0.5e-6 * 0.9, 1}, {0, 0, -1}}, h));
  EXPECT_FALSE(intersect(MeshShape{m}, Ray{{0.9, 2e-6, 1}, {0, 0, -1}}, h));
}

TEST(MeshShape, EmptyMesh_NeverHitsAndHasEmptyBounds) {
  const auto m = make_mesh({}, {});
  const MeshShape s{m};
  LocalHit h;
  EXPECT_FALSE(intersect(s, Ray{{0, 0, 0}, {1, 0, 0}}, h));
  EXPECT_FALSE(occluded(s, Ray{{0, 0, 0}, {1, 0, 0}}));
  SpanList out;
  spans(s, Ray{{0, 0, 0}, {1, 0, 0}}, out);
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(bounds(s).is_empty());
  EXPECT_FALSE(is_closed(s));
}

TEST(MeshShape, AllDegenerate_IsEmpty) {
  const auto m = make_mesh({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 1, 2}, {1, 1, 1}});
  EXPECT_EQ(m->dropped, 2u);
  EXPECT_TRUE(m->bvh.empty());
}

TEST(MeshShape, BadInput_Throws) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(make_mesh({{0, 0, 0}, {1, 0, 0}, {0, nan, 0}}, {{0, 1, 2}}), std::invalid_argument);
  EXPECT_THROW(make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}), std::invalid_argument);
  EXPECT_THROW(make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {{0, 0, 1}}),
               std::invalid_argument);
  EXPECT_THROW(
      make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}}),
      std::invalid_argument);
}

TEST(MeshShape, ClosedCube_SpansAreSolidIntervals) {
  const MeshShape s{unit_cube()};
  EXPECT_TRUE(is_closed(s));
  SpanList out;
  spans(s, Ray{{0.5, 0.5, 5}, {0, 0, -1}, 0, 1}, out);  // tmin, tmax are ignored by spans
  ASSERT_EQ(out.size(), 1u);
  EXPECT_DOUBLE_EQ(out[0].in.t, 4);
  EXPECT_DOUBLE_EQ(out[0].out.t, 5);
  // Through an edge and a vertex: still one interval.
  out.clear();
  spans(s, Ray{{0.5, 0.5, 5}, {0, 0, -1}}, out);
  out.clear();
  spans(s, Ray{{-1, -1, -1}, {1, 1, 1}}, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].in.t, 1, 1e-12);
  EXPECT_NEAR(out[0].out.t, 2, 1e-12);
}

TEST(MeshShape, ClosedSphere_SpansMatchContainsOracle) {
  const TriangleSoup soup = make_octa_sphere(8);
  const MeshShape s{make_mesh(soup.positions, soup.triangles)};
  ASSERT_TRUE(is_closed(s));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 200; ++i) {
    SCOPED_TRACE("ray " + std::to_string(i));
    const Ray ray{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    SpanList out;
    spans(s, ray, out);
    for (std::size_t k = 0; k < out.size(); ++k) {
      EXPECT_LE(out[k].in.t, out[k].out.t);
      if (k > 0) {
        EXPECT_LE(out[k - 1].out.t, out[k].in.t);
      }
      // Midpoints of spans are inside; midpoints of gaps are outside.
      const double mid = 0.5 * (out[k].in.t + out[k].out.t);
      if (out[k].out.t - out[k].in.t > 1e-6) {
        EXPECT_TRUE(contains(s, ray.at(mid)));
      }
      if (k > 0 && out[k].in.t - out[k - 1].out.t > 1e-6) {
        EXPECT_FALSE(contains(s, ray.at(0.5 * (out[k - 1].out.t + out[k].in.t))));
      }
    }
  }
}

// Unit cubes in one mesh: [0, 1]^3 and copies shifted by `shifts`.
std::shared_ptr<const Mesh> cubes(const std::vector<Vec3f>& shifts) {
  const auto a = unit_cube();
  std::vector<Vec3f> p = a->positions;
  std::vector<std::array<std::uint32_t, 3>> t = a->triangles;
  for (const Vec3f& shift : shifts) {
    const auto base = static_cast<std::uint32_t>(p.size());
    for (std::size_t i = 0; i < 8; ++i) p.push_back(a->positions[i] + shift);
    for (std::size_t i = 0; i < 12; ++i)
      t.push_back(
          {a->triangles[i][0] + base, a->triangles[i][1] + base, a->triangles[i][2] + base});
  }
  return make_mesh(p, t);
}

TEST(MeshShape, GrazingAnEdge_IsNoSpanAndDoesNotOpenOne) {
  // The line x + 2z = 3 at y = 0.5 touches the first cube only at its edge x = 1, z = 1 (it leaves
  // through the +x face's plane and enters through the +z face's at the same t), and crosses the
  // cubes at x in [3.5, 4.5] and x in [-3.5, -2.5]. Both directions, so that a real span follows
  // the touch either way: only the two real spans.
  const MeshShape s{cubes({{3.5f, 0, -1}, {-3.5f, 0, 2.5f}})};
  ASSERT_TRUE(is_closed(s));
  for (const double k : {1.0, -1.0}) {
    SCOPED_TRACE(k);
    const Vec3 d = k * Vec3{1, 0, -0.5};
    const Ray ray{Vec3{1, 0.5, 1} - 10.0 * d, d};  // the touch at t = 10
    SpanList out;
    spans(s, ray, out);
    ASSERT_EQ(out.size(), 2u);
    // x = 1 + k (t - 10): the spans at x = -3.5 .. -2.5 and 3.5 .. 4.5.
    const double first = k > 0 ? 5.5 : 6.5, second = k > 0 ? 12.5 : 13.5;
    EXPECT_NEAR(out[0].in.t, first, 1e-12);
    EXPECT_NEAR(out[0].out.t, first + 1, 1e-12);
    EXPECT_NEAR(out[1].in.t, second, 1e-12);
    EXPECT_NEAR(out[1].out.t, second + 1, 1e-12);
  }
}

TEST(MeshShape, SpansFromInside_IncludeTheFaceBehind) {
  // The whole line counts: from inside the cube, the entry lies behind the origin (t < 0), on a
  // face whose BVH box is flat. The box test once shrank negative intervals and culled it.
  const MeshShape s{unit_cube()};
  for (const Vec3& d :
       {Vec3{-1, 0.27, -0.07}, Vec3{1, 0.27, -0.07}, Vec3{0.1, -1, 0.2}, Vec3{0.1, 0.3, 1}}) {
    SCOPED_TRACE(testing::Message() << d.x << " " << d.y << " " << d.z);
    const Ray ray{{0.4, 0.45, 0.5}, d};
    SpanList out;
    spans(s, ray, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_LT(out[0].in.t, 0);
    EXPECT_GT(out[0].out.t, 0);
    EXPECT_TRUE(contains(s, ray.o));
  }
}

TEST(MeshShape, OverlappingClosedComponents_SpanTheirUnion) {
  // Two overlapping cubes in one mesh bound their union (nonzero winding): one span.
  const MeshShape s{cubes({{0.5f, 0.25f, 0.25f}})};
  SpanList out;
  spans(s, Ray{{-1, 0.5, 0.5}, {1, 0, 0}}, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, 1);
  EXPECT_EQ(out[0].out.t, 2.5);
}

TEST(MeshShape, OpenMesh_GivesZeroLengthSpans) {
  const auto m = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const MeshShape s{m};
  EXPECT_FALSE(is_closed(s));
  EXPECT_FALSE(contains(s, {0.5, 0.5, 0}));
  SpanList out;
  spans(s, Ray{{0.5, 0.5, 1}, {0, 0, -1}}, out);  // exactly through the shared diagonal
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, out[0].out.t);
  EXPECT_DOUBLE_EQ(out[0].in.t, 1);
}

TEST(MeshShape, Normal_FollowsCounterClockwiseWinding) {
  const auto up = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const auto down = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 2, 1}});
  const Ray ray{{0.2, 0.2, 1}, {0, 0, -1}};
  LocalHit h;
  ASSERT_TRUE(intersect(MeshShape{up}, ray, h));
  EXPECT_DOUBLE_EQ(surface(MeshShape{up}, ray, h).n.z, 1);
  ASSERT_TRUE(intersect(MeshShape{down}, ray, h));
  EXPECT_DOUBLE_EQ(surface(MeshShape{down}, ray, h).n.z, -1);
}

TEST(MeshShape, Smooth_InterpolatesUnitShadingNormalsOnTheSideOfN) {
  const TriangleSoup soup = make_octa_sphere(6, 0);
  MeshOptions o;
  o.smooth = true;
  const MeshShape s{make_mesh(soup.positions, soup.triangles, {}, o)};
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  for (int i = 0; i < 100; ++i) {
    const Vec3 d{n(rng), n(rng), n(rng)};
    const Ray ray{{0, 0, 0}, d};
    LocalHit h;
    ASSERT_TRUE(intersect(s, ray, h));
    const SurfaceInfo si = surface(s, ray, h);
    EXPECT_NEAR(length(si.shading_n), 1, 1e-12);
    EXPECT_GT(dot(si.shading_n, si.n), 0.9);
    // On a sphere the smooth normal is close to the radial direction.
    EXPECT_GT(dot(si.shading_n, normalize(si.p)), 0.999);
  }
}

TEST(MeshShape, SpawnedRays_DoNotRehitTheirSurface) {
  const TriangleSoup soup = make_procedural_mesh("sphere", 20000);
  const MeshShape s{make_mesh(soup.positions, soup.triangles)};
  std::mt19937 rng(9);
  std::normal_distribution<double> n;
  int rehits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o = 5.0 * normalize(Vec3{n(rng), n(rng), n(rng)});
    const Ray ray{o, -o + 0.3 * Vec3{n(rng), n(rng), n(rng)}};
    LocalHit h;
    if (!intersect(s, ray, h)) continue;
    const SurfaceInfo si = surface(s, ray, h);
    // Leave towards the outside (reflection side): nothing of this convex-ish surface is near.
    const Vec3 w = si.n + 0.1 * Vec3{n(rng), n(rng), n(rng)};
    if (dot(w, si.n) <= 0) continue;
    const Vec3 p = offset_ray_origin(si, w);
    LocalHit again;
    if (intersect(s, Ray{p, w, 0, 1e-3}, again)) ++rehits;
  }
  EXPECT_EQ(rehits, 0);
}

}  // namespace
}  // namespace raycast
