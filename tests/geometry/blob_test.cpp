#include "geometry/blob.h"
#include "geometry/shape_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference_roots.h"

namespace raycast {
namespace {

using testing::Rng;

BlobComponent ball(const Vec3& c, double r, double s) {
  BlobComponent b;
  b.a = b.b = c;
  b.radius = r;
  b.strength = s;
  return b;
}

BlobComponent stick(const Vec3& a, const Vec3& b, double r, double s) {
  BlobComponent c = ball(a, r, s);
  c.b = b;
  c.cylinder = true;
  return c;
}

// The field written from the definition in long double, independently of the shape's code.
long double field_ld(const std::vector<BlobComponent>& cs, long double x, long double y,
                     long double z) {
  long double f = 0;
  for (const BlobComponent& c : cs) {
    long double px = x, py = y, pz = z;
    if (c.xf) {
      const Vec3 q = c.xf->inverse_point({double(x), double(y), double(z)});
      px = q.x, py = q.y, pz = q.z;
    }
    long double rx = px - c.a.x, ry = py - c.a.y, rz = pz - c.a.z;
    if (c.cylinder) {
      const long double ax = c.b.x - c.a.x, ay = c.b.y - c.a.y, az = c.b.z - c.a.z;
      const long double aa = ax * ax + ay * ay + az * az;
      const long double s = std::clamp((rx * ax + ry * ay + rz * az) / aa, 0.0L, 1.0L);
      rx -= s * ax, ry -= s * ay, rz -= s * az;
    }
    const long double d2 = (rx * rx + ry * ry + rz * rz) / ((long double)c.radius * c.radius);
    if (d2 < 1) f += c.strength * (1 - d2) * (1 - d2);
  }
  return f;
}

std::vector<double> crossings(const Blob& s, const Ray& r) {
  SpanList l;
  spans(s, r, l);
  std::vector<double> t;
  for (const Span& sp : l) t.insert(t.end(), {sp.in.t, sp.out.t});
  return t;
}

// The reference crossings of the line over [lo, hi] (no transformed components).
std::vector<double> reference(const std::vector<BlobComponent>& cs, double threshold, const Ray& r,
                              double lo, double hi) {
  const auto f = [&](long double t) {
    return field_ld(cs, r.o.x + t * r.d.x, r.o.y + t * r.d.y, r.o.z + t * r.d.z) - threshold;
  };
  std::vector<double> out;
  for (long double t : testing_reference::sign_change_roots(f, lo, hi, 200000))
    out.push_back(double(t));
  return out;
}

// The radius of a lone sphere component's surface: s (1 - r^2 / R^2)^2 = T.
double lone_radius(double R, double s, double T) { return R * std::sqrt(1 - std::sqrt(T / s)); }

TEST(Blob, MakeBlob_RejectsBadInput) {
  EXPECT_THROW(make_blob(0, {ball({}, 1, 1)}), std::invalid_argument);
  EXPECT_THROW(make_blob(1, {}), std::invalid_argument);
  EXPECT_THROW(make_blob(1, {ball({}, 0, 1)}), std::invalid_argument);
  EXPECT_THROW(make_blob(1, {ball({}, 1, std::nan(""))}), std::invalid_argument);
  EXPECT_THROW(make_blob(1, {ball({}, 1, -1)}), std::invalid_argument);  // nothing positive
}

TEST(Blob, LoneSphere_ClosedFormRadius) {
  const double r = lone_radius(1.5, 2, 0.6);
  const Blob b = make_blob(0.6, {ball({1, 2, 3}, 1.5, 2)});
  const Ray ray{{-4, 2, 3}, {1, 0, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(b, ray, h));
  EXPECT_NEAR(h.t, 5 - r, 1e-13);
  const auto t = crossings(b, ray);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 5 - r, 1e-13);
  EXPECT_NEAR(t[1], 5 + r, 1e-13);
  const SurfaceInfo si = surface(b, ray, h);
  EXPECT_NEAR(si.n.x, -1, 1e-12);
  EXPECT_NEAR(length(si.p - Vec3{1, 2, 3}), r, 1e-13);
}

TEST(Blob, LoneCylinder_BodyAndHemisphericalEnds) {
  const double r = lone_radius(1, 2, 1);
  const Blob b = make_blob(1, {stick({0, 0, -1}, {0, 0, 1}, 1, 2)});
  auto t = crossings(b, Ray{{-5, 0, 0.5}, {1, 0, 0}});
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 5 - r, 1e-13);
  EXPECT_NEAR(t[1], 5 + r, 1e-13);
  t = crossings(b, Ray{{0, 0, -5}, {0, 0, 2}});  // along the axis, through both ends
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], (4 - r) / 2, 1e-13);
  EXPECT_NEAR(t[1], (6 + r) / 2, 1e-13);
  // Through an end's hemisphere off the axis: the sphere about (0, 0, 1).
  const double y = 0.3, half = std::sqrt(r * r - y * y);
  t = crossings(b, Ray{{0, y, 5}, {0, 0, -1}});
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 4 - half, 1e-13);
  EXPECT_NEAR(t[1], 6 + half, 1e-13);
}

