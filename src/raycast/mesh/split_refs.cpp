#include "mesh/split_refs.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/aabb.h"

namespace raycast {

namespace {

double half_area(const BvhBuildRef& r) {
  const double x = double(r.hi[0]) - r.lo[0], y = double(r.hi[1]) - r.lo[1],
               z = double(r.hi[2]) - r.lo[2];
  return x * y + y * z + z * x;
}

double triangle_area(const Vec3f (&v)[3]) {
  const double e[3] = {double(v[1].x) - v[0].x, double(v[1].y) - v[0].y, double(v[1].z) - v[0].z};
  const double f[3] = {double(v[2].x) - v[0].x, double(v[2].y) - v[0].y, double(v[2].z) - v[0].z};
  const double c[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
                       e[0] * f[1] - e[1] * f[0]};
  return 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

// The part of a triangle inside a box: its bounds (double) and area; count 0 when none.
struct ClippedPart {
  int count = 0;
  double lo[3], hi[3];
  double area = 0;
};

// Sutherland-Hodgman clipping of the triangle against the six planes of [lo, hi] in double. A
// new vertex gets the plane's coordinate exactly on the clipped axis; its other coordinates carry
// rounding errors of a few double ulps, which the caller's widening covers.
ClippedPart clip_triangle(const Vec3f (&v)[3], const float lo[3], const float hi[3]) {
  constexpr int kMax = 3 + 6;  // each plane adds at most one vertex
  double p[kMax + 1][3], q[kMax + 1][3];
  int n = 3;
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a) p[i][a] = v[i][a];
  ClippedPart out;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const double plane = side == 0 ? lo[a] : hi[a];
      auto inside = [&](const double* x) { return side == 0 ? x[a] - plane : plane - x[a]; };
      int m = 0;
      for (int i = 0; i < n; ++i) {
        const double* c = p[i];
        const double* d = p[(i + 1) % n];
        const double dc = inside(c), dd = inside(d);
        if (dc >= 0) std::copy(c, c + 3, q[m++]);
        if ((dc >= 0) != (dd >= 0)) {
          const double t = dc / (dc - dd);
          for (int k = 0; k < 3; ++k) q[m][k] = c[k] + t * (d[k] - c[k]);
          q[m++][a] = plane;
        }
      }
      n = m;
      if (n == 0) return out;
      for (int i = 0; i < n; ++i) std::copy(q[i], q[i] + 3, p[i]);
    }
  out.count = n;
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = out.hi[a] = p[0][a];
    for (int i = 1; i < n; ++i) {
      out.lo[a] = std::min(out.lo[a], p[i][a]);
      out.hi[a] = std::max(out.hi[a], p[i][a]);
    }
  }
  // Area of the (planar, convex) polygon: half the length of the sum of its fan's cross products.
  double s[3] = {0, 0, 0};
  for (int i = 1; i + 1 < n; ++i) {
    const double e[3] = {p[i][0] - p[0][0], p[i][1] - p[0][1], p[i][2] - p[0][2]};
    const double f[3] = {p[i + 1][0] - p[0][0], p[i + 1][1] - p[0][1], p[i + 1][2] - p[0][2]};
    s[0] += e[1] * f[2] - e[2] * f[1];
    s[1] += e[2] * f[0] - e[0] * f[2];
    s[2] += e[0] * f[1] - e[1] * f[0];
  }
  out.area = 0.5 * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  return out;
}

// The reference of a clipped part inside the box [lo, hi]: its bounds widened by far more than
// the clipping's rounding errors, rounded outwards to float, then cut back to [lo, hi].
BvhBuildRef part_ref(const ClippedPart& c, const float lo[3], const float hi[3],
                     std::uint32_t index) {
  Aabb box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = c.lo[a] - (std::abs(c.lo[a]) * 0x1p-40 + 0x1p-1000);
    box.hi[a] = c.hi[a] + (std::abs(c.hi[a]) * 0x1p-40 + 0x1p-1000);
  }
  BvhBuildRef r = make_build_ref(box, index);
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = std::max(r.lo[a], lo[a]);
    r.hi[a] = std::min(r.hi[a], hi[a]);
  }
  return r;
}

