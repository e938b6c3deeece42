// The span-list set operations against a brute-force reference on random sorted lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "csg/span_ops.h"

namespace raycast {
namespace {

// A span list from (in, out) pairs; each end's `prim` records which operand and end it is.
SpanList make_list(const std::vector<std::pair<double, double>>& pairs, int tag) {
  SpanList l;
  int k = 0;
  for (const auto& [a, b] : pairs) {
    LocalHit in, out;
    in.t = a;
    out.t = b;
    in.prim = tag * 1000 + k++;
    out.prim = tag * 1000 + k++;
    l.add(in, out);
  }
  return l;
}

// Random sorted, disjoint (touching allowed, zero-length allowed) spans on a coarse integer grid
// so that coincident ends are frequent; the ends may be infinite.
std::vector<std::pair<double, double>> random_pairs(std::mt19937& rng, int max_count = 12) {
  std::uniform_int_distribution<int> count(0, max_count), step(0, 3), coin(0, 9);
  std::vector<double> ends;
  double t = -20;
  const int n = count(rng);
  for (int i = 0; i < 2 * n; ++i) {
    t += step(rng);
    ends.push_back(t);
  }
  std::vector<std::pair<double, double>> pairs;
  for (int i = 0; i < n; ++i) pairs.push_back({ends[2 * i], ends[2 * i + 1]});
  if (!pairs.empty() && coin(rng) == 0) pairs.front().first = -kInfinity;
  if (!pairs.empty() && coin(rng) == 0) pairs.back().second = kInfinity;
  return pairs;
}

bool in_closed(const std::vector<std::pair<double, double>>& pairs, double t) {
  for (const auto& [a, b] : pairs)
    if (a <= t && t <= b) return true;
  return false;
}

// The regularised result by brute force: classify the midpoint of every gap between consecutive
// distinct ends (and points beyond the first and last) and join the gaps where the op holds.
std::vector<std::pair<double, double>> reference(CsgOp op,
                                                 const std::vector<std::pair<double, double>>& a,
                                                 const std::vector<std::pair<double, double>>& b) {
  std::vector<double> ts = {-kInfinity, kInfinity};
  for (const auto* l : {&a, &b})
    for (const auto& [x, y] : *l) ts.insert(ts.end(), {x, y});
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const double lo = ts[i], hi = ts[i + 1];
    const double mid = std::isinf(lo) ? (std::isinf(hi) ? 0 : hi - 1)
                                      : (std::isinf(hi) ? lo + 1 : 0.5 * (lo + hi));
    if (!csg_inside(op, in_closed(a, mid), in_closed(b, mid))) continue;
    if (!out.empty() && out.back().second == lo)
      out.back().second = hi;
    else
      out.push_back({lo, hi});
  }
  return out;
}

const char* op_name(CsgOp op) {
  return op == CsgOp::kUnion ? "union" : op == CsgOp::kIntersection ? "intersection" : "difference";
}

TEST(CombineSpans, RandomLists_MatchBruteForceReference) {
  const unsigned seed = 20261122;
  std::mt19937 rng(seed);
  for (int iter = 0; iter < 30000; ++iter) {
    // A third of the cases with at most one span each: the single-span fast paths.
    const int max_count = iter % 3 ? 12 : 1;
    const auto pa = random_pairs(rng, max_count), pb = random_pairs(rng, max_count);
    const SpanList a = make_list(pa, 1), b = make_list(pb, 2);
    for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
      SCOPED_TRACE(testing::Message()
                   << "seed " << seed << " iteration " << iter << " " << op_name(op));
      SpanList out;
      combine_spans(op, a, b, out);
      const auto ref = reference(op, pa, pb);
      ASSERT_EQ(out.size(), ref.size());
      for (std::size_t i = 0; i < ref.size(); ++i) {
        EXPECT_EQ(out[i].in.t, ref[i].first);
        EXPECT_EQ(out[i].out.t, ref[i].second);
        EXPECT_LT(out[i].in.t, out[i].out.t);  // never a zero-length result
        // Each end is a crossing of an operand at that t, flipped exactly when it comes from the
        // subtracted operand.
        for (const LocalHit* e : {&out[i].in, &out[i].out}) {
          const bool from_b = e->prim / 1000 == 2;
          EXPECT_EQ(e->flip, from_b && op == CsgOp::kDifference);
        }
      }
    }
  }
}

TEST(CombineSpans, BoxMinusEqualBox_IsEmpty) {
  const SpanList a = make_list({{1, 3}}, 1), b = make_list({{1, 3}}, 2);
  SpanList out;
  combine_spans(CsgOp::kDifference, a, b, out);
  EXPECT_TRUE(out.empty());
  combine_spans(CsgOp::kUnion, a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.prim, 1000);  // ties go to the first operand
  EXPECT_EQ(out[0].out.prim, 1001);
}