TEST(Blob, ScaledComponent_Ellipsoid) {
  BlobComponent c = ball({}, 1, 2);
  c.xf = Transform::scale({2, 1, 1});
  const Blob b = make_blob(1, {c});
  const double r = lone_radius(1, 2, 1);
  const auto t = crossings(b, Ray{{-5, 0, 0}, {1, 0, 0}});
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 5 - 2 * r, 1e-12);
  EXPECT_NEAR(t[1], 5 + 2 * r, 1e-12);
  LocalHit h;
  const Ray up{{0.5, -5, 0}, {0, 1, 0}};
  ASSERT_TRUE(intersect(b, up, h));
  testing::expect_outward_normal(
      b, up, h, [&](const Vec3& p) { return contains(b, p); }, 1e-6);
}

void expect_matches_reference(const std::vector<BlobComponent>& cs, double threshold,
                              const Ray& r) {
  const Blob b = make_blob(threshold, cs);
  const auto got = crossings(b, r);
  const auto want = reference(cs, threshold, r, -10, 10);
  ASSERT_EQ(got.size(), want.size()) << testing::describe(r);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-10) << i;
  LocalHit h;
  const bool hit = intersect(b, r, h);
  const auto first = std::find_if(want.begin(), want.end(), [&](double t) { return t >= r.tmin; });
  ASSERT_EQ(hit, first != want.end());
  if (hit) {
    EXPECT_NEAR(h.t, *first, 1e-10);
  }
}

TEST(Blob, TwoSpheres_AgainstDenseReference) {
  const std::vector<BlobComponent> cs = {ball({-0.6, 0, 0}, 1, 1), ball({0.6, 0.1, 0}, 1.2, 1.5)};
  for (double y : {0.0, 0.3, 0.6, 0.75, 0.9})
    expect_matches_reference(cs, 0.5, Ray{{-5, y, 0.05}, {1, 0, 0}});
  expect_matches_reference(cs, 0.5, Ray{{-3, -2, 1}, {1, 0.7, -0.3}});
}

TEST(Blob, SphereAndCylinder_AgainstDenseReference) {
  const std::vector<BlobComponent> cs = {stick({-1, 0, 0}, {1, 0.5, 0}, 0.8, 1.2),
                                         ball({0, 0.9, 0.2}, 0.9, 1)};
  for (double z : {-0.4, 0.0, 0.2, 0.45})
    expect_matches_reference(cs, 0.4, Ray{{-5, 0.3, z}, {1, 0.05, 0}});
  expect_matches_reference(cs, 0.4, Ray{{-1.8, 0.2, -3}, {0.1, 0, 1}});  // through the end
}

