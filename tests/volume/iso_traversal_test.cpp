// The macro-grid and cell-range skipping against a brute-force walk of every cell, spans against
// contains, and the normal against the field's gradient.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "volume/isosurface.h"

namespace raycast {
namespace {

// A lumpy field on a 40^3 grid with large empty regions and thin features.
ScalarGrid lumpy(std::mt19937& rng) {
  ScalarGrid g;
  g.n = {40, 33, 37};
  g.lo = {-1, -0.8, -0.9};
  g.cell = {0.05, 0.05, 0.05};
  g.v.resize(std::size_t(g.n[0]) * g.n[1] * g.n[2]);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  Vec3 c[6];
  for (Vec3& p : c) p = {u(rng), u(rng), u(rng)};
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const Vec3 p = g.lo + Vec3{i * g.cell.x, j * g.cell.y, k * g.cell.z};
        double f = 0;
        for (const Vec3& q : c) f += std::exp(-length_squared(p - q) / 0.03);
        g.v[g.index(i, j, k)] = float(f);
      }
  return g;
}

TEST(IsoTraversal, SkippingEqualsBruteForce) {
  std::mt19937 rng(7);
  const Isosurface s = make_isosurface(lumpy(rng), 0.5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int crossings = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec3 o{u(rng), u(rng), u(rng)};
    Vec3 d = Vec3{u(rng), u(rng), u(rng)} * 0.4 - o;
    if (n % 3 == 0) d = Vec3{0, 0, n % 2 ? 1.0 : -1.0};  // axis-parallel rays
    const Ray r{o, d};
    const auto fast = iso_crossings(*s.data, r, -kInfinity, kInfinity, true);
    const auto slow = iso_crossings(*s.data, r, -kInfinity, kInfinity, false);
    ASSERT_EQ(fast.size(), slow.size()) << n;
    for (std::size_t i = 0; i < fast.size(); ++i) {
      EXPECT_EQ(fast[i].hit.t, slow[i].hit.t) << n;
      EXPECT_EQ(fast[i].entering, slow[i].entering);
      EXPECT_EQ(fast[i].entering, i % 2 == 0);
    }
    crossings += int(fast.size());
  }
  EXPECT_GT(crossings, 500);
}

TEST(IsoTraversal, SpansAgreeWithContains) {
  std::mt19937 rng(8);
  const Isosurface s = make_isosurface(lumpy(rng), 0.4);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  int inside = 0;
  for (int n = 0; n < 500; ++n) {
    const Vec3 o{u(rng), u(rng), u(rng)};
    const Ray r{o, Vec3{u(rng), u(rng), u(rng)} * 0.4 - o};
    SpanList l;
    spans(s, r, l);
    for (std::size_t i = 0; i < l.size(); ++i) {
      ASSERT_LT(l[i].in.t, l[i].out.t);
      if (i > 0) {
        ASSERT_LE(l[i - 1].out.t, l[i].in.t);
      }
      const double mid = 0.5 * (l[i].in.t + l[i].out.t);
      EXPECT_TRUE(contains(s, r.at(mid)));
      inside++;
      if (i + 1 < l.size()) {
        const double gap = 0.5 * (l[i].out.t + l[i + 1].in.t);
        EXPECT_FALSE(contains(s, r.at(gap)));
      }
    }
    // The nearest hit from t = 0 is the first span end at t >= 0 (to rounding: the walk from
    // t = 0 expands the first cell's cubic about 0, the whole line's about the cell's entry).
    LocalHit h;
    double first = kInfinity;
    for (const Span& sp : l)
      for (double t : {sp.in.t, sp.out.t})
        if (t >= 0 && t < first) first = t;
    if (intersect(s, r, h))
      EXPECT_NEAR(h.t, first, 1e-13 * std::max(1.0, first));
    else
      EXPECT_TRUE(std::isinf(first));
  }
  EXPECT_GT(inside, 50);
}

TEST(IsoTraversal, NormalIsMinusTheGradient) {
  std::mt19937 rng(9);
  const Isosurface s = make_isosurface(lumpy(rng), 0.5);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Vec3 o{u(rng), u(rng), u(rng)};
    const Ray r{o, Vec3{u(rng), u(rng), u(rng)} * 0.4 - o};
    LocalHit h;
    if (!intersect(s, r, h) || h.part != 0) continue;
    const SurfaceInfo si = surface(s, r, h);
    // Central differences of the field well inside the hit's cell agree with the analytic normal.
    const double e = 1e-6;
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
      Vec3 dp;
      dp[a] = e;
      g[a] = (sample(s.data->grid, si.p + dp) - sample(s.data->grid, si.p - dp)) / (2 * e);
    }
    if (length(g) < 1e-3) continue;
    EXPECT_GT(dot(si.n, -normalize(g)), 0.999) << n;
    EXPECT_NEAR(length(si.n), 1, 1e-12);
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace raycast