TEST(CombineSpans, TouchingSpans_UnionMergesIntersectionDrops) {
  const SpanList a = make_list({{0, 1}}, 1), b = make_list({{1, 2}}, 2);
  SpanList out;
  combine_spans(CsgOp::kUnion, a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, 0);
  EXPECT_EQ(out[0].out.t, 2);
  combine_spans(CsgOp::kIntersection, a, b, out);
  EXPECT_TRUE(out.empty());
  combine_spans(CsgOp::kDifference, a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].out.prim, 1001);  // a's own exit, not b's entry
  EXPECT_FALSE(out[0].out.flip);
}

TEST(CombineSpans, Difference_HoleEndsComeFromSubtrahendFlipped) {
  const SpanList a = make_list({{0, 10}}, 1), b = make_list({{4, 6}}, 2);
  SpanList out;
  combine_spans(CsgOp::kDifference, a, b, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].out.t, 4);
  EXPECT_EQ(out[0].out.prim, 2000);
  EXPECT_TRUE(out[0].out.flip);
  EXPECT_EQ(out[1].in.prim, 2001);
  EXPECT_TRUE(out[1].in.flip);
  // Subtracting twice restores the orientation.
  SpanList twice;
  combine_spans(CsgOp::kDifference, make_list({{-1, 11}}, 3), out, twice);
  ASSERT_EQ(twice.size(), 3u);
  EXPECT_EQ(twice[1].in.prim, 2000);  // b's surface at 4, subtracted twice
  EXPECT_FALSE(twice[1].in.flip);
}

TEST(CombineSpans, ZeroLengthOperandSpans_LeaveNoTrace) {
  const SpanList a = make_list({{2, 2}}, 1), b = make_list({{0, 5}}, 2);
  SpanList out;
  combine_spans(CsgOp::kUnion, a, make_list({}, 2), out);
  EXPECT_TRUE(out.empty());
  combine_spans(CsgOp::kDifference, b, a, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, 0);
  EXPECT_EQ(out[0].out.t, 5);
}

TEST(CombineSpans, InfiniteEnds_ArePreserved) {
  const SpanList a = make_list({{-kInfinity, 3}}, 1), b = make_list({{1, kInfinity}}, 2);
  SpanList out;
  combine_spans(CsgOp::kIntersection, a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, 1);
  EXPECT_EQ(out[0].out.t, 3);
  combine_spans(CsgOp::kUnion, a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].in.t, -kInfinity);
  EXPECT_EQ(out[0].out.t, kInfinity);
}

TEST(CombineSpans, ManySpans_GrowPastInlineStorage) {
  std::vector<std::pair<double, double>> pa, pb;
  for (int i = 0; i < 40; ++i) {
    pa.push_back({4.0 * i, 4.0 * i + 2});
    pb.push_back({4.0 * i + 1, 4.0 * i + 3});
  }
  SpanList out;
  combine_spans(CsgOp::kDifference, make_list(pa, 1), make_list(pb, 2), out);
  ASSERT_EQ(out.size(), 40u);
  EXPECT_EQ(out[39].in.t, 156);
  EXPECT_EQ(out[39].out.t, 157);
}

TEST(ComplementSpans, GapsBetweenTheSpans_OpenAtBothEnds) {
  SpanList s = make_list({{1, 3}, {4, 6}}, 1);
  complement_spans(s);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].in.t, -kInfinity);
  EXPECT_EQ(s[0].in.part, kNoSurface);
  EXPECT_EQ(s[0].out.t, 1);
  EXPECT_EQ(s[0].out.prim, 1000);  // the span's own crossing
  EXPECT_EQ(s[1].in.t, 3);
  EXPECT_EQ(s[1].out.t, 4);
  EXPECT_EQ(s[2].in.t, 6);
  EXPECT_EQ(s[2].out.t, kInfinity);
  EXPECT_EQ(s[2].out.part, kNoSurface);
  complement_spans(s);  // twice: the spans again
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].in.t, 1);
  EXPECT_EQ(s[1].out.t, 6);
  SpanList all;
  all.add(LocalHit{.t = -kInfinity, .part = kNoSurface},
          LocalHit{.t = kInfinity, .part = kNoSurface});
  complement_spans(all);
  EXPECT_TRUE(all.empty());
  complement_spans(all);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].in.t, -kInfinity);
  EXPECT_EQ(all[0].out.t, kInfinity);
}

}  // namespace
}  // namespace raycast