TEST(Blob, NegativeComponent_CarvesAHole) {
  // A bite out of the side, and a hollow inside.
  const std::vector<BlobComponent> bite = {ball({}, 1, 2), ball({0.3, 0, 0}, 0.5, -3)};
  expect_matches_reference(bite, 1, Ray{{-5, 0, 0}, {1, 0, 0}});
  expect_matches_reference(bite, 1, Ray{{-5, 0.2, 0.1}, {1, 0, 0}});
  const std::vector<BlobComponent> hollow = {ball({}, 1, 2), ball({0.05, 0, 0}, 0.2, -3)};
  const Ray r{{-5, 0, 0}, {1, 0, 0}};
  expect_matches_reference(hollow, 1, r);
  EXPECT_EQ(crossings(make_blob(1, hollow), r).size(), 4u);
}

TEST(Blob, RayStartingInside_HitsTheExitAndSpansReachBack) {
  const double r = lone_radius(1, 2, 1);
  const Blob b = make_blob(1, {ball({}, 1, 2)});
  const Ray ray{{0, 0, 0}, {0, 1, 0}};
  LocalHit h;
  ASSERT_TRUE(intersect(b, ray, h));
  EXPECT_NEAR(h.t, r, 1e-14);
  const auto t = crossings(b, ray);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], -r, 1e-14);
  EXPECT_TRUE(contains(b, {0, 0, 0}));
  EXPECT_FALSE(contains(b, {0, 1.01 * r, 0}));
}

TEST(Blob, TangentAndGrazingRays) {
  const double r = lone_radius(1, 2, 1);
  const Blob b = make_blob(1, {ball({}, 1, 2)});
  LocalHit h;
  EXPECT_FALSE(intersect(b, Ray{{-5, r * (1 + 1e-9), 0}, {1, 0, 0}}, h));
  EXPECT_TRUE(crossings(b, Ray{{-5, r * (1 + 1e-9), 0}, {1, 0, 0}}).empty());
  const Ray grazing{{-5, r * (1 - 1e-6), 0}, {1, 0, 0}};
  ASSERT_TRUE(intersect(b, grazing, h));
  EXPECT_NEAR(h.t, 5, 2e-3);
  const auto t = crossings(b, grazing);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_LT(t[0], 5);
  EXPECT_GT(t[1], 5);
  // Exactly tangent: a touch is no span, and intersect finds it or nothing, near t = 5.
  const Ray tangent{{-5, r, 0}, {1, 0, 0}};
  if (intersect(b, tangent, h)) {
    EXPECT_NEAR(h.t, 5, 1e-4);
  }
  // Along the seam where two equal components meet: the sum is symmetric about x = 0.
  const Blob two = make_blob(1, {ball({-0.5, 0, 0}, 1, 1), ball({0.5, 0, 0}, 1, 1)});
  const auto s = crossings(two, Ray{{0, -5, 0}, {0, 1, 0}});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(s[0] + s[1], 10, 1e-12);
}

TEST(Blob, TMinTMax_Respected) {
  const double r = lone_radius(1, 2, 1);
  const Blob b = make_blob(1, {ball({}, 1, 2)});
  Ray ray{{-5, 0, 0}, {1, 0, 0}};
  ray.tmax = 5 - r - 1e-9;
  LocalHit h;
  EXPECT_FALSE(intersect(b, ray, h));
  ray.tmax = kInfinity;
  ray.tmin = 5 - r + 1e-9;
  ASSERT_TRUE(intersect(b, ray, h));
  EXPECT_NEAR(h.t, 5 + r, 1e-13);
}

std::vector<BlobComponent> random_components(Rng& rng, int n, bool transforms) {
  std::vector<BlobComponent> cs;
  for (int i = 0; i < n; ++i) {
    const Vec3 c = rng.in_box(2);
    const double s = i % 4 == 3 ? -rng.uniform(0.2, 1.5) : rng.uniform(0.5, 2);
    BlobComponent b = i % 3 == 1 ? stick(c, c + rng.in_box(1), rng.uniform(0.3, 1), s)
                                 : ball(c, rng.uniform(0.3, 1.2), s);
    if (transforms && i % 2 == 0)
      b.xf = Transform::rotate(rng.direction(), rng.uniform(0, 180)) *
             Transform::scale({rng.uniform(0.5, 2), rng.uniform(0.5, 2), 1});
    cs.push_back(b);
  }
  return cs;
}

