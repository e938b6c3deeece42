#include "geometry/superellipsoid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "geometry/shape_checks.h"
#include "geometry/shape_error.h"
#include "geometry/sphere.h"

namespace raycast {
namespace {

using testing::Rng;

std::vector<double> all_crossings(const Superellipsoid& s, const Ray& r) {
  SpanList l;
  spans(s, r, l);
  std::vector<double> t;
  for (const Span& sp : l) {
    t.push_back(sp.in.t);
    t.push_back(sp.out.t);
  }
  return t;
}

// The surface's own equation in long double, written directly (not through the gauge's ratios).
long double f_ld(const Superellipsoid& s, const Ray& r, long double t) {
  const long double x = std::fabs(r.o.x + t * (long double)r.d.x);
  const long double y = std::fabs(r.o.y + t * (long double)r.d.y);
  const long double z = std::fabs(r.o.z + t * (long double)r.d.z);
  const long double e = s.e, n = s.n;
  return std::pow(std::pow(x, 2 / e) + std::pow(y, 2 / e), e / n) + std::pow(z, 2 / n) - 1;
}

// The crossings by dense sampling over the line's chord through [-1.5, 1.5]^3 and long-double
// bisection; `resolved` is false when two crossings lie within a few samples (then sampling may
// miss a pair).
std::vector<double> reference_crossings(const Superellipsoid& s, const Ray& r, bool& resolved) {
  double t0 = -kInfinity, t1 = kInfinity;
  for (std::size_t i = 0; i < 3; ++i) {
    double a = (-1.5 - r.o[i]) / r.d[i], b = (1.5 - r.o[i]) / r.d[i];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
  }
  std::vector<double> out;
  resolved = true;
  if (!(t0 < t1)) return out;
  constexpr int kSamples = 5000;
  const long double step = ((long double)t1 - t0) / kSamples;
  long double prev = f_ld(s, r, t0);
  for (int k = 1; k <= kSamples; ++k) {
    const long double t = t0 + k * step;
    const long double cur = f_ld(s, r, t);
    if ((prev < 0) != (cur < 0)) {
      long double a = t - step, b = t, fa = prev;
      for (int it = 0; it < 80; ++it) {
        const long double m = 0.5L * (a + b), fm = f_ld(s, r, m);
        if ((fm < 0) == (fa < 0))
          a = m, fa = fm;
        else
          b = m;
      }
      const double root = static_cast<double>(0.5L * (a + b));
      if (!out.empty() && root - out.back() < 4 * static_cast<double>(step)) resolved = false;
      out.push_back(root);
    }
    prev = cur;
  }
  return out;
}

TEST(Superellipsoid, RejectsExponentsOutsideTheDomain) {
  EXPECT_THROW(make_superellipsoid(0, 1), ShapeParameterError);
  EXPECT_THROW(make_superellipsoid(1, -1), ShapeParameterError);
  EXPECT_THROW(make_superellipsoid(std::nan(""), 1), ShapeParameterError);
  EXPECT_THROW(make_superellipsoid(1, 1e9), ShapeParameterError);
  EXPECT_NO_THROW(make_superellipsoid(kSuperellipsoidMinExponent, kSuperellipsoidMaxExponent));
}

TEST(Superellipsoid, OneOneIsTheUnitSphere) {
  const Superellipsoid s = make_superellipsoid(1, 1);
  Rng rng(11);
  for (int i = 0; i < 2000; ++i) {
    const Ray r = testing::random_ray(rng, 3, 1.2);
    double a, b;
    const bool hit = sphere_line_roots(r.o, r.d, 1, a, b);
    const auto t = all_crossings(s, r);
    if (!hit || !(b - a > 1e-9 * (1 + std::abs(a)))) continue;  // tangent: either answer
    ASSERT_EQ(t.size(), 2u) << testing::describe(r);
    EXPECT_NEAR(t[0], a, 1e-13 * (1 + std::abs(a))) << testing::describe(r);
    EXPECT_NEAR(t[1], b, 1e-13 * (1 + std::abs(b))) << testing::describe(r);
    LocalHit h;
    if (intersect(s, r, h)) {
      const SurfaceInfo si = surface(s, r, h);
      EXPECT_NEAR(length(si.n - si.p), 0, 1e-12);
    }
  }
}

TEST(Superellipsoid, TwoTwoIsTheOctahedron) {
  const Superellipsoid s = make_superellipsoid(2, 2);
  const Ray r{{-5, 0.2, 0.3}, {2, 0, 0}};
  const auto t = all_crossings(s, r);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], (5 - 0.5) / 2, 1e-14);
  EXPECT_NEAR(t[1], (5 + 0.5) / 2, 1e-14);
  LocalHit h;
  ASSERT_TRUE(intersect(s, r, h));
  const SurfaceInfo si = surface(s, r, h);
  const double k = 1 / std::sqrt(3.0);
  EXPECT_NEAR(length(si.n - Vec3{-k, k, k}), 0, 1e-12);
  Rng rng(5);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p = rng.in_box(1.4);
    const Vec3 d = rng.direction();
    const Ray q{p, d};
    testing::check_spans_against_oracle(
        s, q, [](const Vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z) <= 1; }, -5,
        5);
  }
}