// A piece waiting to be split: its wasted area and its slot in refs. The heap's top is the
// largest waste, ties to the smaller slot (deterministic).
struct Piece {
  double waste;
  std::uint32_t slot;
  bool operator<(const Piece& o) const {
    return waste < o.waste || (waste == o.waste && slot > o.slot);
  }
};

}  // namespace

void split_triangle_refs(std::span<const Vec3f> positions,
                         std::span<const std::array<std::uint32_t, 3>> triangles, double budget,
                         double min_ratio, BvhBuildRefs& refs) {
  const std::size_t n = triangles.size();
  if (!(budget > 0) || n == 0) return;
  std::size_t extra = static_cast<std::size_t>(std::min(budget, 4.0) * double(n));
  // Leaf references hold 29-bit group indices; stay far below.
  extra = std::min(extra, (std::size_t(1) << 30) - std::min(n, std::size_t(1) << 30));
  if (extra == 0) return;
  auto corners = [&](std::uint32_t t, Vec3f(&v)[3]) {
    for (int k = 0; k < 3; ++k) v[k] = positions[triangles[t][k]];
  };
  // A piece joins the heap only when its box is much larger than the triangle inside (long thin
  // or diagonal): a budget spent on the moderate waste of ordinary triangles loses on the forest
  // mesh of bench/embree_table.sh. The heap's order is total (waste, then slot), so the pops do not
  // depend on how it was filled.
  std::vector<Piece> heap;
  auto consider = [&](std::uint32_t slot, double area) {
    const double box = half_area(refs[slot]);
    if (box > min_ratio * area && box > area) {
      heap.push_back({box - area, slot});
      std::push_heap(heap.begin(), heap.end());
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    Vec3f v[3];
    corners(refs[i].index, v);
    consider(static_cast<std::uint32_t>(i), triangle_area(v));
  }
  refs.reserve(n + extra);
  while (extra > 0 && !heap.empty()) {
    std::pop_heap(heap.begin(), heap.end());
    const Piece top = heap.back();
    heap.pop_back();
    const BvhBuildRef parent = refs[top.slot];
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (double(parent.hi[a]) - parent.lo[a] > double(parent.hi[axis]) - parent.lo[axis]) axis = a;
    const float mid = static_cast<float>(0.5 * (double(parent.lo[axis]) + parent.hi[axis]));
    if (!(parent.lo[axis] < mid && mid < parent.hi[axis])) continue;  // too narrow to split
    float lo[2][3], hi[2][3];
    for (int h = 0; h < 2; ++h)
      for (int a = 0; a < 3; ++a) {
        lo[h][a] = parent.lo[a];
        hi[h][a] = parent.hi[a];
      }
    hi[0][axis] = mid;
    lo[1][axis] = mid;
    Vec3f v[3];
    corners(parent.index, v);
    ClippedPart part[2];
    BvhBuildRef piece[2];
    for (int h = 0; h < 2; ++h) {
      part[h] = clip_triangle(v, lo[h], hi[h]);
      if (part[h].count > 0) piece[h] = part_ref(part[h], lo[h], hi[h], parent.index);
    }
    if (part[0].count == 0 || part[1].count == 0) {  // the triangle on one side: a tighter box
      const int h = part[0].count == 0 ? 1 : 0;
      if (part[h].count == 0) continue;
      refs[top.slot] = piece[h];
      consider(top.slot, part[h].area);
      continue;
    }
    refs[top.slot] = piece[0];
    refs.push_back(piece[1]);
    --extra;
    consider(top.slot, part[0].area);
    consider(static_cast<std::uint32_t>(refs.size() - 1), part[1].area);
  }
}

}  // namespace raycast