TEST(Blob, RandomRays_SpansAgreeWithContainsAndIntersect) {
  Rng rng(17);
  for (int k = 0; k < 20; ++k) {
    const std::vector<BlobComponent> cs = random_components(rng, 3 + k * 3, k % 2 == 1);
    const Blob b = make_blob(rng.uniform(0.3, 1), cs);
    const auto inside = [&](const Vec3& p) { return contains(b, p); };
    for (int i = 0; i < 50; ++i) {
      const Ray r = testing::random_ray(rng, 5, 2);
      testing::check_spans_against_oracle(b, r, inside, -20, 20, 401);
      LocalHit h;
      const double want = testing::first_span_end(b, r);
      const bool hit = intersect(b, r, h);
      EXPECT_EQ(hit, want < kInfinity) << testing::describe(r);
      if (hit && want < kInfinity) {
        EXPECT_NEAR(h.t, want, 1e-9 * (1 + std::abs(want)));
        const SurfaceInfo si = surface(b, r, h);
        testing::expect_unit(si.n);
        if (!contains(b, r.o)) {  // a first hit from outside faces the ray
          EXPECT_LT(dot(si.n, r.d), 1e-9 * length(r.d)) << testing::describe(r);
        }
      }
    }
  }
}

TEST(Blob, RandomRays_MatchTheFieldInLongDouble) {
  Rng rng(5);
  const std::vector<BlobComponent> cs = random_components(rng, 12, false);
  const Blob b = make_blob(0.7, cs);
  for (int i = 0; i < 30; ++i) {
    Ray r = testing::random_ray(rng, 5, 2);
    r.d = normalize(r.d);
    const auto got = crossings(b, r);
    const auto want = reference(cs, 0.7, r, -12, 12);
    // The dense reference misses pairs of roots closer than its step: compare when it saw all.
    if (got.size() != want.size()) continue;
    for (std::size_t j = 0; j < got.size(); ++j) EXPECT_NEAR(got[j], want[j], 1e-9);
  }
}

TEST(Blob, ManyComponents_HierarchyFindsTheSameField) {
  Rng rng(3);
  std::vector<BlobComponent> cs;
  for (int i = 0; i < 600; ++i) cs.push_back(ball(rng.in_box(10), rng.uniform(0.5, 1.5), 1.2));
  const Blob b = make_blob(0.5, cs);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = rng.in_box(11);
    EXPECT_NEAR(blob_field(b, p), double(field_ld(cs, p.x, p.y, p.z)), 1e-12);
  }
  const auto inside = [&](const Vec3& p) { return contains(b, p); };
  for (int i = 0; i < 40; ++i)
    testing::check_spans_against_oracle(b, testing::random_ray(rng, 15, 8), inside, -30, 30, 801);
}

}  // namespace
}  // namespace raycast

namespace raycast {
namespace {

TEST(Blob, Material_OfTheStrongestComponent) {
  BlobComponent left = ball({-0.6, 0, 0}, 1, 1), right = ball({0.6, 0, 0}, 1, 1);
  left.material = 3;
  const BlobComponent plain = ball({0, 2, 0}, 1, 1);  // the object's material
  const Blob b = make_blob(0.5, {left, right, plain});
  LocalHit h;
  ASSERT_TRUE(intersect(b, Ray{{-5, 0, 0}, {1, 0, 0}}, h));
  EXPECT_EQ(blob_material(b, h), 3);
  ASSERT_TRUE(intersect(b, Ray{{5, 0, 0}, {-1, 0, 0}}, h));
  EXPECT_EQ(blob_material(b, h), -1);
  SpanList l;
  spans(b, Ray{{-5, 0.1, 0}, {1, 0, 0}}, l);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(blob_material(b, l[0].in), 3);
  EXPECT_EQ(blob_material(b, l[0].out), -1);
  // Without any component material every hit takes the object's.
  ASSERT_TRUE(intersect(make_blob(0.5, {right}), Ray{{5, 0, 0}, {-1, 0, 0}}, h));
  EXPECT_EQ(blob_material(make_blob(0.5, {right}), h), -1);
}

}  // namespace
}  // namespace raycast