TEST(Superellipsoid, SmallExponentsApproachTheCube) {
  for (double e : {0.05, 0.01, 1e-3, 1e-6}) {
    const Superellipsoid s = make_superellipsoid(e, e);
    const Ray r{{-5, 0.3, -0.2}, {1, 0, 0}};
    LocalHit h;
    ASSERT_TRUE(intersect(s, r, h)) << e;
    // (|y|^(2/e) + |z|^(2/e)) is at most 2 * 0.3^(2/e): the face is within 1e-9 of x = -1.
    const double gap = 1 - std::pow(1 - std::pow(0.3, 2 / e) * 2, e / 2);
    EXPECT_NEAR(h.t, 4, std::max(gap, 1e-12)) << e;
    const SurfaceInfo si = surface(s, r, h);
    EXPECT_NEAR(si.n.x, -1, 1e-6) << e;
  }
}

TEST(Superellipsoid, TangentAndGrazingRaysOnTheSphere) {
  const Superellipsoid s = make_superellipsoid(1, 1);
  // Tangent at (0, 1, 0), where the line crosses the plane x = 0: a touch, no span.
  // The gauge sqrt(x^2 + 1) rounds to 1 for |x| below about 1e-8: the touch may come out as a
  // sliver of that width around x = 0, never more.
  const Ray tangent{{-3, 1, 0}, {1, 0, 0}};
  SpanList l;
  spans(s, tangent, l);
  for (const Span& sp : l) {
    EXPECT_NEAR(sp.in.t, 3, 1e-7);
    EXPECT_NEAR(sp.out.t, 3, 1e-7);
  }
  LocalHit h;
  if (intersect(s, tangent, h)) {
    EXPECT_NEAR(h.t, 3, 1e-7);
  }
  // Grazing just inside: two crossings at x = -+sqrt(1 - y^2).
  const double y = 1 - 1e-10;
  const Ray graze{{-3, y, 0}, {1, 0, 0}};
  const auto t = all_crossings(s, graze);
  ASSERT_EQ(t.size(), 2u);
  const double x = std::sqrt((1 - y) * (1 + y));
  EXPECT_NEAR(t[0], 3 - x, 1e-12);
  EXPECT_NEAR(t[1], 3 + x, 1e-12);
  // Just outside: nothing.
  EXPECT_TRUE(all_crossings(s, Ray{{-3, 1 + 1e-10, 0}, {1, 0, 0}}).empty());
}

TEST(Superellipsoid, RayFromInsideHitsTheExit) {
  for (const auto& [e, n] : {std::pair{1.0, 1.0}, {0.3, 2.5}, {3.0, 0.5}, {4.0, 4.0}}) {
    const Superellipsoid s = make_superellipsoid(e, n);
    const Ray r{{0.01, -0.02, 0.03}, {0.3, 0.5, -0.2}};
    LocalHit h;
    ASSERT_TRUE(intersect(s, r, h));
    EXPECT_NEAR(superellipsoid_gauge(s, r.at(h.t)), 1, 1e-14);
    SpanList l;
    spans(s, r, l);
    ASSERT_EQ(l.size(), 1u);
    EXPECT_LT(l[0].in.t, 0);
    EXPECT_DOUBLE_EQ(l[0].out.t, h.t);
  }
}

TEST(Superellipsoid, RandomRaysMatchTheDenseLongDoubleReference) {
  const double exps[] = {0.1, 0.25, 0.5, 1, 1.5, 2, 2.5, 3, 4};
  Rng rng(2026);
  double worst = 0;
  int compared = 0, thin = 0;
  for (int i = 0; i < 800; ++i) {
    const Superellipsoid s = make_superellipsoid(exps[rng() % 9], exps[rng() % 9]);
    const Ray r = testing::random_ray(rng, 2.5, 1.1);
    if (r.d.x == 0 || r.d.y == 0 || r.d.z == 0) continue;
    bool resolved;
    const auto ref = reference_crossings(s, r, resolved);
    if (!resolved) continue;
    auto t = all_crossings(s, r);
    // A span narrower than the sampling's step (the thin spikes of e or n above 2) is checked
    // on its own: inside at its middle by the long-double equation, then set aside.
    const double step = 3 * std::sqrt(3.0) / length(r.d) / 5000;
    for (std::size_t k = 0; t.size() != ref.size() && k + 1 < t.size();) {
      if (t[k + 1] - t[k] < 4 * step) {
        EXPECT_LT(f_ld(s, r, 0.5L * ((long double)t[k] + t[k + 1])), 0) << testing::describe(r);
        t.erase(t.begin() + static_cast<std::ptrdiff_t>(k),
                t.begin() + static_cast<std::ptrdiff_t>(k + 2));
        ++thin;
      } else {
        k += 2;
      }
    }
    ASSERT_EQ(t.size(), ref.size()) << "e=" << s.e << " n=" << s.n << " " << testing::describe(r);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double err = std::abs(t[k] - ref[k]) * length(r.d);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-13) << "e=" << s.e << " n=" << s.n << " " << testing::describe(r);
    }
    ++compared;
  }
  EXPECT_GT(compared, 500);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", worst);
  RecordProperty("worst_distance", text);
  RecordProperty("thin_spans", thin);
}

TEST(Superellipsoid, RandomRaysAgreeWithContainsAndIntersect) {
  Rng rng(77);
  for (int i = 0; i < 3000; ++i) {
    const double e = std::exp(rng.uniform(std::log(1e-3), std::log(10.0)));
    const double n = std::exp(rng.uniform(std::log(1e-3), std::log(10.0)));
    const Superellipsoid s = make_superellipsoid(e, n);
    Ray r = testing::random_ray(rng, 2, 1);
    r.tmin = rng.uniform(-1, 1);
    testing::check_spans_against_oracle(
        s, r, [&](const Vec3& p) { return contains(s, p); }, -20, 20, 201);
    LocalHit h;
    const bool hit = intersect(s, r, h);
    const double want = testing::first_span_end(s, r);
    if (std::isfinite(want)) {
      ASSERT_TRUE(hit) << "e=" << e << " n=" << n << " " << testing::describe(r);
      EXPECT_NEAR(h.t, want, 1e-12 * (1 + std::abs(want)))
          << "e=" << e << " n=" << n << " " << testing::describe(r);
    }
    if (hit) {
      const SurfaceInfo si = surface(s, r, h);
      testing::expect_unit(si.n);
      EXPECT_TRUE(std::isfinite(si.p.x + si.p.y + si.p.z));
    }
  }
}

TEST(Superellipsoid, NormalsPointOutOfTheSolid) {
  Rng rng(3);
  for (const auto& [e, n] : {std::pair{1.0, 1.0}, {0.5, 0.5}, {2.0, 1.0}, {0.25, 3.0}}) {
    const Superellipsoid s = make_superellipsoid(e, n);
    for (int i = 0; i < 300; ++i) {
      const Ray r = testing::random_ray(rng, 3, 0.7);
      LocalHit h;
      if (!intersect(s, r, h)) continue;
      const SurfaceInfo si = surface(s, r, h);
      if (std::abs(si.p.x) < 1e-3 || std::abs(si.p.y) < 1e-3 || std::abs(si.p.z) < 1e-3)
        continue;  // near an edge of the sharper shapes a step of h crosses another face
      testing::expect_outward_normal(
          s, r, h, [&](const Vec3& p) { return contains(s, p); }, 1e-6);
    }
  }
}

TEST(Superellipsoid, HitsOnTheAxesHaveFiniteNormals) {
  // e = 3: the cross-section |x|^(2/3) + |y|^(2/3) = 1 has cusps on the axes; n = 3 the profile.
  for (const auto& [e, n] : {std::pair{3.0, 3.0}, {1.0, 1.0}, {0.5, 0.5}, {2.0, 2.0}}) {
    const Superellipsoid s = make_superellipsoid(e, n);
    const Ray rays[] = {{{0, 5, 0}, {0, -1, 0}}, {{5, 0, 0}, {-1, 0, 0}}, {{0, 0, -5}, {0, 0, 1}}};
    for (const Ray& r : rays) {
      LocalHit h;
      ASSERT_TRUE(intersect(s, r, h)) << e << " " << testing::describe(r);
      EXPECT_NEAR(h.t, 4, 1e-12);
      const SurfaceInfo si = surface(s, r, h);
      testing::expect_unit(si.n);
      EXPECT_LT(dot(si.n, r.d), 0) << e << " " << n;
    }
  }
}

}  // namespace
}  // namespace raycast
